"""RadiosityRelight: interactive relighting of radiosity-lit scenes, from Python.

The three VTK filters (wrapped C++):

- ``vtkRadiosityMesher``: polygons -> patches -> elements (cell array ``PatchId``);
- ``vtkLightTaggedRadiosity``: one radiosity solution per light in one progressive pass,
  as point/cell arrays ``Radiosity_<light>``;
- ``vtkRadiosityRelight``: ``sum_i color_i * intensity_i * Radiosity_<light i>``.

plus ``vtkRadiosityWorkPlane`` (illuminance on a calculation grid), ``vtkRadiosityEXRWriter``
for HDR images, and helpers in :mod:`relight.scene`.
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
from .staging import area_light, in_room, luminaire, mark_lights, on_ground  # noqa: F401
from .work_planes import work_plane, write_work_plane_csv  # noqa: F401
from .scene import (  # noqa: F401
    ErrorCatcher,
    add_field_ints,
    add_light_names,
    exr_writer,
    FrameRenderer,
    cell_areas,
    cell_centroids,
    furnace_box,
    light_names,
    make_scene,
    point_array,
    point_lights,
    cell_array,
    read_exr,
    read_polydata,
    render_png,
    solve,
    write_exr,
)
