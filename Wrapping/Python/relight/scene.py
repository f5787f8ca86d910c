"""Helpers around the filters: reading scenes, running the pipeline, pictures."""

import math
import numbers
import os
import re
import warnings
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (registers the OpenGL backend)
from . import levels
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkCommonDataModel import vtkDataSet
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
    vtkWindowToImageFilter,
)
from vtkmodules.vtkIOImage import vtkPNGWriter

from .vtkRadiosityFilters import vtkLightTaggedRadiosity, vtkRadiosityMesher
from .vtkRadiosityIO import vtkRadiosityEXRWriter


class ErrorCatcher:
    """Collects a VTK object's error and warning messages instead of printing them.

    >>> catcher = ErrorCatcher(some_filter)
    >>> some_filter.Update()
    >>> catcher.errors  # list of message strings

    For a filter, the executive's own report that it failed ("returned failure for
    request", which follows the filter's message) is kept apart, in `reports`.
    """

    def __init__(self, vtk_object):
        self.errors = []
        self.warnings = []
        self.reports = []
        vtk_object.AddObserver(vtkCommand.ErrorEvent, self._error)
        vtk_object.AddObserver(vtkCommand.WarningEvent, self._warning)
        executive = vtk_object.GetExecutive() if hasattr(vtk_object, "GetExecutive") else None
        if executive is not None:
            executive.AddObserver(vtkCommand.ErrorEvent, self._report)

    def _error(self, _obj, _event, message=None):
        self.errors.append(str(message))

    def _warning(self, _obj, _event, message=None):
        self.warnings.append(str(message))

    def _report(self, _obj, _event, message=None):
        self.reports.append(str(message))

    # VTK passes the message as call data only to callbacks that ask for a string.
    _error.CallDataType = "string0"
    _warning.CallDataType = "string0"
    _report.CallDataType = "string0"

    def failed(self):
        """Whether the object failed: its own error, or (a filter given the failed output of
        another as its input) only the executive's report that it returned failure."""
        return bool(self.errors or self.reports)

    def first_error(self):
        """The first error's own words, without VTK's file, line and object prefix."""
        if self.errors:
            return own_words(self.errors[0])
        said = [r for r in self.reports if "returned failure for request" not in r]
        if said:  # the executive's own reason (an input port left unconnected)
            return own_words(said[0])
        return "the input is the output of a filter that failed (see that filter's error)" if self.reports \
            else "unknown error"


def own_words(message):
    """A VTK message without its file, line and object prefix."""
    line = message.strip().split("\n")[-1] if message.strip() else message  # not splitlines: a name may hold U+2028
    return re.sub(r"^\w+ \(0x[0-9a-fA-F]+\): ", "", line)


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


def cell_areas(data):
    """Area of every cell, as a float64 numpy array."""
    from vtkmodules.vtkFiltersVerdict import vtkCellSizeFilter

    sizes = vtkCellSizeFilter()
    sizes.SetInputData(data)
    sizes.ComputeAreaOn()
    sizes.Update()
    return cell_array(sizes.GetOutput(), "Area").astype("float64")


def cell_centroids(data):
    """Mean of each cell's points, an (n, 3) numpy array."""
    import numpy as np

    out = np.empty((data.GetNumberOfCells(), 3))
    for c in range(data.GetNumberOfCells()):
        ids = data.GetCell(c).GetPointIds()
        out[c] = np.mean([data.GetPoint(ids.GetId(i)) for i in range(ids.GetNumberOfIds())], axis=0)
    return out


def light_names(data):
    """The light names in the field array LightNames, in LightId order."""
    names = data.GetFieldData().GetAbstractArray("LightNames")
    return [names.GetValue(i) for i in range(names.GetNumberOfValues())] if names else []


def point_array(data, name):
    """A point array as a numpy array (a view, no copy)."""
    array = data.GetPointData().GetAbstractArray(name)
    if array is None:
        raise KeyError(f"no point array {name!r}")
    return vtk_to_numpy(array)


def cell_array(data, name):
    """A cell array as a numpy array (a view, no copy)."""
    array = data.GetCellData().GetAbstractArray(name)
    if array is None:
        raise KeyError(f"no cell array {name!r}")
    return vtk_to_numpy(array)


def render_png(data, path, camera, size=(640, 480)):
    """Renders the relit `data` (its DisplayColors point scalars) to a PNG file.

    Radiosity already holds the lighting, so the renderer's own lights are off
    (ambient 1, diffuse 0): what you see is the solution.
    `camera` = (position, focal_point, view_up, view_angle_degrees).
    """
    _check_camera(camera)
    if data.GetNumberOfPoints() == 0:
        raise ValueError("render_png got empty data: Update() the relight filter before taking its output")
    if data.GetPointData().GetArray("DisplayColors") is None:
        raise ValueError("render_png shows the relight filter's DisplayColors: give it vtkRadiosityRelight's "
                         "output (the solver's output holds radiosity, not colors)")
    folder = os.path.dirname(os.path.abspath(str(path)))
    if not os.path.isdir(folder):  # VTK's writer only prints "Ran out of disk space"
        raise FileNotFoundError(f"cannot write '{path}': the folder '{folder}' does not exist")
    renderer = FrameRenderer(camera, size)
    writer = vtkPNGWriter()
    writer.SetFileName(str(path))
    writer.SetInputData(renderer.render(data))
    writer.Write()
    renderer.close()
    if writer.GetErrorCode():
        raise OSError(f"cannot write '{path}' (VTK error code {writer.GetErrorCode()})")


