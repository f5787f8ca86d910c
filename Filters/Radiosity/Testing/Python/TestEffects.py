"""Effects through the VTK filter: decisions reported in field data, ForceAllEffects gives
the same answer with more work, static lights share a solution."""

import os

import numpy as np
from vtkmodules.vtkCommonCore import vtkLogger

import relight
from testlib import check, finish
from relight import add_field_ints, cell_array, light_names, make_scene, point_array, read_polydata

vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_WARNING)
DATA = os.path.join(os.environ.get("RELIGHT_ROOT", "."), "Data")
def effects(data):
    fields = data.GetFieldData()
    arrays = [fields.GetAbstractArray(name) for name in ("Effects", "EffectDecisions", "EffectReasons")]
    return {arrays[0].GetValue(i): (arrays[1].GetValue(i), arrays[2].GetValue(i))
            for i in range(arrays[0].GetNumberOfValues())}


def solve(scene, force=False, patch=0.5, element=0.25):
    return relight.solve(scene, patch, element, ConvergenceThreshold=1e-6, ForceAllEffects=force)


# A convex grey room lit by its own ceiling: no shadow rays, one channel.
c = [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0), (0, 0, 2), (2, 0, 2), (2, 2, 2), (0, 2, 2)]
faces = [f[::-1] for f in [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (2, 3, 7, 6), (0, 4, 7, 3), (1, 2, 6, 5)]]  # inward
room = make_scene([[c[i] for i in f] for f in faces], [(0.6, 0.6, 0.6)] * 6, [-1, 0, -1, -1, -1, -1],
                  light_names=["Ceiling"])
auto, forced = solve(room), solve(room, force=True)
decided = effects(auto.GetOutput())
check(list(decided) == ["Visibility", "Interreflection", "Color", "LightSeparation", "ConvergedLights",
                        "DirectIndirectSplit", "FinalGather", "MovingLightBasis"], f"effect rows {list(decided)}")
check(decided["Visibility"][0] == "skipped" and "convex" in decided["Visibility"][1], f"visibility: {decided['Visibility']}")
check(decided["Color"][0] == "skipped" and "grey" in decided["Color"][1], f"color: {decided['Color']}")
forced_decisions = effects(forced.GetOutput())
check(all(forced_decisions[e][0] == "simulated" for e in ("Visibility", "Interreflection", "Color", "ConvergedLights")),
      f"ForceAllEffects simulates everything: {forced_decisions}")
a, b = cell_array(auto.GetOutput(), "Radiosity_Ceiling"), cell_array(forced.GetOutput(), "Radiosity_Ceiling")
check(np.allclose(a, b, rtol=1e-6, atol=1e-9), "Auto gives the same radiosity as ForceAllEffects")
check(auto.GetLastRays() == 0 and forced.GetLastRays() > 0,
      f"and casts no rays where forced casts {forced.GetLastRays()}")

# Static lights share one solution; relit by default it equals the standard solution.
scene = add_field_ints(read_polydata(os.path.join(DATA, "paper_3lights.vtp")), "StaticLights", (1, 0, 1))
merged = solve(scene, patch=1.5, element=0.375)
check(light_names(merged.GetOutput()) == ["WarmWhite+Amber", "CoolWhite"], "static lights merged into one bank")
check(effects(merged.GetOutput())["LightSeparation"][0] == "skipped", "the merge is reported")
combined = relight.vtkLightTaggedRadiosity()
combined.SetInputConnection(merged.GetInputConnection(0, 0).GetProducer().GetOutputPort())
combined.SetSolutionModeToStandardCombined()
combined.SetConvergenceThreshold(1e-6)
combined.Update()
rl = relight.vtkRadiosityRelight()
rl.SetInputConnection(merged.GetOutputPort())
rl.Update()
reference = cell_array(combined.GetOutput(), "Radiosity")
check(np.allclose(cell_array(rl.GetOutput(), "Radiosity"), reference, rtol=1e-4, atol=1e-5 * reference.max()),
      "merged static lights relight to the standard solution")

# The final gather says at how many points it gathered, with the cache on (the default) and
# off; its values agree within the gather's noise.
shared = relight.solve(scene, 1.5, 0.375, ConvergenceThreshold=1e-6)
alone = relight.solve(scene, 1.5, 0.375, ConvergenceThreshold=1e-6, GatherCache=0.0)
reason, alone_reason = effects(shared.GetOutput())["FinalGather"][1], effects(alone.GetOutput())["FinalGather"][1]
check("irradiance cache, CacheAccuracy 0.15" in reason and "irradiance cache" not in alone_reason,
      f"FinalGather names the cache where it is on ({reason}) and not where off ({alone_reason})")
mean = [point_array(s.GetOutput(), "Radiosity_CoolWhite").mean() for s in (shared, alone)]
check(abs(mean[0] / mean[1] - 1) < 0.01, f"shared gathers: the mean of CoolWhite's points within 1 % ({mean})")

finish("TestEffects")
