"""Scene files in: ``import_scene`` reads OBJ+MTL, glTF/GLB, PLY, VRML (and IFC, FBX, DAE,
3DS, ... through Debian's ``assimp``) into a scene ready for the mesher."""

import os
import warnings

from .scene import ErrorCatcher
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


def import_scene(path, unit="m", lights_per_object=False, require_lights=True):
    """Reads a scene file into vtkPolyData with Reflectance, LightId, Emission and
    LightNames (and MaterialIds / MaterialNames, for marking lights by material).

    unit: the file's length unit ("mm", "cm", "in", ... or metres per unit); the result
    is in metres. lights_per_object: one light per object and emissive material instead
    of one per emissive material. require_lights: raise ValueError when the file has no
    emissive material (set False to mark lights afterwards).
    Raises OSError naming the file and the problem when it cannot be read.
    """
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
