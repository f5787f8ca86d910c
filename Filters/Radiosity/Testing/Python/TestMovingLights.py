"""Moving lights (paper 2.4) against closed forms and against a full light-tagged solve.

1. Direct light of an isotropic point light on a floor: rho * I * cos(theta) / r^2 exactly.
2. A small Lambertian moving light placed where a lamp is gives the lamp's full solve,
   within an error that falls as patches get finer (printed as a table).
3. A dynamic object between light and floor casts a direct shadow.
"""

import math
import os
import time

import numpy as np
from vtkmodules.vtkCommonCore import vtkLogger
from vtkmodules.vtkCommonDataModel import vtkPolyData

import relight
from testlib import check, finish
from vtkmodules.util.numpy_support import vtk_to_numpy
from relight import ErrorCatcher, cell_areas, cell_array, cell_centroids, make_scene

vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_WARNING)
lights = relight.point_lights


def solve(scene, patch, element, basis=True, threshold=1e-4):
    return relight.solve(scene, patch, element, ConvergenceThreshold=threshold, PatchBasis=basis)


# --- 1. point light over a floor: the closed form ------------------------------------------
floor = [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0)]
faraway = [(10, 10, 5), (11, 10, 5), (11, 11, 5), (10, 11, 5)]  # a static lamp facing up, away
scene = make_scene([floor, faraway], [(0.5, 0.25, 0.125), (0.5, 0.5, 0.5)], [-1, 0])
solver = solve(scene, 0.5, 0.25)
rl = relight.vtkRadiosityRelight()
rl.SetInputConnection(0, solver.GetOutputPort())
rl.SetInputData(1, lights([(0.7, 1.1, 1.5)], intensity=2.0, color=(1.0, 0.5, 0.25)))
rl.SetLightEnabled(0, False)
rl.Update()
out = rl.GetOutput()
on_floor = cell_array(out, "LightId") == -1
c = cell_centroids(out)[on_floor]
d = np.array([0.7, 1.1, 1.5]) - c
r = np.linalg.norm(d, axis=1)
expected = (np.array([0.5, 0.25, 0.125]) * np.array([1.0, 0.5, 0.25]) * 2.0)[None, :] * (d[:, 2] / r / r**2)[:, None]
got = cell_array(out, "Radiosity")[on_floor]
check(np.allclose(got, expected, rtol=1e-5), "point light: rho * I * cos / r^2 at every floor element")

# --- 3. a dynamic object casts a direct shadow -----------------------------------------------
blocker = make_scene([[(0.5, 0.9, 0.75), (0.9, 0.9, 0.75), (0.9, 1.3, 0.75), (0.5, 1.3, 0.75)]],
                     [(0.5, 0.5, 0.5)], [-1])
rl.SetInputData(2, blocker)
rl.Update()
shadowed = cell_array(rl.GetOutput(), "Radiosity")[on_floor]
below = np.linalg.norm(c[:, :2] - np.array([0.7, 1.1]), axis=1) < 0.15
check(np.all(shadowed[below] == 0) and np.allclose(shadowed[~below & (np.abs(c[:, 0] - 0.7) > 0.8)],
                                                   expected[~below & (np.abs(c[:, 0] - 0.7) > 0.8)], rtol=1e-5),
      "a dynamic object shadows the floor below it and nothing far away")
# Moving the object swaps it in the ray scene (the static scene is kept): the same
# picture as a fresh filter given the moved object.
moved = make_scene([[(1.1, 0.9, 0.75), (1.5, 0.9, 0.75), (1.5, 1.3, 0.75), (1.1, 1.3, 0.75)]], [(0.5, 0.5, 0.5)], [-1])
rl.SetInputData(2, moved)
rl.Update()
fresh = relight.vtkRadiosityRelight()
fresh.SetInputConnection(0, solver.GetOutputPort())
fresh.SetInputData(1, lights([(0.7, 1.1, 1.5)], intensity=2.0, color=(1.0, 0.5, 0.25)))
fresh.SetInputData(2, moved)
fresh.SetLightEnabled(0, False)
fresh.Update()
swapped, rebuilt = (cell_array(f.GetOutput(), "Radiosity")[on_floor] for f in (rl, fresh))
check(np.array_equal(swapped, rebuilt) and not np.array_equal(swapped, shadowed),
      "a moved dynamic object, swapped into the kept ray scene, shades as a fresh filter does")
