"""IFC through IfcOpenShell (PyPI; installed into the build by `./relight setup`): IFC2x3,
IFC4 and IFC4x3 with their geometry in metres, each surface style's diffuse colour as the
reflectance, the luminaires of IfcLightFixture (with their photometry where the file gives
it) and the rooms of IfcSpace. assimp reads IFC2x3 only, so ``import_scene`` comes here
for IFC4 and later, or when asked (``ifc="ifcopenshell"``)."""

import math
import os
import tempfile
from collections import namedtuple

import numpy as np

Room = namedtuple("Room", "name bounds")

# Elements that are no surfaces light meets: openings are cut from walls already, spaces are
# the air of rooms, annotations and grids are drawings.
# A light fixture's body is left out too: its luminaire's point sits inside it, where the
# housing would block all its light (the fixture is the light the scene gets from it).
SKIPPED = {"IfcOpeningElement", "IfcSpace", "IfcAnnotation", "IfcGrid", "IfcVirtualElement", "IfcSite", "IfcLightFixture"}
# (an IFC2x3 fixture is an IfcFlowTerminal: its body stays, as one cannot tell it by type here)
GREY = (0.7, 0.7, 0.7)  # a surface without a style


def available():
    """Whether IfcOpenShell can be imported (it is, after ./relight setup)."""
    try:
        import ifcopenshell  # noqa: F401
        import ifcopenshell.geom  # noqa: F401
    except ImportError:
        return False
    return True


def schema(path):
    """The schema a file's header names ("IFC2X3", "IFC4", "IFC4X3", ...), or "" for none."""
    with open(path, "rb") as f:
        head = f.read(1 << 16).decode("latin-1", "replace").upper()  # header descriptions run long
    start = head.find("FILE_SCHEMA")
    if start < 0:
        return ""
    quote = head.find("'", start)
    end = head.find("'", quote + 1)
    return head[quote + 1:end].strip() if 0 <= quote < end else ""


def _cut_short(path):
    """Whether a STEP file lacks its closing END-ISO-10303-21; (IfcOpenShell reads a cut one
    without a word, as the part of the building before the cut; the C++ reader checks the
    same for assimp)."""
    with open(path, "rb") as f:
        if f.read(13) != b"ISO-10303-21;":
            return False  # not STEP at all: IfcOpenShell says what it makes of it
        f.seek(0, os.SEEK_END)
        f.seek(max(0, f.tell() - 256))
        return not f.read().rstrip().endswith(b"END-ISO-10303-21;")


def _open(path):
    import ifcopenshell

    if not available():
        raise OSError(f"{path}: IFC4 and later need IfcOpenShell (./relight setup installs it into the build)")
    if os.path.isfile(str(path)) and _cut_short(str(path)):
        raise OSError(f"{path}: does not end with END-ISO-10303-21; (the file is cut short)")
    try:
        return ifcopenshell.open(str(path))
    except Exception as error:  # IfcOpenShell raises its own kinds for broken files
        raise OSError(f"{path}: IfcOpenShell cannot read it ({error})") from None


def _reflectance(material):
    """A surface style's diffuse colour as a reflectance, a light grey where it has none."""
    if material is None:
        return GREY
    try:
        colour = material.diffuse
        rgb = (colour.r(), colour.g(), colour.b())
    except Exception:
        return GREY
    return tuple(min(1.0, max(0.0, float(c))) for c in rgb)


def _style_name(model, material):
    """A surface style's own name (IfcSurfaceStyle.Name) where the file gives one, else the
    geometry engine's label for it."""
    label = getattr(material, "name", "") or "(none)"
    try:
        rendering = model.by_id(int(label.rsplit("-", 1)[-1]))
        for style in model.get_inverse(rendering):
            if style.is_a("IfcSurfaceStyle") and style.Name:
                return style.Name
    except (ValueError, RuntimeError):
        pass
    return label


