"""The one accuracy knob (relight.levels, relight.solve(accuracy=...)): its default level is
the filters' own defaults, it sets what it says, settings given beside it win, and each
level is closer than the one before to Lambert's closed form for a floor under a square
lamp, at points between the mesh's points (what a rendering shows there)."""

import math

import numpy as np

import relight
from relight import levels
from testlib import check, finish
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersCore import vtkProbeFilter

# --- the default level is the filters' defaults --------------------------------------------
default = levels.LEVELS["default"]
mesher, solver = relight.vtkRadiosityMesher(), relight.vtkLightTaggedRadiosity()
check(default == levels.Level(1.0, mesher.GetLampGrading(), mesher.GetShadowGrading(), solver.GetGatherRays(),
                              solver.GetClusterSeparation(), solver.GetGatherSweeps()),
      f"level 'default' {default} is the filters' LampGrading {mesher.GetLampGrading()}, ShadowGrading "
      f"{mesher.GetShadowGrading()}, GatherRays "
      f"{solver.GetGatherRays()}, ClusterSeparation {solver.GetClusterSeparation()}, GatherSweeps "
      f"{solver.GetGatherSweeps()}")
try:
    levels.level("best")
    check(False, "an unknown level is refused")
except ValueError as error:
    check("preview, draft, default, fine, reference" in str(error), f"an unknown level names the levels: {error}")

# --- a floor under a square lamp (nothing else: only the direct light, in closed form) ----
RHO, HEIGHT, HALF = 0.5, 0.25, 0.2
floor = [(-2, 0, -2), (-2, 0, 2), (2, 0, 2), (2, 0, -2)]  # faces +y
lamp = [(-HALF, HEIGHT, -HALF), (HALF, HEIGHT, -HALF), (HALF, HEIGHT, HALF), (-HALF, HEIGHT, HALF)]  # faces -y
scene = relight.make_scene([floor, lamp], [(RHO,) * 3, (0.0,) * 3], [-1, 0], light_names=["Lamp"])


def lambert(p):
    """Radiosity on the floor at p under the unit-exitance lamp: rho times the point-to-polygon
    form factor, (1 / 2 pi) sum of each edge's angle times the cosine of its plane to the normal."""
    r = [np.array(v, float) - p for v in lamp]
    total = 0.0
    for a, b in zip(r, r[1:] + r[:1]):
        cross = np.cross(a, b)
        angle = math.acos(np.clip(np.dot(a, b) / (np.linalg.norm(a) * np.linalg.norm(b)), -1, 1))
        total += angle * cross[1] / np.linalg.norm(cross)
    return RHO * abs(total) / (2 * math.pi)


rng = np.random.default_rng(7)
probes = np.column_stack([rng.uniform(-1.2, 1.2, 300), np.zeros(300), rng.uniform(-1.2, 1.2, 300)])
exact = np.array([lambert(p) for p in probes])


def probe_error(data):
    points = vtkPoints()
    for p in probes:
        points.InsertNextPoint(*p)
    where = vtkPolyData()
    where.SetPoints(points)
    probe = vtkProbeFilter()
    probe.SetInputData(where)
    probe.SetSourceData(data)
    probe.Update()
    ours = vtk_to_numpy(probe.GetOutput().GetPointData().GetArray("Radiosity_Lamp"))[:, 0]
    return float(np.abs(ours - exact).mean() / exact.mean())


errors, runs = {}, {}
for name in ("preview", "draft", "default", "fine"):
    solved = relight.solve(scene, 1.0, 0.25, accuracy=name)
    runs[name] = solved
    errors[name] = probe_error(solved.GetOutput())
chosen = levels.LEVELS["fine"]
mesher = runs["fine"].GetInputAlgorithm()
check((mesher.GetElementSize(), mesher.GetLampGrading(), mesher.GetShadowGrading(), runs["fine"].GetGatherRays(),
       runs["fine"].GetClusterSeparation(), runs["fine"].GetGatherSweeps()) ==
      (0.25 * chosen.element_scale, chosen.lamp_grading, chosen.shadow_grading, chosen.gather_rays,
       chosen.cluster_separation, chosen.gather_sweeps) and chosen.shadow_grading > 0,
      "accuracy='fine' sets the element size, LampGrading, ShadowGrading, GatherRays, ClusterSeparation and "
      "GatherSweeps")
given = relight.solve(scene, 1.0, 0.25, accuracy="fine", lamp_grading=0, GatherRays=16)
check(given.GetInputAlgorithm().GetLampGrading() == 0 and given.GetGatherRays() == 16,
      "settings given beside the level win over it")
# Preview and draft share their elements, so on direct light alone they come out alike.
check(min(errors["preview"], errors["draft"]) > errors["default"] > errors["fine"] and errors["fine"] < 0.01,
      "each finer element size closer to Lambert's closed form at 300 points between the mesh points: " +
      ", ".join(f"{n} {100 * e:.2f} %" for n, e in errors.items()))

# --- the same knob in ParaView: the mesher's Accuracy, which the solver follows -------------
def pipeline(level, gather_rays=None):
    mesher = relight.vtkRadiosityMesher()
    mesher.SetInputData(scene)
    mesher.SetPatchSize(1.0)
    mesher.SetElementSize(0.25)
    mesher.SetAccuracy(level)
    solver = relight.vtkLightTaggedRadiosity()
    solver.SetInputConnection(mesher.GetOutputPort())
    if gather_rays is not None:
        solver.SetGatherRays(gather_rays)
    solver.Update()
    return mesher, solver


