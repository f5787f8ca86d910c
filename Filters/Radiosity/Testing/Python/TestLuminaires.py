"""Luminaires from real manufacturers' files through `import relight`: the closed room's
mean illuminance in closed form (CIE 171:2006's 4 m cube, 10,000 lm: 208.33 lx at a
reflectance of 0.5), a luminaire beside a lamp cell as a light of its own that the relight
filter dims, and one clear error for each way a luminaire can be wrong."""

import os
import warnings

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

import relight
from testlib import check, finish

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "..", "Data")
LDT = os.path.join(DATA, "Photometry", "erco_sym2.ldt")
IES = os.path.join(DATA, "Photometry", "ael_asa15m_lm63_2002.ies")


def cube(size, rho):
    """A closed cube [0, size]^3 facing inwards, two by two quads a face."""
    s = size
    faces = [[(0, 0, 0), (0, s, 0), (s, s, 0), (s, 0, 0)], [(0, 0, s), (s, 0, s), (s, s, s), (0, s, s)],
             [(0, 0, 0), (s, 0, 0), (s, 0, s), (0, 0, s)], [(0, s, 0), (0, s, s), (s, s, s), (s, s, 0)],
             [(0, 0, 0), (0, 0, s), (0, s, s), (0, s, 0)], [(s, 0, 0), (s, s, 0), (s, s, s), (s, 0, s)]]
    return relight.make_scene([face[::-1] for face in faces], [(rho, rho, rho)] * 6, [-1] * 6)


def mean_illuminance(out, name):
    """Illuminance is irradiance: B / rho on surfaces that do not emit, area-weighted."""
    area = relight.cell_areas(out)
    b = relight.cell_array(out, "Radiosity_" + name)[:, 0]
    rho = relight.cell_array(out, "Reflectance")[:, 0]
    return float((area * b / rho).sum() / area.sum())


# The CIE cube: whatever the luminaire's distribution, a closed room of uniform reflectance
# absorbs all its flux, so the mean illuminance is flux / (S (1 - rho)).
room = cube(4.0, 0.5)
spot = relight.luminaire("Spot", LDT, position=(2, 2, 2), aim=(0, 0, -1), lumens=10000)
out = relight.solve(relight.mark_lights(room, spot), patch_size=1.0, element_size=0.25).GetOutput()
check(relight.light_names(out) == ["Spot"], "the luminaire is the scene's one light, by its name")
mean = mean_illuminance(out, "Spot")
expected = 10000 / (96 * 0.5)
print(f"CIE 171 cube, rho 0.5: mean illuminance {mean:.2f} lx, closed form {expected:.2f} lx "
      f"({100 * (mean / expected - 1):+.3f} %)")
# The element solution alone is within 0.02 %; the final gather's sweep (16 rays an
# element) scatters it: -0.49 % at 0.25 m elements, +0.07 % at 0.125 m, -0.19 % at 0.5 m.
check(abs(mean / expected - 1) < 1e-2, "the cube's mean illuminance is flux / (S (1 - rho)) within 1 %")
area = relight.cell_areas(out)
lux_cells = relight.cell_array(out, "Illuminance_Spot")[:, 0]
lux_mean = float((area * lux_cells).sum() / area.sum())
check(abs(lux_mean / expected - 1) < 1e-2 and relight.point_array(out, "Illuminance_Spot").shape[1] == 3,
      f"the solver's Illuminance arrays give it directly: {lux_mean:.2f} lx")

# A luminaire beside a lamp cell: two lights, each its own solution; the relight filter
# weighs the luminaire like any light (its dimming is its intensity).
lamp = relight.area_light("Panel", centre=(1, 1, 3.99), normal=(0, 0, -1), size=0.5, intensity=50)
street = relight.luminaire("Street", IES, position=(3, 3, 3.5), aim=(0, 0, -1), rotation=30, color=(1, 0.9, 0.7))
both = relight.solve(relight.mark_lights(room, lamp, street), patch_size=1.0, element_size=0.25)
names = relight.light_names(both.GetOutput())
check(names == ["Panel", "Street"], f"the cell light first, then the luminaire ({names})")
colors = vtk_to_numpy(both.GetOutput().GetFieldData().GetArray("LightDefaultColors"))
check(np.allclose(colors[1], (1, 0.9, 0.7)), "the luminaire's color is its default relight color")
rl = relight.vtkRadiosityRelight()
rl.SetInputConnection(both.GetOutputPort())
rl.SetLightColor(0, 1, 1, 1)
rl.SetLightColor(1, 1, 1, 1)
rl.SetLightIntensity(0, 1.0)
rl.SetLightIntensity(1, 0.25)
rl.Update()
relit = relight.point_array(rl.GetOutput(), "Radiosity")
panel = relight.point_array(both.GetOutput(), "Radiosity_Panel")
lum = relight.point_array(both.GetOutput(), "Radiosity_Street")
check(np.allclose(relit, panel + 0.25 * lum, rtol=1e-5, atol=1e-6), "dimmed to 25 %, the luminaire adds a quarter of its solution")

