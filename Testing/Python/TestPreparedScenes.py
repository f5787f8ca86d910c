"""One preparation per mesh (issue 14): the solver's ray scene and geometry are kept for its
mesh and shared by a re-solve with other settings, by the relight's moving lights and by the
EXR writer. Each must give what a preparation made afresh gives, and a changed mesh must be
prepared again; a preparation goes with the last mesh that uses it."""

import gc
import os
import tempfile

import numpy as np
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkLogger
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter

import relight
from relight import cell_array
from testlib import check, finish

vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_WARNING)
DATA = os.path.join(os.environ.get("RELIGHT_ROOT", os.path.join(os.path.dirname(__file__), "..", "..")), "Data")
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
fresh = relight.solve(room, 1.0, 0.25, ConvergenceThreshold=3e-3, PatchBasis=True)
check(not fresh.GetLastPreparationReused(), "a new mesher's output is prepared afresh")
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
    alone = relit(scene_data=back.GetOutput())
check(not alone.GetLastMovingSceneReused(), "a solved scene read from a file is prepared by the relight")
a, b = (cell_array(r.GetOutput(), "Radiosity") for r in (kept, alone))
check(np.array_equal(a, b), f"moving lights on the solver's preparation equal those on the relight's own "
                            f"(largest difference {np.abs(a - b).max():.3g})")

# --- the EXR writer draws the solver's output without building a ray scene -----------------
exr = relight.vtkRadiosityEXRWriter()
exr.SetInputConnection(solver.GetOutputPort())
exr.SetCameraPosition(2.0, 1.25, 7.0)
exr.SetFocalPoint(2.0, 1.25, 2.0)
exr.SetSize(64, 48)
exr.SetArrayName("Radiosity_WarmWhite")
rgb = vtkFloatArray()
check(exr.RenderImage(rgb) and exr.GetRaySceneBuilds() == 0, "the EXR view uses the solver's ray scene")

# --- a mesh changed in place is prepared again ---------------------------------------------
mesh = solver.GetInputAlgorithm().GetOutput()
mesh.GetPoints().Modified()
solver.Modified()
solver.Update()
check(not solver.GetLastPreparationReused(), "points modified in place: the solver prepares again")

# --- preparations go with their meshes ------------------------------------------------------
check(Held() >= 1, f"preparations are held while their meshes live ({Held()})")
del solver, fresh, kept, alone, exr, mesh, back, writer
gc.collect()
check(Held() == before, f"with the meshes gone, no preparation is held ({Held()} of {before} before)")
finish("TestPreparedScenes")
