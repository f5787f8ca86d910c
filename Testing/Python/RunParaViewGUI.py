"""Starts the real ParaView GUI with TestParaViewGUI.py and compares its screenshot with a
baseline image (the GUI's own exit code and output do not carry a script's failure).

usage: RunParaViewGUI.py PARAVIEW PLUGIN_DIR ROOT BASELINE OUTPUT
"""

import os
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

paraview, plugin_dir, root, baseline, output = sys.argv[1:6]
if os.path.exists(output):
    os.remove(output)
env = dict(os.environ, PV_PLUGIN_PATH=plugin_dir, RELIGHT_ROOT=root, RELIGHT_OUTPUT=output)
script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "TestParaViewGUI.py")
subprocess.run([paraview, f"--script={script}", "--exit"], env=env, timeout=300, check=False,
               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
if not os.path.exists(output):
    print("FAIL: the GUI wrote no screenshot")
    sys.exit(1)
if not os.path.exists(baseline):
    print(f"FAIL: no baseline {baseline}; the new image is {output} (look at it, then copy it)")
    sys.exit(1)
images = []
for path in (output, baseline):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    pixels = vtk_to_numpy(data.GetPointData().GetScalars()).astype(np.int32)
    images.append(pixels[:, :3])
if images[0].shape != images[1].shape:
    print(f"FAIL: image sizes differ: {images[0].shape} vs {images[1].shape}")
    sys.exit(1)
difference = np.abs(images[0] - images[1]).max(axis=1)
changed = float((difference > 8).mean())
print(f"pixels differing by more than 8 levels: {changed:.2%} (limit 1 %), mean {difference.mean():.2f}")
if changed > 0.01:
    print(f"FAIL: {output} differs from {baseline}")
    sys.exit(1)
print("RunParaViewGUI: passed")
