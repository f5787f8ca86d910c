"""A model made ready to solve: lights placed in words, and a room or a ground around it.

CAD exports and scans come without lights and without a room. ``area_light`` describes a
lamp with keywords, ``luminaire`` a light at a point (a manufacturer's IES or EULUMDAT file,
a bulb, a spot), ``mark_lights`` adds them (and marks cells as lights) through the Mark
Lights filter, ``in_room`` and ``on_ground`` set the model in a closed room or on a ground
plane sized from the model itself (so in the model's unit), keeping every array it has.
"""

import os
import warnings
from collections import namedtuple

from vtkmodules.vtkCommonDataModel import vtkDataSet

from .errors import ErrorCatcher, _numbers, own_words
from .vtkRadiosityFilters import vtkRadiosityLightMarker

AreaLight = namedtuple("AreaLight", "name centre normal width height color disk")
Luminaire = namedtuple("Luminaire", "name kind parameters position aim rotation color")

AXES = {"x": 0, "y": 1, "z": 2}


def area_light(name, centre, normal, size, color=(1.0, 1.0, 1.0), intensity=1.0, disk=False):
    """A lamp that emits from one side: a rectangle (`size` = width or (width, height)) or,
    with disk=True, a disk of diameter `size`, centred at `centre` and facing `normal`;
    it emits `color` x `intensity` per unit area (W/m^2 per channel at unit relight).
    Raises ValueError naming the argument that cannot make a lamp."""
    what = f"area light {name!r}:"
    pair = isinstance(size, (tuple, list)) or getattr(size, "ndim", 0) == 1
    if disk and pair:
        raise ValueError(f"{what} a disk takes one size, its diameter, not {size!r}")
    width, height = _numbers(size, 2, f"{what} size", 0.0) if pair else _numbers(size, 1, f"{what} size", 0.0) * 2
    if not (width > 0 and height > 0):
        raise ValueError(f"{what} needs a positive size, not {size!r}")
    normal = _numbers(normal, 3, f"{what} normal")
    if not any(normal):
        raise ValueError(f"{what} normal is zero: give the direction the lamp faces")
    intensity = _numbers(intensity, 1, f"{what} intensity", 0.0)[0]
    emission = tuple(c * intensity for c in _numbers(color, 3, f"{what} color", 0.0))
    return AreaLight(str(name), _numbers(centre, 3, f"{what} centre"), normal, width, height, emission, bool(disk))


def luminaire(name, path=None, position=(0.0, 0.0, 0.0), aim=(0.0, 0.0, -1.0), rotation=0.0, lumens=None,
              color=(1.0, 1.0, 1.0), kind=None, maintenance=None, **parameters):
    """A light at a point for mark_lights: by default a luminaire of `path`, its IES LM-63
    or EULUMDAT file (its candela table, at the file's lumens or at `lumens`), at
    `position`, aimed along `aim` (its nadir: straight down is (0, 0, -1) in a z-up scene,
    (0, -1, 0) in a y-up one) and turned by `rotation` degrees about the aim. Without a
    path, `kind` names another kind ("point", "spot" with cone= and falloff= in degrees,
    "lambertian"). Its solution is white at its lumens (lux where the scene is in metres);
    `color` is its default color when relit; `maintenance` its maintenance factor (0 to 1:
    the light it keeps after years of dirt and ageing). Raises ValueError naming what cannot
    be a light; the file itself is read when the lights are marked."""
    what = f"luminaire {name!r}:"
    kind = kind or ("goniometric" if path is not None else None)
    if kind is None:
        raise ValueError(f"{what} give the photometric file (path=...) or another kind (kind='point', 'spot', ...)")
    if kind == "goniometric":
        if path is None:
            raise ValueError(f"{what} a goniometric luminaire needs its photometric file (path=...)")
        parameters["file"] = os.path.abspath(os.fspath(path))
    elif path is not None:
        raise ValueError(f"{what} a {kind} light takes no photometric file")
    if lumens is not None:
        lumens = _numbers(lumens, 1, f"{what} lumens", 0.0)[0]
        if not lumens > 0:
            raise ValueError(f"{what} lumens must be above 0, not {lumens!r}")
        parameters["lumens"] = repr(lumens)
    if maintenance is not None:
        parameters["maintenance"] = repr(_numbers(maintenance, 1, f"{what} maintenance", 0.0)[0])
    aim = _numbers(aim, 3, f"{what} aim")
    if not any(aim):
        raise ValueError(f"{what} aim is zero: give the direction it shines (its nadir)")
    text = "; ".join(f"{key}={value}" for key, value in parameters.items())
    if any(";" in str(v) for v in parameters.values()):
        raise ValueError(f"{what} a parameter holds ';', which separates them")
    return Luminaire(str(name), kind, text, _numbers(position, 3, f"{what} position"), aim,
                     _numbers(rotation, 1, f"{what} rotation")[0], _numbers(color, 3, f"{what} color", 0.0))


