"""Starts the real ParaView GUI under Xvfb with one test script and judges what the script
left behind: its result file (the GUI's own exit code and output do not carry a script's
failure) and, where a baseline is given, its screenshot.

usage: RunParaViewGUI.py PARAVIEW PLUGIN_DIR ROOT SCRIPT OUTPUT_DIR [BASELINE]

The script (run with `paraview --dr --script=SCRIPT --exit`) writes OUTPUT_DIR/NAME.json
with {"failures": [...], "notes": [...]} through guitest.finish(), and NAME.png if it
takes a screenshot. NAME is the script's file name without .py.
"""

import json
import os
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader


def read_png(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    pixels = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars()).astype(np.int32)
    return pixels[:, :3]


def compare(output, baseline):
    """Failures from comparing the screenshot with its baseline image."""
    if not os.path.exists(output):
        return ["the GUI wrote no screenshot"]
    if not os.path.exists(baseline):
        return [f"no baseline {baseline}; the new image is {output} (look at it, then copy it)"]
    images = [read_png(output), read_png(baseline)]
    if images[0].shape != images[1].shape:
        return [f"image sizes differ: {images[0].shape} vs {images[1].shape}"]
    difference = np.abs(images[0] - images[1]).max(axis=1)
    changed = float((difference > 8).mean())
    print(f"pixels differing by more than 8 levels: {changed:.2%} (limit 1 %), mean {difference.mean():.2f}")
    return [f"{output} differs from {baseline}"] if changed > 0.01 else []


def main():
    paraview, plugin_dir, root, script, output_dir = sys.argv[1:6]
    baseline = sys.argv[6] if len(sys.argv) > 6 else None
    name = os.path.splitext(os.path.basename(script))[0]
    result_path = os.path.join(output_dir, name + ".json")
    image_path = os.path.join(output_dir, name + ".png")
    for path in (result_path, image_path):
        if os.path.exists(path):
            os.remove(path)
    env = dict(os.environ, PV_PLUGIN_PATH=plugin_dir, RELIGHT_ROOT=root, RELIGHT_OUTPUT_DIR=output_dir,
               RELIGHT_TEST_NAME=name, RELIGHT_TEST_DIR=os.path.dirname(os.path.abspath(__file__)))
    # --dr: default settings and no welcome dialog, whatever the user's ParaView remembers.
    try:
        output = subprocess.run([paraview, "--dr", f"--script={script}", "--exit"], env=env, timeout=300,
                                check=False, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                errors="replace").stdout
    except subprocess.TimeoutExpired as stopped:
        output = (stopped.output or b"").decode(errors="replace") + f"\nstopped after {stopped.timeout} s"
    if not os.path.exists(result_path):
        print(str(output)[-4000:])
        print(f"FAIL: {name} left no result (the script did not finish; its output is above)")
        sys.exit(1)
    with open(result_path) as f:
        result = json.load(f)
    for note in result.get("notes", []):
        print(note)
    failures = list(result.get("failures", []))
    if baseline:
        failures += compare(image_path, baseline)
    for failure in failures:
        print("FAIL:", failure)
    if failures:
        sys.exit(1)
    print(f"{name}: passed")


if __name__ == "__main__":
    main()