def _numbers(value, count, what, low=-math.inf):
    """`value` as `count` finite floats of at least `low`; ValueError naming `what` if not."""
    try:
        values = tuple(value)  # a tuple, list or numpy array
    except TypeError:
        values = (value,) if count == 1 else None
    try:
        floats = tuple(float(v) for v in values) if values is not None and len(values) == count else None
    except (TypeError, ValueError):
        floats = None
    if floats is None or not all(math.isfinite(v) and v >= low for v in floats):
        numbers = "a finite number" if count == 1 else f"{count} finite numbers"
        bound = "" if low == -math.inf else f" of at least {low:g}" if count == 1 else f", each at least {low:g}"
        raise ValueError(f"{what} needs {numbers}{bound}, not {value!r}")
    return floats



def _check_camera(camera):
    """ValueError unless `camera` is (position, focal point, view-up, view angle) that can
    show something: a silent, empty picture is what VTK makes of the others."""
    try:
        position, focal, up, angle = camera
        position, focal, up = (_numbers(vector, 3, "") for vector in (position, focal, up))
        angle = _numbers(angle, 1, "")[0]
    except (TypeError, ValueError):
        raise ValueError(f"camera needs (position, focal point, view-up, view angle in degrees), three finite "
                         f"numbers each and a number, not {camera!r}") from None
    if position == focal:
        raise ValueError(f"the camera's position and focal point are the same point {position}: it looks nowhere")
    if not 0 < angle < 180:
        raise ValueError(f"the camera's view angle needs to be between 0 and 180 degrees, not {angle!r}")


class FrameRenderer:
    """An off-screen, unlit view of relit data (DisplayColors shown as they are), one window
    reused for many frames (an animation). With `mapper` (a vtkRadiosityRelightMapper
    given the solver's output), the frames are relit on the GPU instead."""

    def __init__(self, camera, size=(640, 480), mapper=None):
        _check_camera(camera)
        self.mapper = mapper or vtkPolyDataMapper()
        if mapper is None:
            self.mapper.SetScalarModeToUsePointData()
            self.mapper.SetColorModeToDirectScalars()
        actor = vtkActor()
        actor.SetMapper(self.mapper)
        actor.GetProperty().SetAmbient(1.0)
        actor.GetProperty().SetDiffuse(0.0)
        actor.GetProperty().SetSpecular(0.0)
        self.renderer = vtkRenderer()
        self.renderer.AddActor(actor)
        self.renderer.SetBackground(0.1, 0.1, 0.12)
        self.window = vtkRenderWindow()
        self.window.SetOffScreenRendering(1)
        self.window.AddRenderer(self.renderer)
        self.window.SetSize(*size)
        position, focal, up, angle = camera
        cam = self.renderer.GetActiveCamera()
        cam.SetPosition(*position)
        cam.SetFocalPoint(*focal)
        cam.SetViewUp(*up)
        cam.SetViewAngle(angle)
        self.grab = vtkWindowToImageFilter()
        self.grab.SetInput(self.window)
        self.grab.ReadFrontBufferOff()

    def render(self, data=None):
        """Renders `data` (or the mapper's input as it is) and returns the frame as
        vtkImageData."""
        if data is not None:
            self.mapper.SetInputData(data)
        self.renderer.ResetCameraClippingRange()
        self.window.Render()
        self.grab.Modified()
        self.grab.Update()
        return self.grab.GetOutput()

    def close(self):
        self.window.Finalize()


def exr_writer(data, camera, size=(640, 480), array="Radiosity"):
    """A vtkRadiosityEXRWriter set up for `data` seen from `camera`; Write() to a file or
    RenderImage() into an array."""
    writer = vtkRadiosityEXRWriter()
    writer.SetInputData(data)
    writer.SetArrayName(array)
    position, focal, up, angle = camera
    writer.SetCameraPosition(*position)
    writer.SetFocalPoint(*focal)
    writer.SetViewUp(*up)
    writer.SetViewAngle(angle)
    writer.SetSize(*size)
    return writer


def write_exr(data, path, camera, size=(640, 480), array="Radiosity", light_layers=False):
    """Writes a linear HDR view of the point array `array` as OpenEXR; with
    `light_layers`, also one 32-bit float layer per light (channels <light>.R/.G/.B)."""
    writer = exr_writer(data, camera, size, array)
    writer.SetLightLayers(bool(light_layers))
    writer.SetFileName(str(path))
    catcher = ErrorCatcher(writer)
    if not writer.Write():
        raise OSError(f"could not write {path!r}: {catcher.first_error()}")


def read_exr(path, layer=""):
    """One layer of an OpenEXR file (a light's name as written, or "" for the plain R, G,
    B) as a (height, width, 3) float32 array, row 0 at the top. Raises OSError."""
    from vtkmodules.vtkCommonCore import vtkFloatArray

    rgb, size = vtkFloatArray(), [0, 0]
    if not vtkRadiosityEXRWriter.ReadLayer(str(path), layer, rgb, size):
        raise OSError(f"could not read layer {layer!r} of {path!r}")
    return vtk_to_numpy(rgb).reshape(size[1], size[0], 3)


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


def add_light_names(data, names):
    """Adds the field array LightNames (light i's name for its Radiosity_<name> arrays)."""
    from vtkmodules.vtkCommonCore import vtkStringArray

    array = vtkStringArray()
    array.SetName("LightNames")
    for name in names:
        array.InsertNextValue(name)
    data.GetFieldData().AddArray(array)
    return data


def add_field_ints(data, name, values):
    """Adds an integer field array, e.g. LightBanks or StaticLights (one value per light)."""
    from vtkmodules.vtkCommonCore import vtkIntArray

    array = vtkIntArray()
    array.SetName(name)
    for value in values:
        array.InsertNextValue(int(value))
    data.GetFieldData().AddArray(array)
    return data
