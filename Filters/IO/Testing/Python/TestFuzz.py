"""Fuzzing: random polygon soups and random array values through mesher + solver + relight.

Never a crash, a hang or a NaN: every stage either gives a finite result or reports a
clear error and an empty output. Also: unshot energy never rises (reflectances up to 1,
coarse one-element patches), and a converged analytic solve of the scene scaled by
1e-3..1e3, rotated and moved gives the same radiosity to 1e-3 of its peak. CI runs a
bounded number of cases; for a long run:
    RELIGHT_FUZZ_CASES=20000 RELIGHT_FUZZ_SEED=7 ./relight python Filters/IO/Testing/Python/TestFuzz.py
"""

import math
import os
import random
import signal
import sys
import time

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import (
    vtkDoubleArray,
    vtkFloatArray,
    vtkIntArray,
    vtkLogger,
    vtkPoints,
    vtkStringArray,
)
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter

import relight
from relight import ErrorCatcher

vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
CASES = int(os.environ.get("RELIGHT_FUZZ_CASES", "150"))
SEED = int(os.environ.get("RELIGHT_FUZZ_SEED", "2026"))
rng = random.Random(SEED)


def pick(*choices):
    return rng.choice(choices)


def number(scale, wild):
    """Ordinary values, or with `wild` sometimes the ones that break code."""
    if wild and rng.random() < 0.05:
        return pick(math.nan, math.inf, -math.inf, 0.0, 1e300)
    return rng.uniform(-1, 1) * scale


def unit(v):
    n = math.sqrt(sum(c * c for c in v)) or 1.0
    return [c / n for c in v]


def random_scene():
    """A random polygon soup. Most cases are valid (so the solver and relight get real
    work); about a third carry one kind of corruption."""
    wild = rng.random() < 0.35
    data = vtkPolyData()
    points = vtkPoints()
    points.SetDataTypeToDouble()
    polys = vtkCellArray()
    scale = 10 ** rng.uniform(-4, 4)
    cells = rng.randint(1 if not wild else 0, 14)
    for _ in range(cells):
        count = rng.randint(3, 7) if not wild else rng.randint(1, 7)
        shape = pick("planar", "planar", "planar", "random", "duplicate", "collinear", "concave") if wild \
            else pick("planar", "planar", "concave")
        centre = [number(scale, wild) for _ in range(3)]
        normal = unit([rng.gauss(0, 1) for _ in range(3)])
        u = unit([normal[1], -normal[0], 0.0] if abs(normal[2]) < 0.9 else [0.0, normal[2], -normal[1]])
        v = [normal[1] * u[2] - normal[2] * u[1], normal[2] * u[0] - normal[0] * u[2], normal[0] * u[1] - normal[1] * u[0]]
        size = scale * rng.uniform(0.1, 1.0)
        ids = []
        for k in range(count):
            angle = 2 * math.pi * k / count
            radius = size * (0.4 if shape == "concave" and k % 2 else 1.0)
            a, b = radius * math.cos(angle), radius * math.sin(angle)
            p = [centre[i] + a * u[i] + b * v[i] for i in range(3)]
            if shape == "random":
                p = [centre[i] + number(scale, wild) for i in range(3)]
            elif shape == "collinear":
                p = [centre[0] + k * size, centre[1], centre[2]]
            elif shape == "duplicate" and ids and rng.random() < 0.5:
                p = list(points.GetPoint(ids[-1]))
            ids.append(points.InsertNextPoint(*p))
        polys.InsertNextCell(len(ids), ids)
    data.SetPoints(points)
    data.SetPolys(polys)
    n = data.GetNumberOfCells()
    lights = rng.randint(1, 3)
    light_of = [rng.choice([-1, -1, -1] + list(range(lights))) for _ in range(n)]
    for i in range(min(lights, n)):
        light_of[i] = i  # every id 0..k-1 used, unless corrupted below
    if not wild or rng.random() < 0.9:
        r = pick(vtkFloatArray, vtkDoubleArray)() if not wild else pick(vtkFloatArray, vtkDoubleArray, vtkIntArray)()
        r.SetName("Reflectance")
        components = 3 if not wild else pick(3, 3, 3, 1, 4)
        r.SetNumberOfComponents(components)
        for _ in range(n):
            r.InsertNextTuple([(rng.uniform(0, 0.999) if rng.random() < 0.8 else pick(0.99, 0.999, 1.0))
                               if not wild or rng.random() < 0.95
                               else pick(math.nan, -0.1, 1.1) for _ in range(components)])
        data.GetCellData().AddArray(r)
    if not wild or rng.random() < 0.9:
        if wild and rng.random() < 0.1:
            ids = vtkStringArray()
            for _ in range(n):
                ids.InsertNextValue("0")
        else:
            ids = pick(vtkIntArray, vtkDoubleArray)()
            for i in range(n):
                value = light_of[i]
                if wild and rng.random() < 0.1:
                    value = pick(-2, 0.5, lights + 1)
                ids.InsertNextTuple1(value)
        ids.SetName("LightId")
        data.GetCellData().AddArray(ids)
    if rng.random() < 0.5:
        e = vtkFloatArray()
        e.SetName("Emission")
        e.SetNumberOfComponents(3)
        for _ in range(n):
            e.InsertNextTuple3(*[abs(number(1.0, wild)) if rng.random() < 0.95 else number(1.0, wild)
                                 for _ in range(3)])
        data.GetCellData().AddArray(e)
    if rng.random() < 0.3:
        names = vtkStringArray()
        names.SetName("LightNames")
        for i in range(rng.randint(0, 4)):
            names.InsertNextValue(pick("A", "B", "A", "", "lamp %d" % i))
        data.GetFieldData().AddArray(names)
    return data, scale