# The mesher grades the surfaces a luminaire lights up close as it does a lamp's, and its
# estimate counts them.
near_wall = relight.mark_lights(cube(4.0, 0.5), relight.luminaire("Wash", kind="point", position=(0.3, 2, 2)))
flat = relight.solve(near_wall, patch_size=1.0, element_size=0.25, lamp_grading=0).GetOutput().GetNumberOfCells()
graded_solver = relight.solve(near_wall, patch_size=1.0, element_size=0.25)
graded = graded_solver.GetOutput().GetNumberOfCells()
estimate = graded_solver.GetInputAlgorithm().EstimateElements(1.0, 0.25)
check(graded > flat and estimate == graded, f"finer elements by the luminaire: {flat} -> {graded} (estimated {estimate:.0f})")

# Light scenes: groups of lights by name pattern, dimmed together, switched by name and
# blended over time by the schedule, with no new solve.
scenes = os.path.join(os.environ.get("TMPDIR", "/tmp"), "relight_scenes.csv")
with open(scenes, "w") as f:
    f.write("# scene, lights, dimming %, r, g, b, on\nEvening, Str*, 25, , , , on\nEvening, Panel, 100, , , , off\n"
            "Work, *, 100, 1, 1, 1, on\n")
scened = relight.vtkRadiosityRelight()
scened.SetInputConnection(both.GetOutputPort())
scened.SetLightScenesFileName(scenes)
scened.SetLightScene("Evening")
scened.Update()
evening = relight.point_array(scened.GetOutput(), "Radiosity")
check(np.allclose(evening, 0.25 * lum * np.array([1, 0.9, 0.7]), rtol=1e-5, atol=1e-6),
      "Evening: the street light at 25 % in its own color, the panel off")
lights = scened.GetLights()
check([lights.GetLightSceneName(i) for i in range(lights.GetNumberOfLightScenes())] == ["Evening", "Work"],
      "the file's scenes by name")
scened.SetLightScene("")
scened.AddScheduleRow(0.0, "scene:Evening", 1, 1, 1, 1, "on")
scened.AddScheduleRow(10.0, "scene:Work", 1, 1, 1, 1, "on")
scened.UpdateTimeStep(5.0)
halfway = relight.point_array(scened.GetOutput(), "Radiosity")
# Halfway from Evening to Work: the street light's color and dimming halfway each (color
# (1, 0.95, 0.85), 62.5 %); the panel held off from the keyframe before, as on/off is.
check(np.allclose(halfway, 0.625 * np.array([1, 0.95, 0.85]) * lum, rtol=1e-5, atol=1e-6),
      "the schedule blends Evening into Work: halfway at t = 5")
scened.SetLightScene("Party")
catcher = relight.ErrorCatcher(scened)
scened.Update()
check(catcher.failed() and "no light scene is called 'Party' (there are Evening, Work)" in catcher.first_error(),
      f"an unknown scene is said: {catcher.first_error()}")

# A work plane: EN 12464-1's grid over the cube (3 x 3 m inside a 0.5 m border: p = 0.2 x
# 5^log10(3) = 0.43 m, so 7 x 7 points at the centres of their cells), 0.8 m up. In a black
# room only the light reaches it: a bulb of 1 W/sr gives cos(theta) / d^2, exactly.
bulb = relight.luminaire("Bulb", kind="point", position=(2, 2, 2))
black = relight.solve(relight.mark_lights(cube(4.0, 0.0), bulb), patch_size=1.0, element_size=0.25)
plane = relight.work_plane(black, height=0.8, up="z")
points = vtk_to_numpy(plane.GetPoints().GetData())
check(plane.GetNumberOfPoints() == 49 and np.allclose(points[:, 2], 0.8) and np.isclose(points[:, 0].min(), 0.5 + 3 / 14),
      f"7 x 7 points at the cells' centres, 0.8 m up ({plane.GetNumberOfPoints()})")
lux = relight.point_array(plane, "Illuminance_Bulb")[:, 0]
d = np.array([2, 2, 2]) - points
r = np.linalg.norm(d, axis=1)
check(np.allclose(lux, d[:, 2] / r**3, rtol=1e-6), "every point takes Lambert's point source, cos / d^2")
check(np.allclose(relight.point_array(plane, "Illuminance"), lux, rtol=1e-6), "the combined value is the one light's")
stats = {n: plane.GetFieldData().GetArray(n).GetValue(0) for n in ("IlluminanceMean", "IlluminanceMinimum", "Uniformity")}
check(np.isclose(stats["IlluminanceMean"], lux.mean(), rtol=1e-6) and np.isclose(stats["Uniformity"], lux.min() / lux.mean(), rtol=1e-6),
      f"mean, minimum and uniformity of the plane: {stats}")
csv = os.path.join(os.environ.get("TMPDIR", "/tmp"), "relight_work_plane.csv")
relight.write_work_plane_csv(plane, csv)
with open(csv) as table:
    lines = table.read().splitlines()
