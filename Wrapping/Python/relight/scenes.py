"""Scenes from Python: made from lists, read from .vtp, meshed and solved in one call."""

import math
import numbers
import warnings

from vtkmodules.vtkCommonDataModel import vtkDataSet
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

from . import levels
from .arrays import add_light_names
from .errors import ErrorCatcher, own_words
from .vtkRadiosityFilters import vtkLightTaggedRadiosity, vtkRadiosityMesher


def make_scene(polygons, reflectance, light_ids, light_names=None, emission=None):
    """A vtkPolyData in the input contract from plain Python lists.

    `polygons`: lists of (x, y, z) points, front side by the right-hand rule;
    `reflectance`: an RGB triple per polygon; `light_ids`: -1 or 0..k-1 per polygon;
    `light_names` (k strings) and `emission` (an RGB triple per polygon) are optional.
    The arrays have the types import_scene gives (double colors), so the two merge.
    """
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkIntArray, vtkPoints, vtkStringArray
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

    data = vtkPolyData()
    points = vtkPoints()
    points.SetDataTypeToDouble()
    cells = vtkCellArray()
    for polygon in polygons:
        cells.InsertNextCell(len(polygon), [points.InsertNextPoint(*p) for p in polygon])
    data.SetPoints(points)
    data.SetPolys(cells)
    arrays = [("Reflectance", vtkDoubleArray, 3, reflectance), ("LightId", vtkIntArray, 1, light_ids)]
    if emission is not None:
        arrays.append(("Emission", vtkDoubleArray, 3, emission))
    for name, kind, components, values in arrays:
        array = kind()
        array.SetName(name)
        array.SetNumberOfComponents(components)
        for value in values:
            array.InsertNextTuple(value if components > 1 else (value,))
        data.GetCellData().AddArray(array)
    if light_names:
        add_light_names(data, light_names)
    return data


def read_polydata(path):
    """Reads a .vtp file; raises OSError if it cannot."""
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(str(path))
    reader.Update()
    data = reader.GetOutput()
    if data.GetNumberOfCells() == 0:
        raise OSError(f"{path}: no cells read (missing or not a .vtp file)")
    return data


def solve(scene, patch_size=None, element_size=None, lamp_grading=None, accuracy=None, **solver_settings):
    """Meshes and solves `scene` (vtkPolyData); returns the updated solver (its
    GetOutput() has the solutions, GetInputAlgorithm() is the mesher).

    Sizes left out are the mesher's suggestion for the scene (a sixth of its extent, or of
    the model's for a model set in a room by in_room or on_ground, rounded; the element a
    quarter of the patch), whatever its unit. `lamp_grading` is the mesher's LampGrading
    (finer elements by the lamps; None: its default, 0: one size everywhere).
    `accuracy` is the one knob: "preview", "draft", "default", "fine" or "reference"
    (relight.levels) scales the element size given or suggested (up to the patch size) and
    sets LampGrading, ShadowGrading, GatherRays, GatherSweeps and ClusterSeparation (those
    of them given here too stay as given).
    `solver_settings` are vtkLightTaggedRadiosity properties, e.g. MaximumShots=500.
    Raises RuntimeError with the filters' message if meshing or solving fails; their
    warnings (a lamp drawn in a surface, an early stop) come as Python RuntimeWarnings.
    """
    if not isinstance(scene, vtkDataSet):
        raise TypeError(f"relight.solve needs a vtkPolyData scene (or another vtkDataSet of polygons), "
                        f"not {type(scene).__name__}")
    for name, size in (("patch_size", patch_size), ("element_size", element_size)):
        if size is not None and not (isinstance(size, numbers.Real) and not isinstance(size, bool)
                                     and math.isfinite(size) and size > 0):
            raise ValueError(f"relight.solve: {name} needs to be a positive length in the scene's unit "
                             f"(or None for the scene's suggestion), not {size!r}")
    chosen = levels.level(accuracy) if accuracy is not None else None
    mesher = vtkRadiosityMesher()
    mesher.SetInputData(scene)
    if patch_size is None or element_size is None:
        mesher.UpdateInformation()  # the suggestion comes with the information pass
    mesher.SetPatchSize(patch_size if patch_size is not None else mesher.GetSuggestedPatchSize())
    element = element_size if element_size is not None else mesher.GetSuggestedElementSize()
    # A level's larger elements stop at the patch (an element never spans patches).
    mesher.SetElementSize(min(element * chosen.element_scale, mesher.GetPatchSize()) if chosen else element)
    if lamp_grading is not None or chosen:
        mesher.SetLampGrading(lamp_grading if lamp_grading is not None else chosen.lamp_grading)
    if chosen:
        mesher.SetShadowGrading(chosen.shadow_grading)
    if chosen:
        solver_settings = {"GatherRays": chosen.gather_rays, "ClusterSeparation": chosen.cluster_separation,
                           "GatherSweeps": chosen.gather_sweeps, **solver_settings}
    solver = vtkLightTaggedRadiosity()
    solver.SetInputConnection(mesher.GetOutputPort())
    for name, value in solver_settings.items():
        if not hasattr(solver, "Set" + name):
            raise TypeError(f"relight.solve: no solver setting {name!r} (vtkLightTaggedRadiosity has no Set{name}; "
                            "the settings are listed in docs/settings.md)")
        getattr(solver, "Set" + name)(value)
    catchers = [ErrorCatcher(mesher), ErrorCatcher(solver)]
    solver.Update()
    # Warnings first, also before an error: they often say why (a lamp above the ceiling
    # "lights nothing" before the solve fails on a scene that emits nothing).
    for catcher in catchers:
        for message in catcher.warnings:
            warnings.warn(own_words(message), RuntimeWarning, stacklevel=2)
    failed = [c for c in catchers if c.failed()]
    if failed:
        raise RuntimeError(failed[0].first_error())  # the filter's own words, not VTK's prefix
    return solver


def furnace_box(size=2.0, rho=0.8):
    """A closed cube whose six faces (facing in) all emit unit exitance with grey
    reflectance `rho`: the furnace, where B = 1 / (1 - rho) everywhere."""
    s = size
    corners = [(0, 0, 0), (s, 0, 0), (s, s, 0), (0, s, 0), (0, 0, s), (s, 0, s), (s, s, s), (0, s, s)]
    faces = [(0, 1, 2, 3), (4, 7, 6, 5), (0, 4, 5, 1), (2, 6, 7, 3), (0, 3, 7, 4), (1, 5, 6, 2)]
    return make_scene([[corners[i] for i in f] for f in faces], [(rho, rho, rho)] * 6, [0] * 6)