def finite_arrays(data):
    for attributes in (data.GetPointData(), data.GetCellData()):
        for a in range(attributes.GetNumberOfArrays()):
            array = attributes.GetArray(a)
            if array is not None and array.GetName() and array.GetName().startswith(("Radiosity", "Direct")):
                if not np.isfinite(vtk_to_numpy(array)).all():
                    return False
    return True


def run_stage(algorithm, source, what, stats):
    algorithm.SetInputData(source)
    catcher = ErrorCatcher(algorithm)
    algorithm.Update()
    out = algorithm.GetOutput()
    if catcher.errors:
        if out.GetNumberOfCells() != 0:
            raise AssertionError(f"{what}: error but a non-empty output: {catcher.errors[0]}")
        if not all("Cannot" in e or "error" in e.lower() for e in catcher.errors):
            raise AssertionError(f"{what}: unclear error: {catcher.errors}")
        stats[what + " errors"] = stats.get(what + " errors", 0) + 1
        if os.environ.get("RELIGHT_FUZZ_VERBOSE"):
            print("   ", catcher.errors[0].strip().splitlines()[-1][:150], flush=True)
        return None
    if not finite_arrays(out):
        raise AssertionError(f"{what}: NaN or infinity in the output")
    stats[what + " ok"] = stats.get(what + " ok", 0) + 1
    return out


def check_placement(solver, source, solved, stats):
    """The same scene scaled, rotated and moved (in double precision) gives the same
    radiosity, relative to its peak, when the solve is not cut short by time."""
    if solver.GetLastSolveSeconds() > 2.0 or not solver.GetLastConverged():
        return  # a cut-short solve depends on which of two equal shooters goes first
    transform = vtkTransform()
    transform.RotateWXYZ(rng.uniform(0, 360), rng.gauss(0, 1), rng.gauss(0, 1), rng.gauss(0, 1) + 1e-3)
    transform.Translate(*[rng.uniform(-100, 100) for _ in range(3)])
    factor = 10 ** rng.uniform(-3, 3)
    transform.Scale(factor, factor, factor)
    moved = vtkTransformPolyDataFilter()
    moved.SetTransform(transform)
    moved.SetOutputPointsPrecision(2)
    moved.SetInputData(source)
    moved.Update()
    again = relight.vtkLightTaggedRadiosity()
    for name in ("FormFactorMethod", "FormFactorSamples", "MaximumShots", "AmbientTerm", "SeparateDirect", "SolutionMode"):
        getattr(again, "Set" + name)(getattr(solver, "Get" + name)())
    catcher = ErrorCatcher(again)
    again.SetInputData(moved.GetOutput())
    again.Update()
    if catcher.errors:
        raise AssertionError(f"placement: the moved scene fails: {catcher.errors[0]}")
    for i in range(solved.GetCellData().GetNumberOfArrays()):
        name = solved.GetCellData().GetArrayName(i)
        if name and name.startswith("Radiosity"):
            a = vtk_to_numpy(solved.GetCellData().GetArray(name)).astype(float)
            b = vtk_to_numpy(again.GetOutput().GetCellData().GetArray(name)).astype(float)
            peak = max(abs(a).max(), 1e-300)
            if a.shape != b.shape or abs(a - b).max() > 1e-3 * peak:
                raise AssertionError(f"placement: '{name}' changes by {abs(a - b).max() / peak:.2e} of its peak "
                                     f"(scale {factor:.3g})")
    stats["placement checks"] = stats.get("placement checks", 0) + 1


