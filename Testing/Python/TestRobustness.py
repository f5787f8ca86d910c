"""Correct under every input (issue 13): each case here crashed, wrote a broken file, or
passed silently before. Every failure must be a clear error naming the problem, with
nothing half-done left behind."""

import os
import tempfile

import numpy as np
from vtkmodules.vtkCommonCore import vtkLogger

import relight
from relight import light_names, read_polydata
from testlib import check, finish

vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
DATA = os.path.join(os.environ.get("RELIGHT_ROOT", "."), "Data")

# --- EXR writer: bad sizes and cameras are refused, failures raise, files are never truncated --
solved = relight.solve(read_polydata(os.path.join(DATA, "paper_1lights.vtp")), 1.0, 0.5,
                       ConvergenceThreshold=1e-2).GetOutput()
ARRAY = "Radiosity_" + light_names(solved)[0]
CAMERA = ((2, 1.5, 6), (2, 1.5, 0), (0, 1, 0), 40)
folder = tempfile.mkdtemp()
good = os.path.join(folder, "view.exr")
relight.write_exr(solved, good, CAMERA, size=(64, 48), array=ARRAY)


def refused(label, fragment, path=good, camera=CAMERA, image=(64, 48)):
    try:
        relight.write_exr(solved, path, camera, size=image, array=ARRAY)
        check(False, f"EXR {label}: refused")
    except OSError as error:
        check(fragment in str(error), f"EXR {label}: OSError naming the problem ({error})")


refused("size -5 x 10", "outside 1..32768", image=(-5, 10))
refused("size 100000 x 100000", "outside 1..32768", image=(100000, 100000))
refused("size 30000 x 30000", "GB", image=(30000, 30000))
refused("NaN camera position", "must be finite", camera=((float("nan"), 0, 0),) + CAMERA[1:])
refused("camera at its focal point", "no view direction", camera=(CAMERA[1],) + CAMERA[1:])
refused("view-up along the view", "view-up", camera=CAMERA[:2] + ((0, 0, 1), 40))
refused("a directory as the file", "Is a directory", path=folder)
refused("a missing folder", "No such file", path=os.path.join(folder, "missing", "x.exr"))
refused("an empty file name", "no FileName", path="")
# The new picture is written beside the old one and renamed over it: when that fails, the
# old file is untouched (here the temporary name is taken by a directory).
size = os.path.getsize(good)
os.mkdir(good + ".part")
refused("temporary name taken", "could not write", path=good)
check(os.path.getsize(good) == size, f"a failed write leaves the old file whole ({os.path.getsize(good)} bytes)")
os.rmdir(good + ".part")
relight.write_exr(solved, good, CAMERA, size=(32, 24), array=ARRAY)
check(sorted(os.listdir(folder)) == ["view.exr"] and os.path.getsize(good) != size,
      f"a good write replaces the file and leaves nothing else: {sorted(os.listdir(folder))}")

# --- too many lights for the machine: a clear error with the size, not std::bad_alloc --------
polygons, reflectance, ids = [[(0, 0, 0), (20, 0, 0), (20, 20, 0), (0, 20, 0)]], [(0.5,) * 3], [-1]
for i in range(200):
    for j in range(200):  # 40,000 lamps of 5 cm
        x, y = 0.1 * i, 0.1 * j
        polygons.append([(x, y, 1), (x, y + 0.05, 1), (x + 0.05, y + 0.05, 1), (x + 0.05, y, 1)])
        reflectance.append((0.5,) * 3)
        ids.append(len(ids) - 1)
mesher = relight.vtkRadiosityMesher()
mesher.SetInputData(relight.make_scene(polygons, reflectance, ids))
mesher.SetPatchSize(1.0)
mesher.SetElementSize(0.25)
solver = relight.vtkLightTaggedRadiosity()
solver.SetInputConnection(mesher.GetOutputPort())
catcher = relight.ErrorCatcher(solver)
solver.Update()
check("40000 solutions on 46400 elements needs about" in catcher.first_error() and
      solver.GetOutput().GetNumberOfCells() == 0, f"40,000 lights: {catcher.first_error()}")

finish("TestRobustness")