def mark_lights(scene, *lights, cells=(), material=None, name="Light", color=(1.0, 1.0, 1.0), intensity=1.0):
    """The scene with `lights` (area_light descriptions) added and, where given, the cells
    with ids `cells` or of materials matching `material` (a wildcard pattern) made the
    light `name` emitting `color` x `intensity`. Raises ValueError naming the problem; the
    lights' checks (a lamp that lights nothing, faces away, lies in a surface) come as
    RuntimeWarnings."""
    if not isinstance(scene, vtkDataSet):
        raise TypeError(f"mark_lights needs a vtkPolyData scene, not {type(scene).__name__}")
    bad = [light for light in lights if not isinstance(light, (AreaLight, Luminaire))]
    if bad:
        raise TypeError(f"mark_lights takes lamps made by relight.area_light or relight.luminaire, not {bad[0]!r}")
    intensity = _numbers(intensity, 1, "mark_lights: intensity", 0.0)[0]
    marker = vtkRadiosityLightMarker()
    marker.SetInputData(scene)
    marker.SetLightName(name)
    marker.SetEmission(*(c * intensity for c in _numbers(color, 3, "mark_lights: color", 0.0)))
    if material:
        marker.SetMaterialPattern(material)
    for cell in cells:
        marker.AddCellId(int(cell))
    for light in lights:
        if isinstance(light, Luminaire):
            marker.AddLuminaire(light.name, light.kind, light.parameters, *light.position, *light.aim, light.rotation,
                                *light.color)
        else:
            marker.AddAreaLight(light.name, 1 if light.disk else 0, *light.centre, *light.normal, light.width,
                                light.height, *light.color)
    catcher = ErrorCatcher(marker)
    marker.Update()
    if catcher.failed():
        raise ValueError(catcher.first_error())
    for message in catcher.warnings:  # a lamp that lights nothing, faces away, sits in a surface
        warnings.warn(own_words(message), RuntimeWarning, stacklevel=2)
    return marker.GetOutput()


def in_room(model, margin=1.0, up="y", reflectance=(0.7, 0.7, 0.7), floor_reflectance=None):
    """The model standing on the floor of a closed room: the room reaches `margin` x the
    model's largest extent beyond it on every side and above it; its walls face inwards. A
    model with a face in its lowest plane (flat, or on a base plate) is set a thousandth of
    its size above the floor, so that the two do not overlap.
    Every cell array of the model is kept (the room's cells: LightId -1, no Emission, the
    given Reflectance, zeros elsewhere), and its field arrays (LightNames) too. The room is
    made around the model's surfaces and the lamps near them; a lamp far outside (more than
    ten times the model's extent away: in another unit?) is a ValueError naming it."""
    low, high = _room_box(model, margin, up)
    _refuse_lamps_outside(model, _room_bounds(model)[2], low, high)
    room = _box_faces(low, high, AXES[up], reflectance, reflectance if floor_reflectance is None else floor_reflectance)
    return _merged(model, room)