check(lines[4] == "x,y,z,Illuminance,Illuminance_Bulb" and len(lines) == 5 + 49, f"the CSV: {lines[:5]}")
refused_plane = False
try:
    relight.work_plane(black, height=5.0, up="z")
except RuntimeError as error:
    refused_plane = "height of 5 is not inside" in str(error)
check(refused_plane, "a work plane above the ceiling is refused with its reason")

# A luminaire that moves: the relight filter's moving lights take its kind, file and aim
# (point arrays Kind, Parameters, Aim), shot per frame with the patch basis carrying its
# interreflection; where it stands still it is the solve's own luminaire.
still = relight.luminaire("Still", IES, position=(2.2, 1.7, 3.5), rotation=20)
solved = relight.solve(relight.mark_lights(cube(4.0, 0.5), still), patch_size=1.0, element_size=0.25, lamp_grading=0,
                       GatherRays=0, ConvergenceThreshold=1e-5, PatchBasis=True)
mover = relight.vtkRadiosityRelight()
mover.SetInputConnection(0, solved.GetOutputPort())
mover.SetInputData(1, relight.point_lights([still.position], like=still))
mover.SetLightEnabled(0, False)
mover.Update()
moved = relight.cell_array(mover.GetOutput(), "Radiosity")[:, 0].astype(float)
fixed = relight.cell_array(solved.GetOutput(), "Radiosity_Still")[:, 0].astype(float)
moving_error = np.abs(moved - fixed).mean() / fixed.mean()
print(f"the luminaire as a moving light against the solve's: {100 * moving_error:.2f} %")
check(moving_error < 0.03, f"as a moving light it lights the room as the solve's luminaire does ({100 * moving_error:.2f} %)")
broken_mover = relight.vtkRadiosityRelight()
broken_mover.SetInputConnection(0, solved.GetOutputPort())
broken_mover.SetInputData(1, relight.point_lights([still.position], like=relight.luminaire("X", "/nowhere/a.ies")))
catcher = relight.ErrorCatcher(broken_mover)
broken_mover.Update()
check(catcher.failed() and "/nowhere/a.ies" in catcher.first_error(), f"a moving luminaire's missing file is said: {catcher.first_error()}")

kinds = [relight.vtkRadiosityLightMarker.GetLightKindName(i) for i in range(relight.vtkRadiosityLightMarker.GetNumberOfLightKinds())]
check(kinds == ["point", "lambertian", "spot", "goniometric"], f"the kinds of light, from the one registry: {kinds}")

# Each way a luminaire can be wrong: one error that says which and why, no output.
def refused(make, words):
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            make()
    except ValueError as error:
        check(all(w in str(error) for w in words), f"refused with {words}: {error}")
        return
    check(False, f"not refused: {words}")


refused(lambda: relight.luminaire("A", position=(0, 0, 1)), ["give the photometric file"])
refused(lambda: relight.luminaire("A", LDT, aim=(0, 0, 0)), ["aim is zero"])
refused(lambda: relight.luminaire("A", LDT, lumens=-5), ["lumens"])
refused(lambda: relight.mark_lights(room, relight.luminaire("A", "/nowhere/lamp.ies")), ["/nowhere/lamp.ies", "cannot be read"])
refused(lambda: relight.mark_lights(room, relight.luminaire("A", kind="spot", cone=20, fallof=3)),
        ["luminaire 'A'", "does not take fallof"])
refused(lambda: relight.mark_lights(room, relight.luminaire("A", kind="laser")), ["no kind of light is called 'laser'"])
refused(lambda: relight.mark_lights(room, lamp, relight.luminaire("Panel", LDT)), ["'Panel' is taken"])
refused(lambda: relight.mark_lights(room, relight.luminaire("Desk lamp", LDT)), ["letters, digits"])
broken = os.path.join(os.environ.get("TMPDIR", "/tmp"), "relight_truncated.ies")
with open(IES) as source, open(broken, "w") as target:
    target.write(source.read()[:3000])
refused(lambda: relight.mark_lights(room, relight.luminaire("A", broken)), ["relight_truncated.ies:", "the file ends"])

# Field arrays that disagree (a luminaire row cut short by hand): the solver says which.
cut = relight.mark_lights(room, relight.luminaire("A", LDT, position=(2, 2, 2)))
cut.GetFieldData().GetArray("LuminairePlacement").SetNumberOfComponents(7)
solver = relight.vtkLightTaggedRadiosity()
mesher = relight.vtkRadiosityMesher()
mesher.SetInputData(cut)
solver.SetInputConnection(mesher.GetOutputPort())
catcher = relight.ErrorCatcher(solver)
solver.Update()
check(catcher.failed() and "LuminairePlacement" in catcher.first_error() and solver.GetOutput().GetNumberOfCells() == 0,
      f"malformed luminaire arrays are refused, the output empty: {catcher.first_error()[:140]}")
try:
    relight.luminaire("A", LDT, position=(float("nan"), 0, 0))
    check(False, "a NaN position is refused")
except ValueError as error:
    check("position" in str(error), f"a NaN position is refused: {error}")

finish("TestLuminaires")
