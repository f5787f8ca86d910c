"""Relighting on the GPU: vtkRadiosityRelightMapper against the CPU path
(relight filter + DisplayColors) for 3 and 40 lights, light changes without uploads or
pipeline runs, and 64 lights with intensities 1e-4 and 1e4 (no quantisation)."""

import os

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkIntArray, vtkLogger
from vtkmodules.vtkCommonDataModel import vtkPolyData

import relight
from relight import FrameRenderer, read_polydata
from testlib import check, finish

vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
DATA = os.path.join(os.environ.get("RELIGHT_ROOT", "."), "Data")
ROOM_CAMERA = ((2.0, 1.5, 0.05), (2.0, 0.9, 4.0), (0.0, 1.0, 0.0), 80.0)
SIZE = (200, 150)


def pixels(image):
    return numpy_support.vtk_to_numpy(image.GetPointData().GetScalars()).astype(float)


def both_paths(solved, settings, camera, exposure):
    """The CPU and GPU pictures for `settings` = {index: (color, intensity, enabled)}."""
    filter_ = relight.vtkRadiosityRelight()
    filter_.SetInputData(solved)
    mapper = relight.vtkRadiosityRelightMapper()
    mapper.SetInputData(solved)
    mapper.SetLights(filter_.GetLights())  # one set of settings, read by both
    for i, (color, intensity, enabled) in settings.items():
        filter_.SetLightColor(i, *color)
        filter_.SetLightIntensity(i, intensity)
        filter_.SetLightEnabled(i, enabled)
    for target in (filter_, mapper):
        target.SetExposure(exposure)
    filter_.Update()
    cpu = FrameRenderer(camera, SIZE)
    gpu = FrameRenderer(camera, SIZE, mapper)
    return pixels(cpu.render(filter_.GetOutput())), pixels(gpu.render()), mapper, gpu


# --- 3 lights: the same picture, and a light change is a frame with no upload ------------------
solved = relight.solve(read_polydata(os.path.join(DATA, "paper_3lights.vtp")), 1.5, 0.375,
                       ConvergenceThreshold=1e-3).GetOutput()
settings = {0: ((1.0, 0.8, 0.6), 3.0, True), 1: ((0.3, 0.6, 1.0), 0.5, True), 2: ((1.0, 0.3, 0.1), 2.0, True)}
cpu, gpu, mapper, view = both_paths(solved, settings, ROOM_CAMERA, 2.0)
difference = np.abs(cpu - gpu)
check(difference.mean() < 1.0 and not mapper.GetLastProblem(),
      f"3 lights: GPU = CPU within {difference.mean():.3f} / 255 mean (max {difference.max():.0f})")
time_before = mapper.GetMTime()
mapper.GetLights().SetLightEnabled(0, False)
changed = pixels(view.render())
check(mapper.GetUploadCount() == 1 and mapper.GetMTime() == time_before and np.abs(changed - gpu).mean() > 2,
      f"a light change re-renders without upload or modification (uploads {mapper.GetUploadCount()}, "
      f"mean change {np.abs(changed - gpu).mean():.1f})")
mapper.GetLights().SetLightIntensity(0, -1.0)
mapper.GetLights().SetLightEnabled(0, True)
view.render()
check("light 'WarmWhite' has intensity -1" in mapper.GetLastProblem(), f"a bad setting is reported: {mapper.GetLastProblem()}")
mapper.GetLights().SetLightIntensity(0, settings[0][1])  # corrected: drawn again, the problem gone
mapper.GetLights().SetLightEnabled(0, settings[0][2])
mended = pixels(view.render())
check(not mapper.GetLastProblem() and np.abs(mended - gpu).mean() < 1.0,
      f"a corrected setting clears the problem and draws as before ({mapper.GetLastProblem()!r}, "
      f"mean difference {np.abs(mended - gpu).mean():.2f})")

# --- the CPU path: asked for here (a weak OpenGL falls back to it by itself) ----------------------
cpu_mapper = relight.vtkRadiosityRelightMapper()
cpu_mapper.SetInputData(solved)
cpu_mapper.SetUseGPU(False)
for i, (color, intensity, enabled) in settings.items():
    cpu_mapper.GetLights().SetLightColor(i, *color)
    cpu_mapper.GetLights().SetLightIntensity(i, intensity)
    cpu_mapper.GetLights().SetLightEnabled(i, enabled)
cpu_mapper.SetExposure(2.0)
catcher = relight.ErrorCatcher(cpu_mapper)
cpu_view = FrameRenderer(ROOM_CAMERA, SIZE, cpu_mapper)
on_cpu = pixels(cpu_view.render())
check(cpu_mapper.GetRelitOnCPU() and np.abs(on_cpu - cpu).mean() < 1.0 and len(catcher.warnings) == 1,
      f"UseGPU off: relit on the CPU, = the filter's picture within {np.abs(on_cpu - cpu).mean():.3f} / 255, "
      f"said once ({len(catcher.warnings)} warning)")