def on_ground(model, margin=1.0, up="y", reflectance=(0.5, 0.5, 0.5)):
    """The model standing on a square ground plane that reaches `margin` x its largest
    extent beyond it: light that misses the ground leaves the scene, as outdoors."""
    low, high = _room_box(model, margin, up)
    axis = AXES[up]
    floor = [f for f in _box_faces(low, high, axis, reflectance, reflectance) if f[2] == "floor"]
    return _merged(model, floor)


def _room_box(model, margin, up):
    if not isinstance(model, vtkDataSet):
        raise TypeError(f"the model needs to be a vtkPolyData (relight.import_scene reads one), "
                        f"not {type(model).__name__}")
    if up not in AXES:
        raise ValueError(f"up must be one of {', '.join(AXES)}, not {up!r}")
    if not margin > 0:
        raise ValueError(f"the margin must be positive, not {margin!r}")
    if model.GetNumberOfCells() == 0:
        raise ValueError("the model has no cells")
    if not model.GetCellData().GetArray("Reflectance"):
        raise ValueError("the model has no cell array 'Reflectance' (import it with relight.import_scene "
                         "or build it with relight.make_scene)")
    lo, hi, _ = _room_bounds(model)
    extent = max(h - l for l, h in zip(lo, hi))
    if not extent > 0:
        raise ValueError("the model has no extent")
    axis = AXES[up]
    room_lo = [l - margin * extent for l in lo]
    room_hi = [h + margin * extent for h in hi]
    room_lo[axis] = lo[axis]  # the model stands on the floor
    if _lies_in_plane(model, axis, lo[axis], 1e-9 * extent):
        # A face up in the floor's plane (a flat model, a rug) would overlap the floor, and
        # both would take the same light: the floor goes a thousandth of the size lower.
        room_lo[axis] -= 1e-3 * extent
    return room_lo, room_hi


def _corners_by_light(model):
    """The model's points (numpy), its cells' corner ids, and each corner's cell's LightId
    (-1 for all where the model has no LightId or holds more than polygons)."""
    import numpy as np
    from vtkmodules.util.numpy_support import vtk_to_numpy

    points = vtk_to_numpy(model.GetPoints().GetData()).astype(float)
    polys = model.GetPolys()
    offsets = vtk_to_numpy(polys.GetOffsetsArray()).astype(np.int64)
    corners = vtk_to_numpy(polys.GetConnectivityArray()).astype(np.int64)
    ids = model.GetCellData().GetArray("LightId")
    if ids is None or model.GetNumberOfCells() != len(offsets) - 1:
        return points, corners, np.full(len(corners), -1)
    return points, corners, np.repeat(vtk_to_numpy(ids).reshape(-1).astype(np.int64), np.diff(offsets))


def _room_bounds(model, reach=10.0):
    """The bounds the room is made around: the model's surfaces, and its lamps that lie
    within `reach` x the surfaces' extent of them (a lamp over a small part); the lamps
    farther out (typed in another unit) are left out and returned as [(id, lo, hi)]."""
    import numpy as np

    points, corners, light = _corners_by_light(model)
    surface = corners[light < 0] if (light < 0).any() else corners
    lo, hi = points[surface].min(axis=0), points[surface].max(axis=0)
    extent = float((hi - lo).max())
    astray = []
    for lamp in np.unique(light[light >= 0]):
        at = points[corners[light == lamp]]
        if (at.min(axis=0) < lo - reach * extent).any() or (at.max(axis=0) > hi + reach * extent).any():
            astray.append((int(lamp), at.min(axis=0), at.max(axis=0)))
        else:
            lo, hi = np.minimum(lo, at.min(axis=0)), np.maximum(hi, at.max(axis=0))
    return list(lo), list(hi), astray


