#!/usr/bin/env python3
"""What switching a light scene costs: the relight filter over a grid of `--elements`
quads with 8 lights (each its own solution, point and cell arrays as the solver writes
them), switched between two scenes from a light-scenes file; milliseconds per switch
(median of 20), measured in one run beside a single light's intensity change.

    ./relight python Testing/Benchmark/light_scenes_bench.py [--elements 1000000]
"""
import argparse
import os
import tempfile
import time

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

import relight

LIGHTS = [f"Ovni{i}" for i in range(4)] + [f"Erco{i}" for i in range(4)]


def grid(elements):
    """A flat n x n grid of quads with random per-light values (what the solver would write)."""
    n = int(np.sqrt(elements))
    xs, ys = np.meshgrid(np.arange(n + 1, dtype=float), np.arange(n + 1, dtype=float))
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.column_stack([xs.ravel(), ys.ravel(), np.zeros(xs.size)]), deep=True))
    i, j = np.meshgrid(np.arange(n), np.arange(n))
    a = (j * (n + 1) + i).ravel()
    quads = np.column_stack([np.full(a.size, 4), a, a + 1, a + n + 2, a + n + 1]).ravel()
    cells = vtkCellArray()
    cells.SetCells(a.size, numpy_to_vtkIdTypeArray(quads.astype(np.int64), deep=True))
    data = vtkPolyData()
    data.SetPoints(points)
    data.SetPolys(cells)
    rng = np.random.default_rng(1)
    for name in LIGHTS:
        for attributes, count in ((data.GetPointData(), points.GetNumberOfPoints()), (data.GetCellData(), a.size)):
            array = numpy_to_vtk(rng.random((count, 3), dtype=np.float32), deep=True)
            array.SetName("Radiosity_" + name)
            attributes.AddArray(array)
    return relight.add_light_names(data, LIGHTS)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--elements", type=int, default=1000000)
    args = parser.parse_args()
    data = grid(args.elements)
    scenes = os.path.join(tempfile.mkdtemp(), "scenes.csv")
    with open(scenes, "w") as f:
        f.write("Meeting, Ovni*, 100, , , , on\nMeeting, Erco*, 30, 1, 0.8, 0.6, on\nFilm, *, 10, , , , on\n")
    relit = relight.vtkRadiosityRelight()
    relit.SetInputData(data)
    relit.SetLightScenesFileName(scenes)
    relit.SetLightScene("Meeting")
    relit.Update()
    switches, changes = [], []
    for k in range(20):
        relit.SetLightScene("Film" if k % 2 == 0 else "Meeting")
        start = time.perf_counter()
        relit.Update()
        switches.append(time.perf_counter() - start)
        relit.SetLightIntensity(0, 1.0 + 0.1 * k)
        start = time.perf_counter()
        relit.Update()
        changes.append(time.perf_counter() - start)
    print(f"{data.GetNumberOfCells()} elements, {len(LIGHTS)} lights, {os.cpu_count()} cores: a light-scene switch "
          f"{1e3 * np.median(switches):.1f} ms, one light's intensity {1e3 * np.median(changes):.1f} ms "
          f"(ratio {np.median(switches) / np.median(changes):.2f}; medians of 20, one run)")


if __name__ == "__main__":
    main()
