// Simulate only what a scene calls for: which lights share solutions, and the solver's
// account of every optional effect it simulated or skipped, with what skipping saved.
#ifndef RadiosityCore_Effects_h
#define RadiosityCore_Effects_h

#include "Solve/LightSolutions.h"

namespace radiosity
{

/// Who gets a solution of their own. Explicit banks win. Otherwise, with Auto, lights
/// marked static (nobody will change them) share one bank and the others stay separate;
/// On keeps every light separate; Off puts all lights in one bank.
/// Returns an empty string or why the banks or flags are unusable.
std::string GroupLights(int lights, const std::vector<int>& banks, const std::vector<int>& isStatic,
  EffectMode separation, LightGrouping& grouping);

/// One row per effect, in a fixed order: Visibility, Interreflection, Color,
/// LightSeparation, ConvergedLights, DirectIndirectSplit, FinalGather, MovingLightBasis.
std::vector<EffectDecision> DescribeEffects(const SceneMesh& mesh, const SolverOptions& options,
  const Solution& solution, const LightGrouping& grouping, int lights, SolutionMode mode);

/// "Visibility simulated, Color skipped, ..." for a log line.
std::string SummarizeEffects(const std::vector<EffectDecision>& effects);

} // namespace radiosity

#endif