def _refuse_lamps_outside(model, astray, low, high):
    """Raises ValueError for the model's lamps far outside the room [low, high]: a closed
    room lets none of their light in, and a lamp typed in another unit would cost a long
    solve before anything said so."""
    if not astray:
        return
    names = model.GetFieldData().GetAbstractArray("LightNames")
    named = ", ".join(repr(names.GetValue(i) if names and i < names.GetNumberOfValues() else str(i))
                      for i, _, _ in astray)
    span = ", ".join(f"{a:.4g}..{b:.4g}" for a, b in zip(low, high))
    raise ValueError(f"light {named} lies far outside the model and the room made around it ({span}), so the "
                     "closed room would let none of its light in. Is it in another unit than the model, or are its "
                     "coordinates off?")


def _lies_in_plane(model, axis, level, tolerance):
    """Whether some polygon of `model` lies at `level` along `axis` facing along it, as the
    floor there would (one facing down sits on the floor, as a box's base does)."""
    import numpy as np
    from vtkmodules.util.numpy_support import vtk_to_numpy

    points = vtk_to_numpy(model.GetPoints().GetData()).astype(float)
    low = np.abs(points[:, axis] - level) <= tolerance
    polys = model.GetPolys()
    offsets = vtk_to_numpy(polys.GetOffsetsArray()).astype(np.int64)
    corners = vtk_to_numpy(polys.GetConnectivityArray()).astype(np.int64)
    a, b = (axis + 1) % 3, (axis + 2) % 3
    for start, end in zip(offsets[:-1], offsets[1:]):
        ids = corners[start:end]
        if end - start >= 3 and low[ids].all():
            p, q = points[ids][:, a], points[ids][:, b]
            if np.sum(p * np.roll(q, -1) - q * np.roll(p, -1)) > 0:  # its normal along +axis
                return True
    return False


def _reflectance(value, what):
    """An RGB reflectance in [0, 1]; ValueError naming `what` if not."""
    rgb = _numbers(value, 3, what, 0.0)
    if max(rgb) > 1:
        raise ValueError(f"{what} needs three numbers from 0 to 1 (a surface reflects at most what it receives), "
                         f"not {value!r}")
    return rgb


def _box_faces(low, high, up, wall, floor):
    """The six faces of the box [low, high] facing inwards: (corners, reflectance, kind)."""
    wall, floor = (_reflectance(r, what) for r, what in ((wall, "reflectance"), (floor, "floor_reflectance")))
    faces = []
    for axis in range(3):
        a, b = (axis + 1) % 3, (axis + 2) % 3
        for side, level in ((0, low[axis]), (1, high[axis])):
            corners = []
            for u, v in ((0, 0), (1, 0), (1, 1), (0, 1)):
                p = [0.0, 0.0, 0.0]
                p[axis], p[a], p[b] = level, (low[a], high[a])[u], (low[b], high[b])[v]
                corners.append(tuple(p))
            # (u, v) counter-clockwise about +axis; the low face must look along +axis.
            if side == 1:
                corners.reverse()
            kind = "floor" if axis == up and side == 0 else "wall"
            faces.append((corners, floor if kind == "floor" else wall, kind))
    return faces


def _merged(model, faces):
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    from vtkmodules.vtkFiltersCore import vtkAppendPolyData

    part, points, cells = vtkPolyData(), vtkPoints(), vtkCellArray()
    points.SetDataTypeToDouble()
    for corners, _, _ in faces:
        cells.InsertNextCell(len(corners), [points.InsertNextPoint(*p) for p in corners])
    part.SetPoints(points)
    part.SetPolys(cells)
    names = model.GetFieldData().GetAbstractArray("MaterialNames")
    materials = names.GetNumberOfValues() if names else 0
    _same_arrays(model.GetCellData(), part.GetCellData(), [f[1] for f in faces], materials=materials)
    _same_arrays(model.GetPointData(), part.GetPointData(), None, points.GetNumberOfPoints())
    append = vtkAppendPolyData()
    append.AddInputData(model)
    append.AddInputData(part)
    append.Update()
    out = vtkPolyData()
    out.ShallowCopy(append.GetOutput())
    out.GetFieldData().DeepCopy(model.GetFieldData())
    # The mesher suggests sizes from the model, not from the room around it: a figure in
    # its room got elements a tenth of its height, and a blocky shadow.
    span = vtkDoubleArray()
    span.SetName("SizingSpan")
    span.InsertNextValue(_span(model))
    out.GetFieldData().AddArray(span)
    if names:
        out.GetFieldData().GetAbstractArray("MaterialNames").InsertNextValue("(room)")
    return out


