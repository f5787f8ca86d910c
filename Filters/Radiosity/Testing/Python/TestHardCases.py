"""Hard cases end to end (mesher -> solver -> relight), each against an exact or reference
expectation. The table in Testing/README.md lists them with the core ones."""

import os

import numpy as np
from vtkmodules.vtkCommonCore import vtkLogger

import relight
from testlib import check, finish
from relight import ErrorCatcher, cell_areas, cell_array, cell_centroids, make_scene, point_array, read_polydata

vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
DATA = os.path.join(os.environ.get("RELIGHT_ROOT", "."), "Data")


def pipeline(scene, patch, element, **solver_settings):
    """Mesher and solver output; failures raise with the filters' message."""
    settings = dict(ConvergenceThreshold=1e-6, MaximumShots=100000)
    settings.update(solver_settings)
    solver = relight.solve(scene, patch, element, **settings)
    return solver.GetInputAlgorithm().GetOutput(), solver.GetOutput()


GREY = (0.5, 0.5, 0.5)
# A lamp 1 m above the origin region, facing down.
LAMP = [(0.4, 0.4, 1.0), (0.4, 0.6, 1.0), (0.6, 0.6, 1.0), (0.6, 0.4, 1.0)]

# --- non-convex polygon: ear-clipped, not fanned ----------------------------------------------
ell = [(0, 0, 0), (2, 0, 0), (2, 1, 0), (1, 1, 0), (1, 2, 0), (0, 2, 0)]
meshed, solved = pipeline(make_scene([LAMP, ell], [GREY, GREY], [0, -1]), 0.5, 0.25)
floor = cell_array(meshed, "LightId") == -1
check(abs(cell_areas(meshed)[floor].sum() - 3.0) < 1e-9, "L-shaped floor keeps its area 3")
c = cell_centroids(meshed)[floor]
check(bool(np.all((c[:, 0] < 1 + 1e-9) | (c[:, 1] < 1 + 1e-9))), "no element outside the L")
check(np.isfinite(cell_array(solved, "Radiosity_Light0")).all(), "L-shaped floor solves finitely")

# --- non-planar quad: meshed into near-planar elements, finite, close to its triangulation ----
warped = [(0, 0, 0), (1, 0, 0.05), (1, 1, 0), (0, 1, 0.05)]
_, as_quad = pipeline(make_scene([LAMP, warped], [GREY, GREY], [0, -1]), 0.25, 0.125)
_, as_tris = pipeline(make_scene([LAMP, warped[:3], [warped[0], warped[2], warped[3]]], [GREY] * 3, [0, -1, -1]),
                      0.25, 0.125)
mean_quad = cell_array(as_quad, "Radiosity_Light0")[cell_array(as_quad, "LightId") == -1].mean()
mean_tris = cell_array(as_tris, "Radiosity_Light0")[cell_array(as_tris, "LightId") == -1].mean()
check(abs(mean_quad - mean_tris) < 0.03 * mean_tris, f"non-planar quad ~ its triangles ({mean_quad:.5f} vs {mean_tris:.5f})")

# --- T-junction: one floor quad next to two half-size ones, same material ---------------------
single = [(0, 0, 0), (2, 0, 0), (2, 1, 0), (0, 1, 0)]
t_parts = [[(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)],
           [(1, 0, 0), (2, 0, 0), (2, 0.5, 0), (1, 0.5, 0)],
           [(1, 0.5, 0), (2, 0.5, 0), (2, 1, 0), (1, 1, 0)]]
# The element solution's power (GatherRays 0): the gather's is an estimate from rays.
_, whole = pipeline(make_scene([LAMP, single], [GREY, GREY], [0, -1]), 0.5, 0.25, GatherRays=0)
_, pieces = pipeline(make_scene([LAMP] + t_parts, [GREY] * 4, [0, -1, -1, -1]), 0.5, 0.25, GatherRays=0)
def floor_power(out):
    return float((cell_array(out, "Radiosity_Light0")[:, 0] * cell_areas(out))[cell_array(out, "LightId") == -1].sum())
check(abs(floor_power(whole) - floor_power(pieces)) < 1e-3 * floor_power(whole),
      "T-junctions change nothing (floor power equal to the single quad's)")