def _shapes(model, threads):
    """(ifc type, verts (n, 3), triangles (m, 3), per-triangle material index, materials)."""
    import ifcopenshell.geom

    settings = ifcopenshell.geom.settings()
    settings.set("use-world-coords", True)
    iterator = ifcopenshell.geom.iterator(settings, model, max(1, threads))
    if not iterator.initialize():
        return
    while True:
        shape = iterator.get()
        geometry = shape.geometry
        if shape.type not in SKIPPED and len(geometry.faces) >= 3:
            verts = np.asarray(geometry.verts, dtype=float).reshape(-1, 3)
            faces = np.asarray(geometry.faces, dtype=np.int64).reshape(-1, 3)
            ids = np.asarray(geometry.material_ids, dtype=np.int64)
            yield shape.type, verts, faces, ids, list(geometry.materials)
        if not iterator.next():
            break


def _placement(product, scale):
    """Where a product stands (metres) and its axes as a 3 x 3 matrix (columns x, y, z)."""
    import ifcopenshell.util.placement

    matrix = np.asarray(ifcopenshell.util.placement.get_local_placement(product.ObjectPlacement), dtype=float)
    return matrix[:3, 3] * scale, matrix[:3, :3]


def _photometry(fixture, folder, out_dir):
    """The photometric file a light fixture's IfcLightSourceGoniometric gives: a file it
    references (relative to the IFC file's folder), or its own intensity table written out
    as LM-63 for the luminaire to read. None where it has neither."""
    sources = []
    representation = getattr(fixture, "Representation", None)
    for rep in getattr(representation, "Representations", None) or []:
        sources += [item for item in rep.Items if item.is_a("IfcLightSourceGoniometric")]
    for source in sources:
        data = source.LightDistributionDataSource
        if data is None:
            continue
        if data.is_a("IfcExternalReference") and data.Location:
            path = data.Location if os.path.isabs(data.Location) else os.path.join(folder, data.Location)
            if os.path.exists(path):
                return path, source
        if data.is_a("IfcLightIntensityDistribution"):
            return _write_ies(data, fixture, out_dir), source
    return None, sources[0] if sources else None


def _write_ies(distribution, fixture, out_dir):
    """An IfcLightIntensityDistribution (type C, B or A planes of intensities in cd/klm) as an
    LM-63-2002 file, absolute at the source's lumens where given by the caller's scaling."""
    kind = {"TYPE_C": 1, "TYPE_B": 2, "TYPE_A": 3}.get(str(distribution.LightDistributionCurve).upper(), 1)
    planes = sorted(distribution.DistributionData, key=lambda d: d.MainPlaneAngle)
    horizontal = [math.degrees(p.MainPlaneAngle) if abs(p.MainPlaneAngle) <= 2 * math.pi + 1e-9 else p.MainPlaneAngle
                  for p in planes]
    vertical = list(planes[0].SecondaryPlaneAngle)
    vertical = [math.degrees(v) if max(abs(x) for x in vertical) <= 2 * math.pi + 1e-9 else v for v in vertical]
    lines = ["IESNA:LM-63-2002", f"[TEST] IfcLightIntensityDistribution of #{fixture.id()}", "TILT=NONE",
             f"1 -1 1 {len(vertical)} {len(horizontal)} {kind} 2 0 0 0", "1 1 0",
             " ".join(f"{v:g}" for v in vertical), " ".join(f"{h:g}" for h in horizontal)]
    for plane in planes:
        lines.append(" ".join(f"{c:g}" for c in plane.LuminousIntensity))
    path = os.path.join(out_dir, f"fixture_{fixture.id()}.ies")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return path


def _fixtures(model):
    """The light fixtures: IfcLightFixture (IFC4), or in IFC2x3 the flow terminals typed by
    an IfcLightFixtureType."""
    import ifcopenshell.util.element

    try:
        return list(model.by_type("IfcLightFixture"))
    except RuntimeError:  # IFC2x3 has no such entity
        pass
    return [t for t in model.by_type("IfcFlowTerminal")
            if (ifcopenshell.util.element.get_type(t) is not None
                and ifcopenshell.util.element.get_type(t).is_a("IfcLightFixtureType"))]