def _span(model):
    """The model's span as the mesher measures a scene's: twice the largest distance of a
    corner from the corners' mean (turning the model does not change it); its lamps left
    out, so that a lamp's size does not set the model's elements."""
    import numpy as np

    points, corners, light = _corners_by_light(model)
    used = points[np.unique(corners[light < 0] if (light < 0).any() else corners)]
    return float(2 * np.linalg.norm(used - used.mean(axis=0), axis=1).max())


def _same_arrays(source, target, reflectance, count=None, materials=0):
    """Arrays of the model's names, types and widths on the added part, so that the merge
    keeps them all (vtkAppendPolyData drops an array one input lacks); the part's cells are
    material `materials` (one past the model's)."""
    count = len(reflectance) if count is None else count
    for i in range(source.GetNumberOfArrays()):
        given = source.GetAbstractArray(i)
        if given is None or not given.IsNumeric():
            continue
        array = given.NewInstance()
        array.SetName(given.GetName())
        array.SetNumberOfComponents(given.GetNumberOfComponents())
        array.SetNumberOfTuples(count)
        fill = {"LightId": -1, "MaterialIds": materials}.get(given.GetName(), 0)
        for c in range(given.GetNumberOfComponents()):
            array.FillComponent(c, fill)
        if given.GetName() == "Reflectance" and reflectance is not None:
            for t, rgb in enumerate(reflectance):
                array.SetTuple(t, rgb)
        target.AddArray(array)


def point_lights(positions, intensity=1.0, color=(1, 1, 1), normal=None, like=None):
    """Moving lights for vtkRadiosityRelight's second input: one point per light with the
    point arrays Color, Intensity and (for small Lambertian emitters) Normal. With `like`
    (a relight.luminaire), every light is that luminaire at its position: the string point
    arrays Kind and Parameters, and Aim and Rotation, carry its kind, its photometric file
    and lumens, and its turn."""
    from vtkmodules.vtkCommonCore import vtkFloatArray, vtkPoints, vtkStringArray
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

    data, points, verts = vtkPolyData(), vtkPoints(), vtkCellArray()
    arrays = {"Color": 3, "Intensity": 1, **({"Normal": 3} if normal is not None else {}),
              **({"Aim": 3, "Rotation": 1} if like is not None else {})}
    made = {}
    for name, components in arrays.items():
        made[name] = vtkFloatArray()
        made[name].SetName(name)
        made[name].SetNumberOfComponents(components)
    texts = {name: vtkStringArray() for name in (("Kind", "Parameters") if like is not None else ())}
    for name, array in texts.items():
        array.SetName(name)
    for p in positions:
        verts.InsertNextCell(1, [points.InsertNextPoint(*p)])
        made["Color"].InsertNextTuple3(*color)
        made["Intensity"].InsertNextValue(intensity)
        if normal is not None:
            made["Normal"].InsertNextTuple3(*normal)
        if like is not None:
            made["Aim"].InsertNextTuple3(*like.aim)
            made["Rotation"].InsertNextValue(like.rotation)
            texts["Kind"].InsertNextValue(like.kind)
            texts["Parameters"].InsertNextValue(like.parameters)
    data.SetPoints(points)
    data.SetVerts(verts)
    for array in list(made.values()) + list(texts.values()):
        data.GetPointData().AddArray(array)
    return data
