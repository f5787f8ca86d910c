"""Bad input gets a clear error naming the problem and an empty output: no crash, no NaN."""

import math
import os
import tempfile
import sys

import numpy as np
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkFloatArray, vtkIntArray, vtkStringArray
from vtkmodules.vtkCommonDataModel import vtkPolyData

import relight
from relight import ErrorCatcher, make_scene
from vtkmodules.vtkCommonCore import vtkLogger, vtkOutputWindow, vtkStringOutputWindow

# The executive logs every failed request too; the filters' own messages are what we check.
vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)

failures = []


def scene(reflectance=(0.5, 0.5, 0.5), light_ids=(0, -1), points=None, reflectance_components=3,
          light_array=vtkIntArray, with_reflectance=True, with_light=True):
    """Two unit quads facing each other; the first one is the light. The arguments break
    one thing at a time."""
    coords = points or [(0, 0, 1), (0, 1, 1), (1, 1, 1), (1, 0, 1), (0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    quads = [coords[0:4], coords[4:8]][: len(light_ids)]
    data = make_scene(quads, [(0.5, 0.5, 0.5)] * len(quads), [-1] * len(quads))
    cells = data.GetCellData()
    cells.RemoveArray("Reflectance")
    cells.RemoveArray("LightId")
    if with_reflectance:
        r = vtkFloatArray()
        r.SetName("Reflectance")
        r.SetNumberOfComponents(reflectance_components)
        for _ in light_ids:
            r.InsertNextTuple(list(reflectance)[:reflectance_components])
        cells.AddArray(r)
    if with_light:
        ids = light_array()
        ids.SetName("LightId")
        for i in light_ids:
            ids.InsertNextValue(i)
        cells.AddArray(ids)
    return data


def expect_error(filter_class, data, fragment, setup=None):
    f = filter_class()
    f.SetInputData(data)
    if setup:
        setup(f)
    catcher = ErrorCatcher(f)
    f.Update()
    out = f.GetOutput()
    message = " | ".join(catcher.errors)
    ok = any(fragment in e for e in catcher.errors) and out.GetNumberOfCells() == 0
    print(f"{'ok  ' if ok else 'FAIL'} {filter_class.__name__}: expected '{fragment}', got: {message}")
    if not ok:
        failures.append(fragment)


solver = relight.vtkLightTaggedRadiosity
mesher = relight.vtkRadiosityMesher
nan = math.nan
# Reflectance
expect_error(solver, scene(reflectance=(0.5, nan, 0.5)), "Reflectance of cell 0")
expect_error(mesher, scene(reflectance=(0.5, nan, 0.5)), "Reflectance of cell 0")
# The light marker's Emission (ParaView's panel bounds it at 0; Python can pass anything)
for bad in ((-1.0, 1.0, 1.0), (1.0, nan, 1.0)):
    expect_error(relight.vtkRadiosityLightMarker, scene(), "Emission color component",
                 lambda f, e=bad: (f.SetEmission(*e), f.AddCellId(1)))
expect_error(solver, scene(reflectance=(1.5, 0.5, 0.5)), "must be a number in [0, 1]")
expect_error(solver, scene(reflectance=(-0.1, 0.5, 0.5)), "must be a number in [0, 1]")
expect_error(solver, scene(reflectance_components=1), "'Reflectance' has 1 components; it needs 3")
expect_error(solver, scene(with_reflectance=False), "no cell array 'Reflectance'")
# LightId
expect_error(solver, scene(with_light=False), "no cell array 'LightId'")
expect_error(solver, scene(light_ids=(1, -1)), "LightId has a gap")
expect_error(solver, scene(light_ids=(0, -3)), "LightId of cell 1 is -3")
expect_error(solver, scene(light_ids=(-1, -1)), "no lights (k = 0)")
expect_error(mesher, scene(light_ids=(0.5, -1), light_array=vtkDoubleArray), "must hold integers")
string_ids = scene(with_light=False)
s = vtkStringArray()
s.SetName("LightId")
s.InsertNextValue("0")
s.InsertNextValue("-1")
string_ids.GetCellData().AddArray(s)
expect_error(solver, string_ids, "it must be a numeric array")
short = scene()
short.GetCellData().GetArray("Reflectance").SetNumberOfTuples(1)
expect_error(solver, short, "'Reflectance' has 1 tuples; it needs one per cell")
huge = scene(light_ids=(0, -1))
huge.GetCellData().GetArray("LightId").SetValue(0, 2000000000)
expect_error(solver, huge, "there are only 2 cells")
# Geometry
expect_error(solver, vtkPolyData(), "no polygons")
expect_error(mesher, vtkPolyData(), "no polygons")
# Triangle strips alone (vtkStripper's output): said, with the filter that turns them into polygons.
from vtkmodules.vtkFiltersCore import vtkStripper, vtkTriangleFilter
triangles = vtkTriangleFilter()
triangles.SetInputData(scene())
stripper = vtkStripper()
stripper.SetInputConnection(triangles.GetOutputPort())
stripper.Update()
expect_error(mesher, stripper.GetOutput(), "vtkTriangleFilter")
flat = [(0, 0, 1), (0, 0, 1), (1, 1, 1), (1, 1, 1), (0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
expect_error(solver, scene(points=flat), "cell 0 has zero area")
expect_error(mesher, scene(points=flat), "cell 0 has zero area")
nan_point = [(0, 0, 1), (0, nan, 1), (1, 1, 1), (1, 0, 1), (0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
expect_error(solver, scene(points=nan_point), "non-finite coordinate")
# A closed room reflecting all the light has no finite solution: said, not run to the cap.
expect_error(solver, relight.furnace_box(rho=1.0), "no finite solution")
# Settings that cannot mean anything: a NaN threshold ended every solve at once as "converged".
expect_error(solver, scene(), "ConvergenceThreshold is nan", setup=lambda s: s.SetConvergenceThreshold(nan))
expect_error(solver, scene(), "TimeBudget is nan", setup=lambda s: s.SetTimeBudget(nan))
expect_error(solver, scene(), "ClusterSeparation is 1.5", setup=lambda s: s.SetClusterSeparation(1.5))
expect_error(mesher, scene(), "choose a larger ElementSize", setup=lambda m: m.SetElementSize(1e-9))

# Relight: no solutions, wrong array types, NaN inside a solution.
expect_error(relight.vtkRadiosityRelight, scene(), "no lights")


def with_solution(kind, name, value):
    """scene() with a 3-component point array `name` of type `kind`, value(i) at point i."""
    data = scene()
    array = kind()
    array.SetName(name)
    array.SetNumberOfComponents(3)
    for i in range(data.GetNumberOfPoints()):
        array.InsertNextTuple3(value(i), 0.5, 0.5)
    data.GetPointData().AddArray(array)
    return data


expect_error(relight.vtkRadiosityRelight, with_solution(vtkIntArray, "Radiosity_Bad", lambda i: 1),
             "solutions must be float or double")
poisoned = with_solution(vtkFloatArray, "Radiosity_Lamp", lambda i: nan if i == 3 else 0.5)
expect_error(relight.vtkRadiosityRelight, poisoned, "not finite at item 3")
# Exposure -1 was clamped to 0 without a word (an all-black picture); NaN reached glTF as null.
lit = with_solution(vtkFloatArray, "Radiosity_Lamp", lambda i: 0.5)
expect_error(relight.vtkRadiosityRelight, lit, "must be finite and not negative", setup=lambda r: r.SetExposure(-1))
for exposure in (nan, -1.0):
    try:
        relight.write_gltf(lit, os.path.join(tempfile.gettempdir(), "bad_exposure.glb"), exposure=exposure)
        refused = False
    except OSError as error:
        refused = "Exposure is" in str(error)
    print(f"{'ok  ' if refused else 'FAIL'} write_gltf with exposure {exposure}: refused")
    if not refused:
        failures.append(f"write_gltf exposure {exposure}")

# A NaN in a disabled light is not an error: the light contributes nothing.
r = relight.vtkRadiosityRelight()
r.SetInputData(poisoned)
r.SetLightEnabled(0, False)
r.Update()
got = relight.point_array(r.GetOutput(), "Radiosity")
if not (np.all(got == 0) and got.shape == (8, 3)):
    failures.append("disabled NaN light")
    print("FAIL disabled light with NaN data should give zeros")

# The input the user made is never modified.
original = scene(reflectance=(0.5, nan, 0.5))
before = relight.cell_array(original, "Reflectance").copy()
f = solver()
f.SetInputData(original)
ErrorCatcher(f)
f.Update()
if not np.array_equal(before, relight.cell_array(original, "Reflectance"), equal_nan=True):
    failures.append("input modified")

# A failed filter says what went wrong once and returns 0, as VTK filters do: the update
# stops there (the executive reports that one failure), and the filters downstream do not
# run, so they add no "no polygons" errors of their own.
window = vtkStringOutputWindow()
previous = vtkOutputWindow.GetInstance()
vtkOutputWindow.SetInstance(window)
broken = scene(reflectance=(0.5, nan, 0.5))
chain = [relight.vtkRadiosityMesher(), solver(), relight.vtkRadiosityRelight()]
chain[0].SetInputData(broken)
for upstream, downstream in zip(chain, chain[1:]):
    downstream.SetInputConnection(upstream.GetOutputPort())
updated = chain[-1].GetExecutive().Update()
vtkOutputWindow.SetInstance(previous)
text = window.GetOutput()
own = text.count("Cannot ")
dumps = [line for line in text.splitlines() if "returned failure" in line]
print(f"{'ok  ' if own == 1 and len(dumps) == 1 else 'FAIL'} a broken scene through three filters: "
      f"update {updated}, {own} error(s) of the filters, {len(dumps)} executive report(s)")
if updated != 0 or own != 1 or len(dumps) != 1 or "vtkRadiosityMesher" not in dumps[0] or \
        chain[0].GetOutput().GetNumberOfCells() != 0 or \
        chain[0].GetOutput().GetFieldData().GetArray("RadiosityFailed") is None:
    failures.append("one clean error for a failed pipeline")
    print(text)

# relight.solve on a broken scene raises the filter's own words and prints nothing: not the
# filter's message, not the executive's report that follows it.
window = vtkStringOutputWindow()
vtkOutputWindow.SetInstance(window)
try:
    relight.solve(scene(reflectance=(0.5, nan, 0.5)), 1.0, 0.5)
    raised = ""
except RuntimeError as error:
    raised = str(error)
vtkOutputWindow.SetInstance(previous)
quiet = window.GetOutput().strip() == ""
print(f"{'ok  ' if raised.startswith('Cannot mesh') and quiet else 'FAIL'} relight.solve of a broken scene: "
      f"{raised!r}, output window {'empty' if quiet else window.GetOutput()!r}")
if not raised.startswith("Cannot mesh") or not quiet:
    failures.append("relight.solve of a broken scene")

# ...and given the marked, empty output of a filter that failed, it says so instead of
# returning an empty solution.
try:
    relight.solve(chain[0].GetOutput(), 1.0, 0.5)
    raised = ""
except RuntimeError as error:
    raised = str(error)
print(f"{'ok  ' if 'filter that failed' in raised else 'FAIL'} relight.solve of a failed filter's output: {raised!r}")
if "filter that failed" not in raised:
    failures.append("relight.solve of a failed filter's output")

# A writer below the failed filter does not run; vtkWriter.Write() would then return 1 with
# no file. Ours return 0 and say why, and again on a second Write of the same pipeline
# (which reaches the writer, its input marked as failed).
for writer, name in ((relight.vtkRadiosityGLTFWriter(), "broken.glb"), (relight.vtkRadiosityEXRWriter(), "broken.exr")):
    path = os.path.join(tempfile.mkdtemp(), name)
    writer.SetInputConnection(chain[-1].GetOutputPort())
    writer.SetFileName(path)
    said = []
    for attempt in range(2):
        catcher = ErrorCatcher(writer)
        written = writer.Write()
        said.append((written, catcher.first_error()))
    good = all(w == 0 and "upstream" in text for w, text in said) and not os.path.exists(path)
    print(f"{'ok  ' if good else 'FAIL'} {name} below a failed filter, written twice: {said}, "
          f"file {os.path.exists(path)}")
    if not good:
        failures.append(f"{name} below a failed filter")

# ElementSize above PatchSize: elements are patch-sized, said so, and reported as they are
# (MesherElementSize said 1.0 while 0.1 m elements made a 100 times slower solve).
sizes = relight.vtkRadiosityMesher()
sizes.SetInputData(scene())
sizes.SetPatchSize(0.1)
sizes.SetElementSize(1.0)
catcher = ErrorCatcher(sizes)
sizes.Update()
used = sizes.GetOutput().GetFieldData().GetArray("MesherElementSize").GetValue(0)
said = any("larger than PatchSize 0.1" in w for w in catcher.warnings)
print(f"{'ok  ' if said and used == 0.1 else 'FAIL'} ElementSize 1.0 over PatchSize 0.1: warned {said}, MesherElementSize {used}")
if not (said and used == 0.1):
    failures.append("ElementSize over PatchSize")

if failures:
    print(f"{len(failures)} check(s) failed")
    sys.exit(1)
print("TestBadInput: all checks passed")
