"""Scene files in: ``import_scene`` reads OBJ+MTL, glTF/GLB, PLY, VRML (and IFC2x3, FBX, DAE,
3DS, ... through Debian's ``assimp``; IFC4 and IFC4x3 through IfcOpenShell, with their
luminaires and rooms) into a scene ready for the mesher."""

import os
import warnings

from .errors import ErrorCatcher
from .vtkRadiosityIO import vtkRadiositySceneReader

UNITS = {"m": 1.0, "cm": 0.01, "mm": 0.001, "km": 1000.0, "in": 0.0254, "ft": 0.3048}


def unit_scale(unit):
    """Metres per file unit, from a name in UNITS or a positive number."""
    if isinstance(unit, str):
        if unit not in UNITS:
            raise ValueError(f"unknown unit {unit!r}; use one of {', '.join(UNITS)} or a number of metres")
        return UNITS[unit]
    scale = float(unit)
    if not scale > 0:
        raise ValueError(f"the unit must be a positive number of metres, not {unit!r}")
    return scale


def import_scene(path, unit="m", lights_per_object=False, require_lights=True, ifc=None):
    """Reads a scene file into vtkPolyData with Reflectance, LightId, Emission and
    LightNames (and MaterialIds / MaterialNames, for marking lights by material).

    unit: the file's length unit ("mm", "cm", "in", ... or metres per unit); the result
    is in metres. lights_per_object: one light per object and emissive material instead
    of one per emissive material. require_lights: raise ValueError when the file has no
    emissive material (set False to mark lights afterwards).
    IFC: IFC4 and later (which assimp cannot read) go through IfcOpenShell, as every IFC does
    with ifc="ifcopenshell" (ifc="assimp" keeps IFC2x3 on assimp, the default): each
    IfcLightFixture becomes a luminaire (its IfcLightSourceGoniometric's photometry where the
    file gives it, else a 1000 lm Lambertian downlight), each IfcSpace a room (field arrays
    RoomNames and RoomBounds, for relight.work_plane(room=...)). The file's own units are
    read from it (`unit` applies to the other formats).
    Raises OSError naming the file and the problem when it cannot be read.
    """
    if str(path).lower().endswith(".ifc") and _through_ifcopenshell(path, ifc):
        return _import_ifc(path, require_lights)
    reader = vtkRadiositySceneReader()
    reader.SetFileName(str(path))
    reader.SetUnitScale(unit_scale(unit))
    reader.SetLightsPerObject(bool(lights_per_object))
    catcher = ErrorCatcher(reader)
    reader.Update()
    if catcher.failed():
        raise OSError(catcher.first_error())
    scene = reader.GetOutput()
    if require_lights and not scene.GetFieldData().GetAbstractArray("LightNames").GetNumberOfValues():
        raise ValueError(f"{path}: no emissive material, so no lights; import with require_lights=False, "
                         "then add lamps with relight.mark_lights(scene, relight.area_light(...)) or mark "
                         "materials or cells as lights (relight.mark_lights)")
    # What the reader noticed (a PLY without colors, an unknown material) is said in Python
    # too, not only kept in the field array Warnings; that there are no lights only where
    # the caller did not say it will add them.
    noticed = scene.GetFieldData().GetAbstractArray("Warnings")
    named = os.path.basename(str(path)) + ": "
    for i in range(noticed.GetNumberOfValues() if noticed is not None else 0):
        text = noticed.GetValue(i)
        if require_lights or "no emissive material" not in text:
            text = text[len(named):] if text.startswith(named) else text  # the reader names the file too
            warnings.warn(f"{path}: {text}", RuntimeWarning, stacklevel=2)
    return scene


def _through_ifcopenshell(path, ifc):
    if ifc not in (None, "assimp", "ifcopenshell"):
        raise ValueError(f"ifc must be 'assimp' or 'ifcopenshell', not {ifc!r}")
    if ifc is not None:
        return ifc == "ifcopenshell"
    from . import ifc as ifc_files

    return os.path.exists(str(path)) and ifc_files.schema(str(path)) not in ("IFC2X3", "")


def _import_ifc(path, require_lights):
    """An IFC file through IfcOpenShell: surfaces, material names, luminaires, rooms."""
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkIntArray, vtkStringArray

    from . import ifc as ifc_files
    from .scenes import make_scene
    from .staging import mark_lights

    polygons, reflectance, materials, lights, rooms = ifc_files.read(str(path))
    scene = make_scene(polygons, reflectance, [-1] * len(polygons))
    names = sorted(set(materials))
    ids, labels = vtkIntArray(), vtkStringArray()
    ids.SetName("MaterialIds")
    labels.SetName("MaterialNames")
    index = {n: i for i, n in enumerate(names)}
    for m in materials:
        ids.InsertNextValue(index[m])
    for n in names:
        labels.InsertNextValue(n)
    scene.GetCellData().AddArray(ids)
    scene.GetFieldData().AddArray(labels)
    room_names, room_bounds = vtkStringArray(), vtkDoubleArray()
    room_names.SetName("RoomNames")
    room_bounds.SetName("RoomBounds")
    room_bounds.SetNumberOfComponents(6)
    for room in rooms:
        room_names.InsertNextValue(room.name)
        room_bounds.InsertNextTuple(room.bounds)
    scene.GetFieldData().AddArray(room_names)
    scene.GetFieldData().AddArray(room_bounds)
    summary = vtkStringArray()
    summary.SetName("ImportSummary")
    summary.InsertNextValue(f"{os.path.basename(str(path))}: {len(polygons)} polygons, {len(names)} materials, "
                            f"{len(lights)} luminaires, {len(rooms)} rooms (IfcOpenShell, {ifc_files.schema(str(path))})")
    scene.GetFieldData().AddArray(summary)
    if lights:
        scene = mark_lights(scene, *lights)
    elif require_lights:
        raise ValueError(f"{path}: no IfcLightFixture, so no lights; import with require_lights=False, then add lamps "
                         "with relight.mark_lights(scene, relight.luminaire(...)) or relight.area_light(...)")
    return scene
