"""Solutions out: ``write_gltf`` writes a solved (and optionally relit) scene as binary
glTF with one vertex attribute per light, for relighting outside VTK."""

from .scene import ErrorCatcher
from .vtkRadiosityFilters import vtkRadiosityGLTFWriter


def write_gltf(data, path, exposure=1.0):
    """Writes `data` (the solver's or the relight filter's output) as a .glb file:
    geometry, `_RADIOSITY_<LIGHT>` per light, COLOR_0 from `Radiosity` x `exposure`, and
    the light names and default colours in the mesh's extras.relight. Raises OSError."""
    writer = vtkRadiosityGLTFWriter()
    writer.SetInputData(data)
    writer.SetFileName(str(path))
    writer.SetExposure(exposure)
    catcher = ErrorCatcher(writer)
    if not writer.Write():
        raise OSError(f"could not write {path!r}: {catcher.first_error()}")