rl.RemoveAllInputConnections(2)

# --- 4. a time-varying light source drives the animation through the pipeline's time ---------
from vtkmodules.util.vtkAlgorithm import VTKPythonAlgorithmBase  # noqa: E402
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp  # noqa: E402


class LightOnAPath(VTKPythonAlgorithmBase):
    """One point light moving along x over time steps 0..4."""

    def __init__(self):
        super().__init__(nInputPorts=0, nOutputPorts=1, outputType="vtkPolyData")

    def RequestInformation(self, request, inInfo, outInfo):
        info = outInfo.GetInformationObject(0)
        info.Set(sddp.TIME_STEPS(), [0.0, 1.0, 2.0, 3.0, 4.0], 5)
        info.Set(sddp.TIME_RANGE(), [0.0, 4.0], 2)
        return 1

    def RequestData(self, request, inInfo, outInfo):
        info = outInfo.GetInformationObject(0)
        t = info.Get(sddp.UPDATE_TIME_STEP()) if info.Has(sddp.UPDATE_TIME_STEP()) else 0.0
        out = vtkPolyData.GetData(outInfo)
        out.ShallowCopy(lights([(0.2 + 0.4 * t, 1.0, 1.5)]))
        return 1


path = LightOnAPath()
animated = relight.vtkRadiosityRelight()
animated.SetInputConnection(0, solver.GetOutputPort())
animated.SetInputConnection(1, path.GetOutputPort())
animated.SetLightEnabled(0, False)
animated.UpdateInformation()
steps = animated.GetOutputInformation(0).Get(sddp.TIME_STEPS())
check(steps is not None and list(steps) == [0.0, 1.0, 2.0, 3.0, 4.0], f"the path's time steps reach the output: {steps}")
brightest = []
for t in (0.0, 4.0):
    animated.UpdateTimeStep(t)
    values = cell_array(animated.GetOutput(), "Radiosity")[:, 0]
    brightest.append(float(c[np.argmax(values[on_floor]), 0]))
check(brightest[0] < 0.5 and brightest[1] > 1.5, f"the lit spot follows the light along x: {brightest}")

# --- 2. moving light vs full solve, error against patch size ----------------------------------
# A lamp close to a reflective wall, so its direct light varies a lot within a patch: the
# basis spreads each patch's reflected light evenly, which is what finer patches improve.
# The reference is the full light-tagged solve with an emitter at the light's place, at the
# finest patch size, on the same elements.
W, H, D = 4.0, 2.0, 4.0  # multiples of every patch size below: one element grid for all
room = [
    [(0, 0, 0), (0, 0, D), (W, 0, D), (W, 0, 0)], [(0, H, 0), (W, H, 0), (W, H, D), (0, H, D)],
    [(0, 0, 0), (W, 0, 0), (W, H, 0), (0, H, 0)], [(0, 0, D), (0, H, D), (W, H, D), (W, 0, D)],
    [(0, 0, 0), (0, H, 0), (0, H, D), (0, 0, D)], [(W, 0, 0), (W, 0, D), (W, H, D), (W, H, 0)],
]
colors = [(0.6, 0.6, 0.6), (0.8, 0.8, 0.8), (0.8, 0.3, 0.3), (0.8, 0.8, 0.8), (0.3, 0.4, 0.8), (0.8, 0.8, 0.8)]
centre, half = (0.25, 1.2, 1.6), 0.05  # 0.25 m from the x = 0 wall, facing it
lamp = [(centre[0], centre[1] - half, centre[2] - half), (centre[0], centre[1] - half, centre[2] + half),
        (centre[0], centre[1] + half, centre[2] + half), (centre[0], centre[1] + half, centre[2] - half)]  # faces -x
scene = make_scene(room + [lamp], colors + [(0.0, 0.0, 0.0)], [-1] * 6 + [0], light_names=["Lamp"])
def tagged(patch, basis):
    # Converged: the default shot cap would stop the fine meshes early. The basis carries the
    # element solution's interreflection, so that is what it is held against (GatherRays 0),
    # on one element grid for every patch size (no grading by the lamp, which is to move).
    return relight.solve(scene, patch, ELEMENT, lamp_grading=0, ConvergenceThreshold=1e-5, MaximumShots=1000000,
                         PatchBasis=basis, SeparateDirect=True, GatherRays=0)