cpu_mapper.GetLights().SetLightEnabled(0, False)
check(np.abs(pixels(cpu_view.render()) - on_cpu).mean() > 2 and len(catcher.warnings) == 1,
      "the CPU path follows a light change too, without saying so again")
# A light index past the lights is said once, not at every frame (it was not said at all).
cpu_mapper.GetLights().SetLightIntensity(9, 2.0)
for _ in range(3):
    cpu_view.render()
said = [w for w in catcher.warnings if "index 9" in w]
check(len(said) == 1, f"a light index past the lights, over 3 frames: said {len(said)} time(s)")
cpu_mapper.GetLights().SetLightEnabled(0, True)

# --- bad input: said as the relight filter says it (the two read their input alike) ---------------
def problem_of(data):
    """The mapper's problem with `data` after a frame, and the relight filter's error."""
    bad = relight.vtkRadiosityRelightMapper()
    bad.SetInputData(data)
    catcher = relight.ErrorCatcher(bad)
    FrameRenderer(ROOM_CAMERA, SIZE, bad).render()
    filter_ = relight.vtkRadiosityRelight()
    filter_.SetInputData(data)
    caught = relight.ErrorCatcher(filter_)
    filter_.Update()
    return bad.GetLastProblem(), " ".join(caught.errors), len(catcher.errors), bad.GetNumberOfLights()


cells_only = vtkPolyData()
cells_only.DeepCopy(solved)
names = relight.light_names(solved)
for name in names:
    cells_only.GetPointData().RemoveArray(f"Radiosity_{name}")
problem, said, errors, lights = problem_of(cells_only)
check("no point arrays 'Radiosity_<light>'" in problem and errors == 1 and lights == 0,
      f"solutions on the cells only: '{problem}' (said {errors} time(s))")
integers = vtkPolyData()
integers.DeepCopy(solved)
whole_numbers = vtkIntArray()
whole_numbers.DeepCopy(solved.GetPointData().GetArray(f"Radiosity_{names[0]}"))
whole_numbers.SetName(f"Radiosity_{names[0]}")
integers.GetPointData().AddArray(whole_numbers)
problem, said, errors, lights = problem_of(integers)
check("solutions must be float or double" in problem and problem in said and lights == 0,
      f"an integer solution array: '{problem}', as the filter says it")
nan = vtkPolyData()
nan.DeepCopy(solved)
nan.GetPointData().GetArray(f"Radiosity_{names[1]}").SetComponent(100, 1, float("nan"))
problem, said, errors, lights = problem_of(nan)
check(f"light '{names[1]}' is not finite at point 100" in problem and errors == 1 and lights == 0,
      f"a NaN in a solution array: '{problem}' (said {errors} time(s) over a frame)")
# A mapper that relit the last input on the CPU draws a bad one black, as the GPU path does.
was_cpu = relight.vtkRadiosityRelightMapper()
was_cpu.SetUseGPU(False)
was_cpu.SetInputData(solved)
relight.ErrorCatcher(was_cpu)
cpu_frame = FrameRenderer(ROOM_CAMERA, SIZE, was_cpu)
cpu_frame.render()
on_cpu_before = was_cpu.GetRelitOnCPU()
was_cpu.SetInputData(nan)
dark = pixels(cpu_frame.render())
check(on_cpu_before and not was_cpu.GetRelitOnCPU() and "not finite" in was_cpu.GetLastProblem() and dark.max() < 40,
      f"after a CPU frame, a NaN input is drawn dark (brightest {dark.max():.0f}) and no longer relit on the CPU")
exposed = relight.vtkRadiosityRelightMapper()
caught = relight.ErrorCatcher(exposed)
exposed.SetExposure(2.0)
exposed.SetExposure(-5.0)
check(exposed.GetExposure() == 2.0 and len(caught.errors) == 1 and "must be finite and not negative" in caught.errors[0],
      f"a negative exposure is refused as the relight filter refuses it, the last one kept: {caught.errors}")
plain = vtkPolyData()
plain.DeepCopy(read_polydata(os.path.join(DATA, "paper_3lights.vtp")))
plain.GetFieldData().RemoveArray("LightNames")
problem, said, errors, lights = problem_of(plain)
check("has no lights" in problem and problem in said, f"a scene not solved: '{problem}', as the filter says it")

