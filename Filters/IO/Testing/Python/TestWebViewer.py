"""The browser viewer: the page relight.export_viewer writes, shown by Debian's
headless Chromium, matches VTK's render of the same light settings, and a slider moved
(through the page's URL, which sets the slider and fires its input event as a drag does)
changes the picture where that light dominates, and only there. With 20 lights (more than
WebGL's 16 vertex attributes), every light still counts: the page matches VTK, and
switching off the twentieth changes the page as it changes VTK's picture."""

import os
import shutil
import subprocess
import tempfile

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkLogger
from vtkmodules.vtkIOImage import vtkPNGReader

import relight
from relight import light_names, point_array, read_polydata
from testlib import check, finish

vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
DATA = os.path.join(os.environ.get("RELIGHT_ROOT", "."), "Data")
CAMERA = ((2.0, 1.5, 0.05), (2.0, 0.9, 4.0), (0.0, 1.0, 0.0), 80.0)
SIZE = (240, 180)
BOOST = 4.0  # the Amber slider moved to four times its default
folder = tempfile.mkdtemp()


def read_png(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    pixels = numpy_support.vtk_to_numpy(image.GetPointData().GetScalars())[:, :3]
    return pixels.reshape(height, width, 3)[::-1].astype(float)  # VTK's rows run bottom up


def browser_shot(page, query, name):
    """A screenshot of the page by headless Chromium (software WebGL, no network)."""
    shot = os.path.join(folder, name)
    subprocess.run([shutil.which("chromium"), "--headless", "--no-sandbox", "--disable-gpu",
                    "--enable-unsafe-swiftshader", "--use-angle=swiftshader", "--disable-background-networking",
                    "--disable-component-update", "--disable-sync", "--no-first-run",
                    f"--user-data-dir={tempfile.mkdtemp()}", f"--window-size={SIZE[0]},{SIZE[1]}",
                    "--virtual-time-budget=10000", f"--screenshot={shot}", f"file://{page}?{query}"],
                   capture_output=True, timeout=180)
    return read_png(shot) if os.path.exists(shot) else None


def vtk_shot(relit, name):
    path = os.path.join(folder, name)
    relit.Update()
    relight.render_png(relit.GetOutput(), path, CAMERA, SIZE)
    return read_png(path)


check(shutil.which("chromium") is not None, "Debian's chromium is installed (./relight test installs it)")
solver = relight.solve(read_polydata(os.path.join(DATA, "paper_3lights.vtp")), 1.5, 0.375, ConvergenceThreshold=1e-3)
relit = relight.vtkRadiosityRelight()
relit.SetInputConnection(solver.GetOutputPort())
relit.Update()
b = point_array(relit.GetOutput(), "Radiosity").max(axis=1)
exposure = 0.8 / np.percentile(b[b < 0.5 * b.max()], 99)  # the walls bright, the lamps clipped
relit.SetExposure(exposure)
relit.Update()
names = light_names(relit.GetOutput())
amber = names.index("Amber")
page = relight.export_viewer(relit.GetOutput(), os.path.join(folder, "viewer"), CAMERA, SIZE, exposure)

before = browser_shot(page, "controls=0", "before.png")
reference = vtk_shot(relit, "vtk_before.png")
defaults = numpy_support.vtk_to_numpy(relit.GetOutput().GetFieldData().GetArray("LightDefaultColors"))
# The default intensity, in the page's slider and the filter alike: the default color's
# largest channel (its hue is the rest).
peak = defaults[amber].max()
after = browser_shot(page, f"controls=0&intensity.Amber={BOOST * peak:.9g}", "after.png")
relit.SetLightIntensity(amber, BOOST * peak)
boosted = vtk_shot(relit, "vtk_after.png")
relit.SetLightIntensity(amber, peak)
for i in range(len(names)):  # Amber alone, then the others alone: where does it dominate?
    relit.SetLightEnabled(i, i == amber)
alone = vtk_shot(relit, "vtk_amber.png")
for i in range(len(names)):
    relit.SetLightEnabled(i, i != amber)
others = vtk_shot(relit, "vtk_others.png")

# A page exported from the filter as set (Amber boosted, WarmWhite off) starts from it.
relit.SetLightIntensity(amber, BOOST * peak)
warm = names.index("WarmWhite")
relit.SetLightEnabled(warm, False)
relit.Update()
set_page = relight.export_viewer(relit.GetOutput(), os.path.join(folder, "set"), CAMERA, SIZE, exposure)
as_set = browser_shot(set_page, "controls=0", "as_set.png")
vtk_as_set = vtk_shot(relit, "vtk_as_set.png")
relit.SetLightIntensity(amber, peak)
relit.SetLightEnabled(warm, True)
if check(as_set is not None, "Chromium rendered the page exported from the filter as set"):
    error = np.abs(as_set - vtk_as_set)
    check(error.mean() < 3.0 and np.percentile(error, 95) < 12 and np.abs(as_set - before).mean() > 5,
          f"the page starts from the filter's settings (Amber x{BOOST:g}, WarmWhite off): it matches VTK's render "
          f"(mean {error.mean():.2f}), not the defaults (mean change {np.abs(as_set - before).mean():.1f})")

# Light scenes: the page offers the file's scenes, resolved as the relight filter resolves
# them; ?scene=Evening picks one as the chooser does.
scenes_file = os.path.join(folder, "scenes.csv")
with open(scenes_file, "w") as f:
    f.write("# scene, lights, dimming %, r, g, b, on\nEvening, Amber, 300, , , , on\nEvening, Warm*, 100, , , , off\n"
            "Work, *, 100, 1, 1, 1, on\n")
scene_page = relight.export_viewer(relit.GetOutput(), os.path.join(folder, "scenes"), CAMERA, SIZE, exposure,
                                   scenes=scenes_file)
evening = browser_shot(scene_page, "controls=0&scene=Evening", "evening.png")
scened = relight.vtkRadiosityRelight()  # no settings by name over the scene
scened.SetInputConnection(solver.GetOutputPort())
scened.SetExposure(exposure)
scened.SetLightScenesFileName(scenes_file)
scened.SetLightScene("Evening")
vtk_evening = vtk_shot(scened, "vtk_evening.png")
if check(evening is not None, "Chromium rendered the page in its Evening light scene"):
    error = np.abs(evening - vtk_evening)
    check(error.mean() < 3.0 and np.percentile(error, 95) < 12 and np.abs(evening - before).mean() > 5,
          f"?scene=Evening (Amber at 300 %, WarmWhite off) matches the relight filter in that scene (mean "
          f"{error.mean():.2f}), not the defaults (mean change {np.abs(evening - before).mean():.1f})")
try:
    relight.export_viewer(relit.GetOutput(), os.path.join(folder, "bad"), scenes=os.path.join(folder, "none.csv"))
    check(False, "a missing light-scenes file is refused")
except ValueError as error:
    check("none.csv" in str(error), f"a missing light-scenes file is refused naming it ({error})")

if check(before is not None and after is not None, "Chromium rendered the page twice"):
    for label, browser, vtk in (("default settings", before, reference), (f"Amber x{BOOST:g}", after, boosted)):
        error = np.abs(browser - vtk)
        check(error.mean() < 3.0 and np.percentile(error, 95) < 12,
              f"{label}: the browser matches VTK's render (mean {error.mean():.2f}, 95th percentile "
              f"{np.percentile(error, 95):.1f} of 255; edges rasterise differently)")
    # Amber's share of each pixel (in VTK's pictures of it alone and of the others alone).
    share = alone.sum(axis=2) / np.maximum(alone.sum(axis=2) + others.sum(axis=2), 1)
    dominant, weak = share > 0.5, share < 0.3
    change = np.abs(after - before).sum(axis=2)
    check(dominant.mean() > 0.05 and weak.mean() > 0.05 and change[dominant].mean() > 2 * change[weak].mean(),
          f"moving Amber's slider changes the picture most where Amber dominates: mean change "
          f"{change[dominant].mean():.0f} where its share is over half ({dominant.mean():.0%} of the picture), "
          f"{change[weak].mean():.0f} where under 30 % ({weak.mean():.0%})")

# --- 20 lights: the solutions travel in a texture, so none is left out ---------------------------
marker = relight.vtkRadiosityLightMarker()
marker.SetInputData(read_polydata(os.path.join(DATA, "paper_3lights.vtp")))
for n in range(17):  # 17 small lamps under the ceiling, in a grid, in turning colors
    x, z = 0.6 + 0.7 * (n % 5), 0.6 + 0.9 * (n // 5)
    marker.AddAreaLight(f"Lamp{n + 4}", 0, x, 2.45, z, 0, -1, 0, 0.15, 0.15, 1 + n % 3, 1 + (n + 1) % 3, 1 + (n + 2) % 3)
marker.Update()
solver20 = relight.solve(marker.GetOutput(), 1.5, 0.375, ConvergenceThreshold=1e-3)  # kept: the port does not hold it
many = relight.vtkRadiosityRelight()
many.SetInputConnection(solver20.GetOutputPort())
many.SetExposure(exposure)
many.Update()
lamps = light_names(many.GetOutput())
page = relight.export_viewer(many.GetOutput(), os.path.join(folder, "viewer20"), CAMERA, SIZE, exposure)
last = lamps[-1]
browser = [browser_shot(page, query, f"many{i}.png") for i, query in enumerate(("controls=0", f"controls=0&enabled.{last}=0"))]
vtk = [vtk_shot(many, "vtk_many.png")]
many.SetLightEnabled(len(lamps) - 1, False)
vtk.append(vtk_shot(many, "vtk_many_off.png"))
if check(len(lamps) == 20 and all(b is not None for b in browser), f"Chromium rendered the {len(lamps)}-light page twice"):
    error = np.abs(browser[0] - vtk[0])
    check(error.mean() < 3.0, f"20 lights: the browser matches VTK's render (mean {error.mean():.2f} of 255)")
    ours, theirs = (np.abs(pair[1] - pair[0]).sum(axis=2) for pair in (browser, vtk))
    changed = theirs > 6
    check(changed.mean() > 0.01 and np.abs(ours - theirs).mean() < 0.25 * theirs[changed].mean(),
          f"switching off {last}, the twentieth light, changes {changed.mean():.0%} of VTK's picture by "
          f"{theirs[changed].mean():.0f} there, and the page alike (mean difference of the changes "
          f"{np.abs(ours - theirs).mean():.1f})")
finish("TestWebViewer")
