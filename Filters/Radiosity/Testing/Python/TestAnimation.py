"""Light animation: a schedule of keyframes (in Python or a CSV file) makes the relight
filter time-aware; any time relights by linear interpolation between keyframes."""

import os
import tempfile

import numpy as np
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
from vtkmodules.vtkCommonCore import vtkLogger

import relight
from testlib import check, finish
from relight import cell_array, read_polydata

vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_WARNING)
DATA = os.path.join(os.environ.get("RELIGHT_ROOT", "."), "Data")
mesher = relight.vtkRadiosityMesher()
mesher.SetInputData(read_polydata(os.path.join(DATA, "paper_3lights.vtp")))
mesher.SetPatchSize(1.5)
mesher.SetElementSize(0.375)
solver = relight.vtkLightTaggedRadiosity()
solver.SetInputConnection(mesher.GetOutputPort())
solver.Update()
solved = solver.GetOutput()
B = {n: cell_array(solved, "Radiosity_" + n).astype(np.float64) for n in ("WarmWhite", "CoolWhite", "Amber")}
emission, ids = cell_array(solved, "Emission"), cell_array(solved, "LightId")
amber_default = emission[ids == 2].mean(axis=0)

rows = [  # time, light, r, g, b, intensity, enabled
    (0.0, "WarmWhite", 1.0, 1.0, 1.0, 1.0, 1),
    (10.0, "WarmWhite", 1.0, 0.0, 0.0, 3.0, 1),
    (0.0, "1", 1.0, 1.0, 1.0, 1.0, 0),  # CoolWhite by index: off
]


def expected(t):
    w = t / 10.0
    color = np.array([1.0, 1.0 - w, 1.0 - w]) * (1.0 + 2.0 * w)
    return color * B["WarmWhite"] + amber_default * B["Amber"]


def run(rl, label):
    rl.SetInputConnection(solver.GetOutputPort())
    rl.UpdateInformation()
    steps = rl.GetOutputInformation(0).Get(sddp.TIME_STEPS())
    check(steps is not None and list(steps) == [0.0, 10.0], f"{label}: time steps {steps}")
    executions = []
    solver.AddObserver("StartEvent", lambda *a: executions.append(1))
    for t in (0.0, 2.5, 5.0, 10.0, 12.0):
        rl.UpdateTimeStep(t)
        got = cell_array(rl.GetOutput(), "Radiosity")
        check(np.allclose(got, expected(min(t, 10.0)), rtol=1e-5, atol=1e-8), f"{label}: relit at t = {t}")
    check(not executions, f"{label}: scrubbing time never re-solves")


scheduled = relight.vtkRadiosityRelight()
for row in rows:
    scheduled.AddScheduleEntry(*row)
run(scheduled, "AddScheduleEntry")

with tempfile.NamedTemporaryFile("w", suffix=".csv", delete=False) as f:
    f.write("time,light,r,g,b,intensity,enabled\n")
    for row in rows:
        f.write(",".join(str(v) for v in row) + "\n")
from_file = relight.vtkRadiosityRelight()
from_file.SetScheduleFileName(f.name)
run(from_file, "CSV schedule")
os.unlink(f.name)

# A schedule naming a light the data lacks is said once, not at every frame of an animation
# (it was said at each update, burying the rest of the log); a new mistake is said again.
misnamed = relight.vtkRadiosityRelight()
misnamed.AddScheduleEntry(0.0, "Nobody", 1.0, 0.0, 0.0, 1.0, 1)
misnamed.AddScheduleEntry(10.0, "Nobody", 1.0, 0.0, 0.0, 2.0, 1)
misnamed.SetInputConnection(solver.GetOutputPort())
catcher = relight.ErrorCatcher(misnamed)
for t in (0.0, 2.5, 5.0, 7.5):
    misnamed.UpdateTimeStep(t)
said = [w for w in catcher.warnings if "Nobody" in w]
check(len(said) == 1, f"an unknown light in the schedule: said {len(said)} times over 4 frames")
misnamed.SetLightIntensity(7, 2.0)
misnamed.UpdateTimeStep(0.0)
said = [w for w in catcher.warnings if "index 7" in w]
again = [w for w in catcher.warnings if "Nobody" in w]
check(len(said) == 1 and len(again) == 1,
      f"...and a light index past the lights, said when set ({len(said)}), the name not again ({len(again)})")

finish("TestAnimation")
