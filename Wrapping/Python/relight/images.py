"""Pictures of relit data: PNG frames off screen, and linear HDR views as OpenEXR."""

import os

import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (registers the OpenGL backend)
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
    vtkWindowToImageFilter,
)

from .errors import ErrorCatcher, _numbers
from .vtkRadiosityIO import vtkRadiosityEXRWriter


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