# --- a room with 40 lamps (a 5 x 8 grid in the ceiling) and 64 lamps (8 x 8) ----------------------
def lamp_room(columns, rows, size=8.0, height=3.0):
    """A closed room with a grid of small downward ceiling lamps, one light each."""
    s, h = size, height
    walls = [[(0, 0, 0), (s, 0, 0), (s, s, 0), (0, s, 0)], [(0, 0, h), (0, s, h), (s, s, h), (s, 0, h)],
             [(0, 0, 0), (0, 0, h), (s, 0, h), (s, 0, 0)], [(0, s, 0), (s, s, 0), (s, s, h), (0, s, h)],
             [(0, 0, 0), (0, s, 0), (0, s, h), (0, 0, h)], [(s, 0, 0), (s, 0, h), (s, s, h), (s, s, 0)]]
    lamps = []
    for r in range(rows):
        for c in range(columns):
            x, y, half = (c + 0.5) * s / columns, (r + 0.5) * s / rows, 0.1
            lamps.append([(x - half, y - half, h - 0.01), (x - half, y + half, h - 0.01),
                          (x + half, y + half, h - 0.01), (x + half, y - half, h - 0.01)])
    k = len(lamps)
    scene = relight.make_scene(walls + lamps, [(0.5, 0.5, 0.5)] * 6 + [(0.8, 0.8, 0.8)] * k,
                               [-1] * 6 + list(range(k)), [f"L{i}" for i in range(k)])
    return relight.solve(scene, 2.0, 0.25, ConvergenceThreshold=1e-3).GetOutput()


DOWN = ((4.0, 4.0, 2.9), (4.0, 4.0, 0.0), (0.0, 1.0, 0.0), 110.0)  # under the lamps, looking at the floor
forty = lamp_room(8, 5)
rng = np.random.default_rng(7)
settings = {i: (tuple(rng.uniform(0.2, 1.0, 3)), float(rng.uniform(0.5, 4.0)), bool(rng.random() > 0.2)) for i in range(40)}
cpu, gpu, mapper, _ = both_paths(forty, settings, DOWN, 3.0)
difference = np.abs(cpu - gpu)
check(mapper.GetNumberOfLights() == 40 and difference.mean() < 1.0,
      f"40 lights: GPU = CPU within {difference.mean():.3f} / 255 mean (max {difference.max():.0f})")

# Two open-topped boxes side by side, 32 lamps hanging in each: no light passes between
# them, so the 1e-4 lamp in one box is all that lights it while the 1e4 one floods the other.
def twin_boxes():
    polygons, ids = [], []
    for box, x0 in enumerate((0.0, 4.5)):
        x1, s, h = x0 + 4.0, 4.0, 2.0
        polygons += [[(x0, 0, 0), (x1, 0, 0), (x1, s, 0), (x0, s, 0)], [(x0, 0, 0), (x0, 0, h), (x1, 0, h), (x1, 0, 0)],
                     [(x0, s, 0), (x1, s, 0), (x1, s, h), (x0, s, h)], [(x0, 0, 0), (x0, s, 0), (x0, s, h), (x0, 0, h)],
                     [(x1, 0, 0), (x1, 0, h), (x1, s, h), (x1, s, 0)]]
        ids += [-1] * 5
        for r in range(8):
            for c in range(4):
                x, y, half = x0 + (c + 0.5), (r + 0.5) * 0.5, 0.08
                polygons.append([(x - half, y - half, 1.5), (x - half, y + half, 1.5),
                                 (x + half, y + half, 1.5), (x + half, y - half, 1.5)])
                ids.append(32 * box + 4 * r + c)
    scene = relight.make_scene(polygons, [(0.5, 0.5, 0.5)] * len(polygons), ids, [f"L{i}" for i in range(64)])
    return relight.solve(scene, 2.0, 0.25, ConvergenceThreshold=1e-3).GetOutput()


sixty_four = twin_boxes()
weak, strong = 63, 0
only = {i: ((1.0, 1.0, 1.0), 0.0, False) for i in range(64)}
only[strong] = ((1.0, 1.0, 1.0), 1e4, True)
only[weak] = ((1.0, 1.0, 1.0), 1e-4, True)
weak_floor = numpy_support.vtk_to_numpy(sixty_four.GetPointData().GetArray("Radiosity_L63"))[:, 0]
exposure = 0.5 / (1e-4 * np.percentile(weak_floor[weak_floor > 0], 90))  # the weak box's floor mid-grey
ABOVE = ((4.25, 2.0, 9.0), (4.25, 2.0, 0.0), (0.0, 1.0, 0.0), 60.0)
cpu, gpu, mapper, view = both_paths(sixty_four, only, ABOVE, exposure)
mapper.GetLights().SetLightEnabled(weak, False)
without = pixels(view.render())
change = np.abs(gpu - without).sum(axis=1)
check(mapper.GetNumberOfLights() == 64 and np.abs(cpu - gpu).mean() < 1.0,
      f"64 lights, 1e-4 next to 1e4: GPU = CPU within {np.abs(cpu - gpu).mean():.3f} / 255 "
      f"(strong box saturated: {100 * (gpu.min(axis=1) == 255).mean():.0f} % of the picture white)")
check((change > 30).mean() > 0.05, f"the 1e-4 light still changes {100 * (change > 30).mean():.1f} % of the picture "
      f"(its box) when switched off")
finish("TestRelightMapper")