# --- light leak at unwelded seams, through the mesher --------------------------------------------
# A closed unit box of six separate quads (no shared points), a lamp outside facing it.
box = [
    [(0, 0, 0), (0, 1, 0), (1, 1, 0), (1, 0, 0)], [(0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)],
    [(0, 0, 0), (1, 0, 0), (1, 0, 1), (0, 0, 1)], [(0, 1, 0), (0, 1, 1), (1, 1, 1), (1, 1, 0)],
    [(0, 0, 0), (0, 0, 1), (0, 1, 1), (0, 1, 0)], [(1, 0, 0), (1, 1, 0), (1, 1, 1), (1, 0, 1)],
]
def facing(quad, towards):
    a, b, c = (np.array(p, dtype=float) for p in quad[:3])
    normal = np.cross(b - a, c - b)
    return quad if normal.dot(np.array(towards) - a) > 0 else quad[::-1]


box = [facing(q, (0.5, 0.5, 0.5)) for q in box]  # walls face into the box
outside_lamp = facing([(1.002, -0.5, -0.5), (1.002, -0.5, 1.5), (1.002, 1.5, 1.5), (1.002, 1.5, -0.5)],
                      (0.5, 0.5, 0.5))  # shines at the box's x = 1 wall and its seams
_, leak = pipeline(make_scene(box + [outside_lamp], [GREY] * 6 + [GREY], [-1] * 6 + [0]), 0.25, 0.125,
                   FormFactorSamples=64)
inside = cell_array(leak, "LightId") == -1
check(float(cell_array(leak, "Radiosity_Light0")[inside].max()) == 0.0, "no light leaks through unwelded seams")

# --- scale invariance, whole pipeline (Cornell box in metres and kilometres) --------------------
cornell = read_polydata(os.path.join(DATA, "cornell_box.vtp"))
results = []
for scale in (1e-3, 1.0, 1e3):
    from vtkmodules.vtkFiltersGeneral import vtkTransformFilter
    from vtkmodules.vtkCommonTransforms import vtkTransform
    transform = vtkTransform()
    transform.Scale(scale, scale, scale)
    scaled = vtkTransformFilter()
    scaled.SetTransform(transform)
    scaled.SetInputData(cornell)
    scaled.Update()
    _, out = pipeline(scaled.GetOutput(), 100 * scale, 50 * scale, ConvergenceThreshold=1e-3)
    results.append(cell_array(out, "Radiosity_Ceiling").astype(np.float64))
for scaled_result, scale in ((results[0], 1e-3), (results[2], 1e3)):
    difference = np.abs(scaled_result - results[1]).max() / results[1].max()
    check(difference < 1e-5, f"Cornell box at scale {scale:g} matches mm ({difference:.1e} of the peak)")

# --- emission ratio 1e6 : 1 in relight ------------------------------------------------------------
_, two = pipeline(read_polydata(os.path.join(DATA, "paper_3lights.vtp")), 1.5, 0.375, ConvergenceThreshold=1e-4)
rl = relight.vtkRadiosityRelight()
rl.SetInputData(two)
for i, intensity in enumerate((1e6, 1.0, 1e-6)):
    rl.SetLightColor(i, 1, 1, 1)
    rl.SetLightIntensity(i, intensity)
rl.Update()
exact = (1e6 * point_array(two, "Radiosity_WarmWhite").astype(np.float64)
         + point_array(two, "Radiosity_CoolWhite") + 1e-6 * point_array(two, "Radiosity_Amber").astype(np.float64))
got = point_array(rl.GetOutput(), "Radiosity")
check(np.isfinite(got).all() and np.allclose(got, exact, rtol=2e-7, atol=0),
      "1e6 : 1 : 1e-6 intensities combine to float precision")

# --- a light reaching nothing, next to one that does -------------------------------------------
away = [(0.4, 0.4, 1.0), (0.6, 0.4, 1.0), (0.6, 0.6, 1.0), (0.4, 0.6, 1.0)]  # faces up, into nothing
_, dark = pipeline(make_scene([LAMP, away, single], [GREY] * 3, [0, 1, -1], light_names=["Down", "Up"]), 0.5, 0.25)
lit_floor = cell_array(dark, "LightId") == -1
check(float(cell_array(dark, "Radiosity_Up")[lit_floor].max()) == 0.0 and
      float(cell_array(dark, "Radiosity_Down")[lit_floor].min()) > 0.0, "a light facing away lights nothing")

# --- the StandardCombined output is not relightable, and says so ------------------------------
_, combined = pipeline(read_polydata(os.path.join(DATA, "paper_1lights.vtp")), 1.5, 0.375,
                       SolutionMode=1, ConvergenceThreshold=1e-2)
bad = relight.vtkRadiosityRelight()
bad.SetInputData(combined)
catcher = ErrorCatcher(bad)
bad.Update()
check(any("one combined solution" in e for e in catcher.errors) and bad.GetOutput().GetNumberOfCells() == 0,
      "relighting a combined solution is refused with a clear message")

finish("TestHardCases")