def warnings_of(data):
    listed = data.GetFieldData().GetAbstractArray("Warnings")
    return [listed.GetValue(i) for i in range(listed.GetNumberOfValues())] if listed else []


def effect(data, name):
    fields = data.GetFieldData()
    names = fields.GetAbstractArray("Effects")
    row = [i for i in range(names.GetNumberOfValues()) if names.GetValue(i) == name][0]
    return fields.GetAbstractArray("EffectReasons").GetValue(row)


mesher, solver = pipeline(3)
out = solver.GetOutput()
stamp = out.GetFieldData().GetArray("Accuracy")
check(mesher.GetElementSizeInUse() == 0.125 and mesher.GetLampGradingInUse() == chosen.lamp_grading and
      mesher.GetShadowGradingInUse() == chosen.shadow_grading and stamp is not None and stamp.GetValue(0) == 3,
      f"Accuracy Fine on the mesher: elements {mesher.GetElementSizeInUse()}, LampGrading "
      f"{mesher.GetLampGradingInUse()}, stamped {stamp.GetValue(0) if stamp else None}")
check(out.GetNumberOfCells() == runs["fine"].GetOutput().GetNumberOfCells() and
      abs(probe_error(out) - errors["fine"]) < 1e-12,
      f"...the same mesh and answer as relight.solve(accuracy='fine') ({out.GetNumberOfCells()} elements)")
mesher, solver = pipeline(0, gather_rays=0)  # the level's 64 rays, not the solver's own 0
check("then 64 rays" in effect(solver.GetOutput(), "FinalGather"),
      f"the solver takes Preview's gather rays from the mesher's stamp: {effect(solver.GetOutput(), 'FinalGather')}")
said = warnings_of(solver.GetOutput())
check(any("GatherRays 0 was not used" in w and "sets 64" in w for w in said),
      f"...and says that its own GatherRays 0 was not used: {said}")
mesher, solver = pipeline(-1, gather_rays=0)
check(solver.GetOutput().GetFieldData().GetArray("Accuracy") is None and
      "not asked for" in effect(solver.GetOutput(), "FinalGather"),
      "Custom stamps nothing: the solver's own GatherRays 0 holds")

check(not any("was not used" in w for w in warnings_of(solver.GetOutput())),
      "...and says nothing of it, the solver's own being used")

# --- a setting only another method reads is reported, not silently dropped ----------------
HIERARCHICAL_RAN = "was not used: only the Clustered method reads it, and Hierarchical ran"
for method, separation, expected in (("Hierarchical", 6.0, HIERARCHICAL_RAN), ("Clustered", 6.0, None),
                                     ("Hierarchical", solver.GetClusterSeparation(), None), ("Auto", 6.0, None)):
    alone = relight.vtkLightTaggedRadiosity()
    alone.SetInputConnection(mesher.GetOutputPort())
    getattr(alone, "SetSolverMethodTo" + method)()
    alone.SetClusterSeparation(separation)
    alone.Update()
    said = [w for w in warnings_of(alone.GetOutput()) if "ClusterSeparation" in w]
    check(said == [] if expected is None else len(said) == 1 and expected in said[0],
          f"ClusterSeparation {separation:g} with the {method} method: {'nothing said' if expected is None else 'reported'}"
          f" ({said})")

# --- settings by name: each method's own, from the method table -----------------------------
def by_name(method, name, value):
    solver = relight.vtkLightTaggedRadiosity()
    solver.SetInputConnection(mesher.GetOutputPort())
    getattr(solver, "SetSolverMethodTo" + method)()
    solver.SetMethodSetting(name, value)
    solver.errors = relight.ErrorCatcher(solver).errors
    solver.Update()
    return solver


tight = by_name("Clustered", "ClusterMemoryLimit", 1e4)  # 10 kB: the links cannot fit
stopped = [w for w in warnings_of(tight.GetOutput()) if "memory" in w.lower()] + \
    [effect(tight.GetOutput(), "Interreflection")]
check(tight.GetMethodSettingName(0) == "ClusterMemoryLimit" and tight.GetMethodSettingValue(0) == 1e4 and
      any("memory" in text.lower() for text in stopped),
      f"SetMethodSetting('ClusterMemoryLimit', 1e4) reaches the clustered method, which stops for memory: {stopped}")
said = [w for w in warnings_of(by_name("Hierarchical", "ClusterMemoryLimit", 1e9).GetOutput()) if "ClusterMemoryLimit" in w]
check(len(said) == 1 and "only the Clustered method reads it, and Hierarchical ran" in said[0],
      f"...and under Hierarchical is said to be unused: {said}")
for name, value, words in (("Separation", 4.0, "no method has a setting 'Separation'"),
                           ("RefinementThreshold", 2.0, "RefinementThreshold is 2; it is from 0 to 1")):
    bad = by_name("Hierarchical", name, value)
    check(bad.GetOutput().GetNumberOfCells() == 0 and any(words in e for e in bad.errors),
          f"SetMethodSetting('{name}', {value:g}) fails the update, saying so: {bad.errors}")

finish("TestAccuracyLevels")