ELEMENT = 0.25
FINEST = 0.5
full = tagged(FINEST, False).GetOutput()
reference = cell_array(full, "Radiosity_Lamp").astype(np.float64)
receivers = cell_array(full, "LightId") == -1
direct = cell_array(full, "Direct_Lamp").astype(np.float64)
direct[~receivers] = 0.0  # the lamp's own unit emission is not reflected light
indirect = (reference - direct)[receivers].mean()
area = cell_areas(full)
print(f"reference: full solve, {full.GetNumberOfCells()} elements, {FINEST} m patches")
print(f"{'patch':>6} {'patches':>7} {'basis KB':>9} {'solve s':>8} {'frame ms':>9} {'basis err':>10} {'filter err':>10}")
def lamp_as_moving_light(solver):
    """The filter end to end: the lamp replaced by a small Lambertian moving light (exitance
    1 over area a: on-axis intensity a / pi). Returns the filter and its error against the
    full solve."""
    mover = relight.vtkRadiosityRelight()
    mover.SetInputConnection(0, solver.GetOutputPort())
    mover.SetInputData(1, lights([(centre[0] - 1e-4, centre[1], centre[2])], intensity=(2 * half) ** 2 / math.pi,
                                 normal=(-1, 0, 0)))
    mover.SetLightEnabled(0, False)
    mover.Update()
    moved = cell_array(mover.GetOutput(), "Radiosity").astype(np.float64)
    return mover, np.abs(moved - reference)[receivers].mean() / reference[receivers].mean()


errors = []
for patch in (2.0, 1.0, 0.5):
    start = time.perf_counter()
    solver = tagged(patch, True)
    seconds = time.perf_counter() - start
    data = solver.GetOutput()
    basis = data.GetCellData().GetArray("PatchBasis")
    # The basis on its own, rebuilt in numpy from the exact direct light:
    # B = D + sum_q E_q basis_q, E_q the area mean of D over patch q.
    P = basis.GetNumberOfComponents() // 3
    patch_id = cell_array(data, "PatchId")
    emitted = np.zeros((P, 3))
    np.add.at(emitted, patch_id, direct * area[:, None])
    emitted /= np.bincount(patch_id, weights=area, minlength=P)[:, None]
    coefficients = vtk_to_numpy(basis).astype(np.float64).reshape(-1, P, 3)
    rebuilt = direct + np.einsum("epc,pc->ec", coefficients, emitted)
    errors.append(np.abs(rebuilt - reference)[receivers].mean() / indirect)
    mover, filter_error = lamp_as_moving_light(solver)
    print(f"{patch:6.2f} {P:7d} {basis.GetNumberOfTuples() * basis.GetNumberOfComponents() * 4 / 1024:9.0f} "
          f"{seconds:8.2f} {mover.GetLastMovingSeconds() * 1e3:9.2f} {errors[-1]:10.2%} {filter_error:10.2%}")
check(errors[2] < errors[1] < errors[0], "finer patches, smaller error in the interreflected light")
check(errors[-1] < 0.01, f"same patches: within 1 % of the full solve's indirect light ({errors[-1]:.2%})")
# The lamp's shot in the reference now delivers exactly its power (its point-rule
# excess beside the wall was 4 %); the point light's is exact for a point. Measured 2.3 %
# (0.7 % when both over-delivered alike).
check(filter_error < 0.03, f"the filter with a point-approximated lamp: within 3 % ({filter_error:.2%})")

# --- 5. the basis per patch node: memory independent of the elements, accuracy kept ---------
# Each patch is one receiver, interpolated to the elements through its corners and centre.
# Same room and lamp; measured end to end 3.2 % here (3.1 % in a room with a panel at
# 16 elements per patch, against 0.6 % for the element basis).
def node_basis(patch, element):
    solver = relight.solve(scene, patch, element, lamp_grading=0, ConvergenceThreshold=1e-5, MaximumShots=1000000,
                           PatchBasis=True, PatchBasisLevel=2)
    return solver, solver.GetOutput().GetFieldData().GetArray("PatchBasis")


