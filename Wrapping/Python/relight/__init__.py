"""RadiosityRelight: interactive relighting of radiosity-lit scenes, from Python.

The three VTK filters (wrapped C++):

- ``vtkRadiosityMesher``: polygons -> patches -> elements (cell array ``PatchId``);
- ``vtkLightTaggedRadiosity``: one radiosity solution per light in one progressive pass,
  as point/cell arrays ``Radiosity_<light>``;
- ``vtkRadiosityRelight``: ``sum_i color_i * intensity_i * Radiosity_<light i>``.

plus ``vtkRadiosityWorkPlane`` (illuminance on a calculation grid), ``vtkRadiosityEXRWriter``
for HDR images, and helpers by topic: :mod:`relight.scenes` (make, read, mesh and solve),
:mod:`relight.staging` (lights placed in words, a room around a model), :mod:`relight.importing`
and :mod:`relight.ifc` (other formats), :mod:`relight.arrays` (results as numpy),
:mod:`relight.images` (PNG and OpenEXR), :mod:`relight.exporting` (glTF, the browser viewer),
:mod:`relight.work_planes` (illuminance grids) and :mod:`relight.levels` (the accuracy knob).
The demos live beside the package (``Wrapping/Python/demos``), the benchmarks in
``Testing/Benchmark``.
"""

from .vtkRadiosityFilters import (  # noqa: F401
    vtkLightTaggedRadiosity,
    vtkRadiosityAppendPieces,
    vtkRadiosityLightMarker,
    vtkRadiosityLights,
    vtkRadiosityMesher,
    vtkRadiosityRelight,
    vtkRadiosityWorkPlane,
)
from .vtkRadiosityIO import vtkRadiosityEXRWriter, vtkRadiosityGLTFWriter, vtkRadiositySceneReader  # noqa: F401
from .vtkRadiosityRendering import vtkRadiosityRelightMapper  # noqa: F401
from .exporting import export_viewer, write_gltf  # noqa: F401
from . import levels  # noqa: F401  (the accuracy knob: relight.solve(..., accuracy="fine"))
from .importing import import_scene  # noqa: F401
from .staging import area_light, in_room, luminaire, mark_lights, on_ground, point_lights  # noqa: F401
from .work_planes import work_plane, write_work_plane_csv  # noqa: F401
from .errors import ErrorCatcher  # noqa: F401
from .arrays import (  # noqa: F401
    add_field_ints,
    add_light_names,
    cell_areas,
    cell_array,
    cell_centroids,
    light_names,
    point_array,
)
from .images import FrameRenderer, exr_writer, read_exr, render_png, write_exr  # noqa: F401
from .scenes import furnace_box, make_scene, read_polydata, solve  # noqa: F401
