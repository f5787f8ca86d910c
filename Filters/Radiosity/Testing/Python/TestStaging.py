"""A model without a room or lights made ready to solve: lamps placed with keywords, the
model set in a closed room or on a ground plane, every array kept. The room must be closed
and face inwards: all the light its lamp emits is absorbed (energy balance over the solved
elements), while on an open ground most of it escapes."""

import os
import tempfile

import warnings

import numpy as np

import relight
from testlib import check, finish


def cube(centre, half, rho):
    """A closed box facing outwards (a model standing on y = centre - half)."""
    lo, hi = [c - half for c in centre], [c + half for c in centre]
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    faces = [[(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)], [(x0, y1, z0), (x0, y1, z1), (x1, y1, z1), (x1, y1, z0)],
             [(x0, y0, z0), (x0, y1, z0), (x1, y1, z0), (x1, y0, z0)], [(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)],
             [(x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0)], [(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)]]
    return relight.make_scene(faces, [rho] * 6, [-1] * 6)


def absorbed_fraction(scene):
    """Power absorbed by every element over the power emitted, for the one light's unit
    solution: emitted sum A E, absorbed sum A (1 - rho) H with H = (B - E) / rho."""
    out = relight.solve(scene, patch_size=0.25, element_size=0.125, AmbientTerm=True).GetOutput()
    area = relight.cell_areas(out)
    b = relight.cell_array(out, "Radiosity_" + relight.light_names(out)[0])
    rho = relight.cell_array(out, "Reflectance")
    lit = relight.cell_array(out, "LightId") >= 0
    e = np.where(lit[:, None], 1.0, 0.0)  # each light's solution is for unit emission
    emitted = (area[:, None] * e).sum(axis=0)
    absorbed = (area[:, None] * (1 - rho) * (b - e) / rho).sum(axis=0)
    return absorbed / emitted


model = cube((0.0, 0.25, 0.0), 0.25, (0.6, 0.5, 0.4))
lamp = relight.area_light("Lamp", centre=(0, 0.99, 0), normal=(0, -1, 0), size=0.3, color=(1, 0.9, 0.8), intensity=20)

# The keywords give what AddAreaLight's thirteen numbers give.
marker = relight.vtkRadiosityLightMarker()
marker.SetInputData(model)
marker.AddAreaLight("Lamp", 0, 0, 0.99, 0, 0, -1, 0, 0.3, 0.3, 20, 18, 16)
marker.Update()
by_hand = marker.GetOutput()
by_name = relight.mark_lights(model, lamp)
check(np.array_equal(relight.cell_array(by_hand, "Emission"), relight.cell_array(by_name, "Emission"))
      and by_hand.GetNumberOfPoints() == by_name.GetNumberOfPoints()
      and all(by_hand.GetPoint(i) == by_name.GetPoint(i) for i in range(by_hand.GetNumberOfPoints())),
      "area_light's keywords make the lamp AddAreaLight's positional numbers make")

# In a room: six inward faces around the model, the model on the floor, arrays kept.
room = relight.in_room(model, margin=1.0)
bounds = room.GetBounds()
check(room.GetNumberOfCells() == 12 and np.allclose(bounds, (-0.75, 0.75, 0.0, 1.0, -0.75, 0.75)),
      f"in_room adds six faces a model's extent beyond it, floor under it (bounds {bounds})")
# A flat model facing up (a rug, a CAD plate) would lie in the floor's plane, both taking
# the same light: the floor goes a thousandth of its size lower. One facing down sits on it.
for facing, floor in ((1, -1e-3), (-1, 0.0)):
    square = [(-0.5, 0, -0.5), (-0.5, 0, 0.5), (0.5, 0, 0.5), (0.5, 0, -0.5)][::facing]
    flat = relight.in_room(relight.make_scene([square], [(0.5, 0.5, 0.5)], [-1]))
    check(abs(flat.GetBounds()[2] - floor) < 1e-12,
          f"a flat model facing {'up' if facing > 0 else 'down'}: the floor at {flat.GetBounds()[2]:g} ({floor:g})")
# A lamp typed in another unit (cm for a model in m: 99 up, 30 wide) is refused by name: a
# closed room would let none of its light in (a new user's 40 m lamp cost a 67 s solve).
astray_scene = relight.mark_lights(model, relight.area_light("Key", centre=(0, 99, 0), normal=(0, -1, 0), size=30))
try:
    relight.in_room(astray_scene)
    refused = ""
except ValueError as error:
    refused = str(error)
