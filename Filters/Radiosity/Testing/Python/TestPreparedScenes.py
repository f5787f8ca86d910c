"""One preparation per mesh: the solver's ray scene and geometry are kept for its
mesh and shared by a re-solve with other settings, by the relight's moving lights and by the
EXR writer. Each must give what a preparation made afresh gives, and a changed mesh must be
prepared again; a preparation goes with the last mesh that uses it."""

import gc
import os
import tempfile

import numpy as np
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkLogger
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter

import relight
from relight import cell_array
from testlib import check, finish

vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_WARNING)
DATA = os.path.join(os.environ.get("RELIGHT_ROOT", os.path.join(os.path.dirname(__file__), "..", "..", "..", "..")), "Data")
reader = vtkXMLPolyDataReader()
reader.SetFileName(os.path.join(DATA, "paper_8lights.vtp"))  # a box on the floor: enclosed elements
reader.Update()
room = reader.GetOutput()
Held = relight.vtkLightTaggedRadiosity.GetPreparedScenesHeld
before = Held()

# --- a re-solve with other settings reuses the preparation, and solves as a fresh one ---------
solver = relight.solve(room, 1.0, 0.25, ConvergenceThreshold=1e-2, PatchBasis=True)
check(not solver.GetLastPreparationReused(), "the first solve prepares the scene")
solver.SetConvergenceThreshold(3e-3)
solver.Update()
check(solver.GetLastPreparationReused(), "a re-solve with another threshold reuses the preparation")
again = relight.solve(room, 1.0, 0.25, ConvergenceThreshold=3e-3, PatchBasis=True)
check(again.GetLastPreparationReused(), "a new mesher's output with the same content finds it too")
relight.vtkLightTaggedRadiosity.ReleasePreparedScenes()
check(Held() == 0, "released: none held")
fresh = relight.solve(room, 1.0, 0.25, ConvergenceThreshold=3e-3, PatchBasis=True)
check(not fresh.GetLastPreparationReused(), "after the release a solve prepares afresh")
def solutions(data):
    cells = data.GetCellData()
    names = [cells.GetArrayName(i) for i in range(cells.GetNumberOfArrays())]
    return np.hstack([cell_array(data, n) for n in names if n.startswith("Radiosity_")])


same = np.array_equal(solutions(solver.GetOutput()), solutions(fresh.GetOutput()))
check(same, "the re-solve on the kept preparation equals a solve prepared afresh, bit for bit")

# --- moving lights use the solver's preparation; a file read back prepares its own ----------
def relit(scene_port=None, scene_data=None):
    rl = relight.vtkRadiosityRelight()
    if scene_port is not None:
        rl.SetInputConnection(0, scene_port)
    else:
        rl.SetInputData(0, scene_data)
    rl.SetInputData(1, relight.point_lights([(1.2, 2.0, 1.5)], intensity=3.0))
    rl.Update()
    return rl

solver.Modified()
solver.Update()  # prepared afresh above: `solver` now reuses `fresh`'s, and keeps it for its output
kept = relit(scene_port=solver.GetOutputPort())
check(kept.GetLastMovingSceneReused(), "the relight's moving lights take the solver's preparation")
with tempfile.TemporaryDirectory() as folder:
    path = os.path.join(folder, "solved.vtp")
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(solver.GetOutput())
    writer.Write()
    back = vtkXMLPolyDataReader()
    back.SetFileName(path)
    back.Update()
    relight.vtkLightTaggedRadiosity.ReleasePreparedScenes()
    alone = relit(scene_data=back.GetOutput())
check(not alone.GetLastMovingSceneReused(), "a solved scene read from a file, nothing kept: the relight prepares")
a, b = (cell_array(r.GetOutput(), "Radiosity") for r in (kept, alone))
check(np.array_equal(a, b), f"moving lights on the solver's preparation equal those on the relight's own "
                            f"(largest difference {np.abs(a - b).max():.3g})")

# --- the EXR writer draws the solver's output without building a ray scene -----------------
relight.vtkLightTaggedRadiosity.ReleasePreparedScenes()
solver.Modified()
solver.Update()
exr = relight.vtkRadiosityEXRWriter()
exr.SetInputConnection(solver.GetOutputPort())
exr.SetCameraPosition(2.0, 1.25, 7.0)
exr.SetFocalPoint(2.0, 1.25, 2.0)
exr.SetSize(64, 48)
exr.SetArrayName("Radiosity_WarmWhite")
rgb = vtkFloatArray()
check(exr.RenderImage(rgb) and exr.GetRaySceneBuilds() == 0, "the EXR view uses the solver's ray scene")

# --- a mesh changed in place is prepared again ---------------------------------------------
# Found by content, not by modification times: numpy writes change no time at all.
mesh = solver.GetInputAlgorithm().GetOutput()
solver.Modified()
solver.Update()
check(solver.GetLastPreparationReused(), "unchanged: reused")
points = vtk_to_numpy(mesh.GetPoints().GetData())
points *= 1.01  # written in place: the points array's modification time stays
solver.Modified()
solver.Update()
check(not solver.GetLastPreparationReused(), "points scaled in place through numpy: the solver prepares again")
ids = vtk_to_numpy(mesh.GetCellData().GetArray("PatchId"))
ids += 1000  # the same patches under other ids: a new patch order to prepare
solver.Modified()
solver.Update()
check(not solver.GetLastPreparationReused(), "PatchId changed in place: the solver prepares again")
solver.Modified()
solver.Update()
check(solver.GetLastPreparationReused(), "and reuses that preparation on the next solve")

# --- preparations go with their meshes ------------------------------------------------------
check(Held() >= 1, f"preparations are held while their meshes live ({Held()})")
del solver, again, fresh, kept, alone, exr, mesh, back, writer, points, ids
gc.collect()
check(Held() == before, f"with the meshes gone, no preparation is held ({Held()} of {before} before): "
                        f"each went as its points were deleted")
finish("TestPreparedScenes")