def on_timeout(signum, frame):
    raise TimeoutError("a case took longer than 60 s (hang?)")


signal.signal(signal.SIGALRM, on_timeout)
stats = {}
start = time.time()
for case in range(CASES):
    scene, scale = random_scene()
    if os.environ.get("RELIGHT_FUZZ_VERBOSE"):
        print(f"case {case}: {scene.GetNumberOfCells()} cells, scale {scale:.3g}", flush=True)
    signal.alarm(60)
    try:
        mesher = relight.vtkRadiosityMesher()
        mesher.SetPatchSize(scale * pick(0.5, 1.0, 5.0, 1e-9, 1e9))
        mesher.SetElementSize(scale * pick(0.25, 0.5, 0.05, 2.0))  # 2.0: coarse, one element per patch
        if os.environ.get("RELIGHT_FUZZ_VERBOSE"):
            print(f"  mesher {mesher.GetPatchSize():.3g} {mesher.GetElementSize():.3g}", flush=True)
        meshed = run_stage(mesher, scene, "mesher", stats)
        solver = relight.vtkLightTaggedRadiosity()
        solver.SetFormFactorMethod(rng.randint(0, 2))
        solver.SetFormFactorSamples(pick(0, 1, 4, 64))
        solver.SetMaximumShots(rng.randint(0, 200))
        solver.SetAmbientTerm(rng.random() < 0.3)
        solver.SetSeparateDirect(rng.random() < 0.3)
        solver.SetSolutionMode(rng.randint(0, 2))
        solver.SetTimeBudget(5.0)
        source = meshed if meshed is not None and rng.random() < 0.8 else scene
        solved = run_stage(solver, source, "solver", stats)
        if solved is None:
            continue
        unshot = solved.GetFieldData().GetArray("UnshotHistory")
        history = [unshot.GetValue(i) for i in range(unshot.GetNumberOfTuples())] if unshot else []
        if any(b > a * (1 + 1e-9) for a, b in zip(history, history[1:])):
            raise AssertionError("unshot energy rose during the solve")
        if solver.GetFormFactorMethod() == 0 and solver.GetTimeBudget() > 0 and rng.random() < 0.3:
            check_placement(solver, source, solved, stats)
        rl = relight.vtkRadiosityRelight()
        for i in range(rng.randint(0, 4)):
            rl.SetLightColor(rng.randint(-1, 4), abs(number(2.0, False)), abs(number(2.0, False)), 1.0)
            rl.SetLightIntensity(rng.randint(-1, 4), pick(1.0, 1e6, 0.0, -1.0, math.nan))
            rl.SetLightEnabled(rng.randint(-1, 4), rng.random() < 0.5)
        rl.SetIndirectScale(pick(1.0, 0.0, 2.0))
        run_stage(rl, solved, "relight", stats)
    except (AssertionError, TimeoutError) as failure:
        print(f"case {case} (seed {SEED}) failed: {failure}")
        sys.exit(1)
    finally:
        signal.alarm(0)

print(f"{CASES} fuzz cases in {time.time() - start:.1f} s, seed {SEED}: " +
      ", ".join(f"{k} {v}" for k, v in sorted(stats.items())))
print("TestFuzz: all cases passed")