check("'Key'" in refused and "another unit" in refused, f"a lamp 99 m over a 0.5 m model: refused ({refused[:100]})")
with warnings.catch_warnings(record=True) as said:  # a lamp 2 m over the 0.5 m model is meant: the room holds it
    warnings.simplefilter("always")
    over = relight.in_room(relight.mark_lights(model, relight.area_light("Over", centre=(0, 2.5, 0), normal=(0, -1, 0),
                                                                         size=0.2)))
check(not said and over.GetBounds()[3] > 2.5, f"a lamp 2 m over the model: in the room ({over.GetBounds()}), unsaid")
# A lamp above the ceiling is said when it is placed, not found later in a field array.
with warnings.catch_warnings(record=True) as said:
    warnings.simplefilter("always")
    relight.mark_lights(room, relight.area_light("Attic", centre=(0, 1.5, 0), normal=(0, -1, 0), size=0.2))
check(any("'Attic' lights nothing" in str(w.message) for w in said),
      f"a lamp above the ceiling: said when marked ({[str(w.message)[:60] for w in said]})")
names = lambda d: sorted(d.GetCellData().GetArrayName(i) for i in range(d.GetCellData().GetNumberOfArrays()))
check(names(room) == names(model), f"every cell array is kept ({names(room)})")
lit = relight.mark_lights(room, lamp)
check(relight.light_names(lit) == ["Lamp"], "the lamp is the scene's one light")
closed = absorbed_fraction(lit)
check(np.all(np.abs(closed - 1) < 0.02), f"closed room: the emitted power is absorbed ({closed.round(4)})")
ground = absorbed_fraction(relight.mark_lights(relight.on_ground(model, margin=1.0), lamp))
check(np.all(ground < 0.8), f"on an open ground most of the light escapes ({ground.round(4)} absorbed)")

# An imported model keeps its materials: the room is a material of its own.
folder = tempfile.mkdtemp()
with open(os.path.join(folder, "part.obj"), "w") as obj:
    obj.write("mtllib part.mtl\nusemtl steel\nv 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nv 0 1 0\n"
              "f 1 5 2\nf 2 5 3\nf 3 5 4\nf 4 5 1\n")
with open(os.path.join(folder, "part.mtl"), "w") as mtl:
    mtl.write("newmtl steel\nKd 0.5 0.5 0.5\n")
part = relight.import_scene(os.path.join(folder, "part.obj"), require_lights=False)
made = relight.make_scene([[(0, 0, 0), (1, 0, 0), (0, 1, 0)]], [(0.5, 0.5, 0.5)], [-1], emission=[(0, 0, 0)])
kinds = lambda d: [d.GetCellData().GetArray(n).GetClassName() for n in ("Reflectance", "Emission")]
check(kinds(part) == kinds(made), f"make_scene and import_scene give the same array types ({kinds(made)})")
housed = relight.in_room(part)
materials = housed.GetFieldData().GetAbstractArray("MaterialNames")
ids = relight.cell_array(housed, "MaterialIds")
check(materials.GetValue(materials.GetNumberOfValues() - 1) == "(room)" and set(ids[-6:]) == {materials.GetNumberOfValues() - 1}
      and set(ids[:-6]) == {0}, "the room's cells are a material '(room)'; the model's keep theirs")

# Sizes from the model, not from its room (a new user's 1.5 m figure got 0.6 m elements
# from its 4.5 m room, and a blocky shadow): a 1 m cube (span 1.73 m) in its room is
# meshed at patch 0.25 m, as the cube alone would be, not at the room's 0.5 m.
from vtkmodules.vtkFiltersSources import vtkCubeSource  # noqa: E402
cube_source = vtkCubeSource()
cube_source.Update()
cube = relight.make_scene([[cube_source.GetOutput().GetPoint(cube_source.GetOutput().GetCell(c).GetPointId(k))
                            for k in range(4)] for c in range(6)], [(0.5, 0.5, 0.5)] * 6, [-1] * 6)
sized = relight.vtkRadiosityMesher()
for data, expected in ((cube, 0.25), (relight.in_room(cube), 0.25), (relight.on_ground(cube), 0.25)):
    sized.SetInputData(data)
    sized.UpdateInformation()
    check(sized.GetSuggestedPatchSize() == expected and sized.GetSuggestedElementSize() == expected / 4,
          f"suggested sizes {sized.GetSuggestedPatchSize()} / {sized.GetSuggestedElementSize()} for "
          f"{data.GetNumberOfCells()} cells (the cube's {expected})")