def _luminaires(model, scale, folder, default_lumens):
    """A relight.luminaire for each IfcLightFixture: at its placement, aimed along its -z,
    turned by its x axis; its photometry where the file gives one, else a Lambertian
    downlight of `default_lumens` (the file says nothing of its light)."""
    from .staging import luminaire

    out_dir = tempfile.mkdtemp(prefix="relight_ifc_")
    lights, used = [], set()
    for fixture in _fixtures(model):
        if fixture.ObjectPlacement is None:
            continue
        position, axes = _placement(fixture, scale)
        aim = -axes[:, 2]
        stem = "".join(c if c.isascii() and (c.isalnum() or c == "_") else "_" for c in (fixture.Name or "Luminaire"))
        stem = stem.strip("_")[:32] or "Luminaire"
        name, n = stem, 1
        while name in used:
            n += 1
            name = f"{stem}_{n}"
        used.add(name)
        path, source = _photometry(fixture, folder, out_dir)
        flux = getattr(source, "LuminousFlux", None) if source is not None else None
        lumens = float(flux) if flux and flux > 0 else None
        if path:
            lights.append(luminaire(name, path, position=position, aim=aim, lumens=lumens))
        else:
            lights.append(luminaire(name, kind="lambertian", position=position, aim=aim,
                                    lumens=lumens or default_lumens))
    return lights


def _rooms(model, scale):
    """Each IfcSpace's name (its long name where it has one) and the bounds of its shape."""
    import ifcopenshell.geom

    settings = ifcopenshell.geom.settings()
    settings.set("use-world-coords", True)
    rooms = []
    for space in model.by_type("IfcSpace"):
        try:
            shape = ifcopenshell.geom.create_shape(settings, space)
        except Exception:
            continue  # a space without a body: no bounds to lay a work plane in
        verts = np.asarray(shape.geometry.verts, dtype=float).reshape(-1, 3)
        if len(verts):
            low, high = verts.min(axis=0), verts.max(axis=0)
            rooms.append(Room(space.LongName or space.Name or f"Space{space.id()}",
                              (low[0], high[0], low[1], high[1], low[2], high[2])))
    return rooms


def luminaires(path, default_lumens=1000.0):
    """The light fixtures of an IFC file as relight.luminaire rows (for mark_lights): each
    at its placement, aimed along its -z, with its photometry where the file gives it, else
    a Lambertian downlight of `default_lumens`."""
    import ifcopenshell.util.unit

    model = _open(path)
    return _luminaires(model, ifcopenshell.util.unit.calculate_unit_scale(model), os.path.dirname(str(path)),
                       default_lumens)


def read(path, threads=0, default_lumens=1000.0):
    """The IFC file's surfaces as relight.make_scene's arguments (polygons, reflectances,
    light ids, material names per polygon), its luminaires and its rooms."""
    import ifcopenshell.util.unit

    model = _open(path)
    scale = ifcopenshell.util.unit.calculate_unit_scale(model)
    polygons, reflectance, materials = [], [], []
    for _, verts, faces, ids, styles in _shapes(model, threads or os.cpu_count() or 1):
        colours = [_reflectance(m) for m in styles]
        names = [_style_name(model, m) for m in styles]
        for t, face in enumerate(faces):
            m = int(ids[t]) if t < len(ids) else -1
            polygons.append([tuple(verts[i]) for i in face])
            reflectance.append(colours[m] if 0 <= m < len(colours) else GREY)
            materials.append(names[m] if 0 <= m < len(names) else "(none)")
    if not polygons:
        raise OSError(f"{path}: no surfaces in it (IfcOpenShell found no geometry)")
    return polygons, reflectance, materials, _luminaires(model, scale, os.path.dirname(str(path)), default_lumens), \
        _rooms(model, scale)