solver, basis = node_basis(FINEST, ELEMENT)
_, node_error = lamp_as_moving_light(solver)
check(node_error < 0.04, f"basis per patch node: the filter within 4 % of the full solve ({node_error:.2%})")
weights = cell_array(solver.GetOutput(), "PatchBasisWeights")
check(np.allclose(weights.sum(axis=1), 1.0, atol=1e-5), "each element's node weights sum to one")
broken = vtkPolyData()
broken.DeepCopy(solver.GetOutput())
broken.GetCellData().GetArray("PatchBasisNodes").SetValue(7, 10**6)
bad = relight.vtkRadiosityRelight()
bad.SetInputData(0, broken)
bad.SetInputData(1, lights([(1.0, 1.0, 1.0)]))
catcher = ErrorCatcher(bad)
bad.Update()
check(any("'PatchBasisNodes' refers to a node outside" in e for e in catcher.errors) and
      bad.GetOutput().GetNumberOfCells() == 0, "a node index out of range is refused with a clear message")
_, finer = node_basis(1.0, ELEMENT / 2)
_, coarser = node_basis(1.0, ELEMENT)
check(finer.GetNumberOfTuples() == coarser.GetNumberOfTuples() and finer.GetNumberOfComponents() == coarser.GetNumberOfComponents(),
      f"4x the elements, the same node basis: {coarser.GetNumberOfTuples()} -> {finer.GetNumberOfTuples()} nodes")

# --- 5. the cells' order does not matter ----------------------------------------------------
# Ranks append their pieces in another order than one process reads them. Patches split by
# the solver were numbered by their first element, so the relight filter read another
# patch's basis column: 11 % of the peak off on the 3-light room with its halves swapped.
from vtkmodules.vtkCommonCore import vtkIdList
from vtkmodules.vtkFiltersCore import vtkAppendPolyData, vtkExtractCells
from vtkmodules.vtkFiltersGeometry import vtkGeometryFilter

mesher = relight.vtkRadiosityMesher()
mesher.SetInputData(relight.read_polydata(os.path.join(os.environ["RELIGHT_ROOT"], "Data", "paper_3lights.vtp")))
mesher.SetPatchSize(1.0)
mesher.SetElementSize(0.5)
mesher.Update()
meshed = mesher.GetOutput()
halves = vtkAppendPolyData()
kept = []
for first, last in ((meshed.GetNumberOfCells() // 2, meshed.GetNumberOfCells()), (0, meshed.GetNumberOfCells() // 2)):
    ids = vtkIdList()
    for c in range(first, last):
        ids.InsertNextId(c)
    part = vtkExtractCells()
    part.SetInputData(meshed)
    part.SetCellList(ids)
    surface = vtkGeometryFilter()
    surface.SetInputConnection(part.GetOutputPort())
    surface.Update()
    kept.append(surface)
    halves.AddInputData(surface.GetOutput())
halves.Update()
swapped = halves.GetOutput()
swapped.GetFieldData().ShallowCopy(meshed.GetFieldData())
relit = []
for data in (meshed, swapped):
    solver = relight.vtkLightTaggedRadiosity()
    solver.SetInputData(data)
    solver.SetConvergenceThreshold(1e-4)
    solver.SetPatchBasis(True)
    mover = relight.vtkRadiosityRelight()
    mover.SetInputConnection(0, solver.GetOutputPort())
    mover.SetInputData(1, lights([(1.0, 1.2, 2.0), (3.0, 1.0, 1.0)], intensity=3.0))
    mover.Update()
    kept += [solver, mover]
    out = mover.GetOutput()
    relit.append({tuple(x): v for x, v in zip(cell_centroids(out).round(6), cell_array(out, "Radiosity"))})
peak = max(np.abs(v).max() for v in relit[0].values())
worst = max(np.abs(relit[0][c] - relit[1][c]).max() for c in relit[0]) / peak
check(relit[0].keys() == relit[1].keys() and worst < 1e-2,
      f"the room's cells in another order relight alike: within {worst:.1e} of the peak (at most 1e-2)")

finish("TestMovingLights")