sized.SetInputData(relight.make_scene([[(-1.5, -1.5, -1.5), (2.5, -1.5, -1.5), (2.5, 2.5, -1.5)]], [(0.5,) * 3], [-1]))
sized.UpdateInformation()
check(sized.GetSuggestedPatchSize() > 0.25, f"...while a room-sized scene of its own gets {sized.GetSuggestedPatchSize()}")


def plain_plane():
    from vtkmodules.vtkFiltersSources import vtkPlaneSource
    plane = vtkPlaneSource()
    plane.Update()
    return plane.GetOutput()


# What numpy gives is taken as lists are: vectors, a (width, height) size, reflectances,
# float32 sizes (a size computed from float points).
lamp = relight.area_light("N", np.array([0.0, 0.9, 0.0]), np.array([0, -1, 0]), np.array([0.2, 0.3]),
                          color=np.ones(3), intensity=np.float32(2))
check((lamp.width, lamp.height) == (0.2, 0.3) and lamp.color == (2.0, 2.0, 2.0),
      f"area_light takes numpy vectors, sizes and scalars ({lamp})")
tinted = relight.in_room(model, reflectance=np.full(3, 0.7), floor_reflectance=np.array([0.3, 0.3, 0.3]))
check(tinted.GetNumberOfCells() == room.GetNumberOfCells(), "in_room takes numpy reflectances")
with warnings.catch_warnings():
    warnings.simplefilter("ignore")  # the lamp's placement is not what this checks
    numpy_sized = relight.solve(relight.mark_lights(room, lamp), np.float32(0.5), np.float64(0.25))
check(numpy_sized.GetOutput().GetNumberOfCells() > 0, "relight.solve takes numpy sizes")

# Clear errors, where the argument is given (not later, at the solve, naming a cell).
nan = float("nan")
for name, call, kind, words in (
        ("no size", lambda: relight.mark_lights(room, relight.area_light("L", (0, 0.9, 0), (0, -1, 0), 0)),
         ValueError, "positive size"),
        ("bad axis", lambda: relight.in_room(model, up="w"), ValueError, "up must be"),
        ("no Reflectance", lambda: relight.in_room(plain_plane()), ValueError, "Reflectance"),
        ("a centre of two numbers", lambda: relight.area_light("L", (0, 1), (0, -1, 0), 0.5), ValueError, "centre"),
        ("a negative intensity", lambda: relight.area_light("L", (0, 1, 0), (0, -1, 0), 0.5, intensity=-3),
         ValueError, "intensity"),
        ("a zero normal", lambda: relight.area_light("L", (0, 1, 0), (0, 0, 0), 0.5), ValueError, "normal"),
        ("a disk of two sizes", lambda: relight.area_light("L", (0, 1, 0), (0, -1, 0), (1, 1), disk=True),
         ValueError, "diameter"),
        ("a negative size", lambda: relight.area_light("L", (0, 1, 0), (0, -1, 0), -1), ValueError, "not -1"),
        ("a NaN color", lambda: relight.area_light("L", (0, 1, 0), (0, -1, 0), 0.5, color=(1, nan, 1)),
         ValueError, "color"),
        ("no scene", lambda: relight.mark_lights(None, relight.area_light("L", (0, 1, 0), (0, -1, 0), 0.5)),
         TypeError, "vtkPolyData"),
        ("a lamp not made by area_light", lambda: relight.mark_lights(room, ("L", (0, 1, 0))), TypeError, "area_light"),
        ("a room reflecting more than it gets", lambda: relight.in_room(model, reflectance=(2, 2, 2)),
         ValueError, "reflectance"),
        ("no model", lambda: relight.in_room(None), TypeError, "vtkPolyData"),
        ("a negative patch size", lambda: relight.solve(room, -1.0, 0.5), ValueError, "patch_size"),
        ("a NaN element size", lambda: relight.solve(room, 0.5, nan), ValueError, "element_size"),
        ("an unknown solver setting", lambda: relight.solve(room, 0.5, 0.25, MaxShots=3), TypeError, "MaxShots"),
        ("a camera at its focal point", lambda: relight.render_png(relight.furnace_box(), "/tmp/x.png",
                                                                   ((1, 1, 1), (1, 1, 1), (0, 1, 0), 60)),
         ValueError, "focal point"),
        ("a camera of two numbers", lambda: relight.FrameRenderer(((1, 1), (0, 0, 0), (0, 1, 0), 60)),
         ValueError, "camera needs")):
    try:
        call()
        check(False, f"{name}: an error")
    except kind as error:
        check(words in str(error), f"{name}: {kind.__name__} naming it ({error})")

finish("TestStaging")
