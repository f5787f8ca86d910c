#include "Solve/Effects.h"

#include <cstdio>
#include <set>

namespace radiosity
{

namespace
{
std::string Format(const char* format, double a = 0, double b = 0, double c = 0, double d = 0)
{
  char buffer[512];
  std::snprintf(buffer, sizeof(buffer), format, a, b, c, d);
  return buffer;
}

double Megabytes(double bytes)
{
  return bytes / (1024.0 * 1024.0);
}
} // namespace

std::string GroupLights(int lights, const std::vector<int>& banks, const std::vector<int>& isStatic,
  EffectMode separation, LightGrouping& grouping)
{
  if (!banks.empty())
  {
    return LightGrouping::FromBanks(banks, lights, grouping);
  }
  if (!isStatic.empty() && static_cast<int>(isStatic.size()) != lights)
  {
    return "StaticLights has " + std::to_string(isStatic.size()) + " entries; it needs one per light (" +
      std::to_string(lights) + ")";
  }
  grouping = LightGrouping::OnePerLight(lights);
  if (separation == EffectMode::On)
  {
    return std::string();
  }
  std::vector<int> bank(lights, 0);
  if (separation == EffectMode::Off)
  {
    return LightGrouping::FromBanks(bank, lights, grouping);
  }
  // Auto: every static light in bank 0 (if any), the others one bank each.
  int staticCount = 0;
  for (int i = 0; i < lights && !isStatic.empty(); ++i)
  {
    staticCount += isStatic[i] != 0;
  }
  if (staticCount < 2)
  {
    return std::string(); // nothing to merge
  }
  int next = 1;
  for (int i = 0; i < lights; ++i)
  {
    bank[i] = isStatic[i] ? 0 : next++;
  }
  return LightGrouping::FromBanks(bank, lights, grouping);
}

namespace
{
EffectDecision VisibilityRow(const SolverOptions& options, const SolverStatistics& s)
{
  EffectDecision row{ "Visibility", true, "" };
  if (options.FormFactorMethod != FormFactorMethod::Analytic)
  {
    row.Reason = "simulated: the hemicube or Monte Carlo rays are the form factors";
  }
  else if (options.Visibility == EffectMode::Off || options.FormFactorSamples <= 0)
  {
    row.Simulated = false;
    row.Reason = "skipped: turned off, every pair treated as unoccluded";
  }
  else if (options.Visibility == EffectMode::On)
  {
    row.Reason = Format("simulated: forced on, %.0f shadow rays", static_cast<double>(s.RayCount));
  }
  else if (s.BlockingSurfaces == 0)
  {
    row.Simulated = false;
    row.Reason = Format("skipped: no surface has scene geometry behind it (a convex enclosure), "
                        "so nothing can block; saved %.0f shadow rays",
      static_cast<double>(s.RaysSkipped));
  }
  else
  {
    const double pairs = s.PairsUnblockable + (options.FormFactorSamples > 0 ? s.RayCount / options.FormFactorSamples : 0);
    row.Reason = Format("simulated where needed: %.0f planes can block; %.0f of %.0f lit pairs "
                        "cannot be blocked, saved %.0f shadow rays",
      s.BlockingSurfaces, static_cast<double>(s.PairsUnblockable), pairs, static_cast<double>(s.RaysSkipped));
  }
  return row;
}

EffectDecision InterreflectionRow(const SceneMesh& mesh, const SolverOptions& options, const SolverStatistics& s)
{
  bool reflects = false;
  for (const Vec3& r : mesh.Reflectance)
  {
    reflects = reflects || r.x > 0 || r.y > 0 || r.z > 0;
  }
  EffectDecision row{ "Interreflection", true, "" };
  if (options.Interreflection == EffectMode::Off)
  {
    row.Simulated = false;
    row.Reason = "skipped: turned off, direct light only (emission and its first bounce)";
  }
  else if (!reflects)
  {
    row.Simulated = false;
    row.Reason = Format("skipped: no surface reflects, each light's patches shoot once (%.0f shots)",
      static_cast<double>(s.Shots));
  }
  else
  {
    row.Reason = Format("simulated: %.0f shots", static_cast<double>(s.Shots));
  }
  return row;
}

EffectDecision ColorRow(const SolverOptions& options, const SolverStatistics& s, double polygons, int solutions)
{
  EffectDecision row{ "Color", !s.SingleChannel, "" };
  const double saved = 2.0 / 3.0 * polygons * solutions * sizeof(double) * 3;
  if (s.SingleChannel && options.Color == EffectMode::Off)
  {
    row.Reason = Format("skipped: turned off, one grey channel (mean reflectance); saved %.2f MB", Megabytes(saved));
  }
  else if (s.SingleChannel)
  {
    row.Reason = Format("skipped: every reflectance and emission is grey, one channel solved and "
                        "expanded; saved %.2f MB and two thirds of the distribution work",
      Megabytes(saved));
  }
  else
  {
    row.Reason = options.Color == EffectMode::On ? "simulated: forced on" : "simulated: colored reflectance or emission";
  }
  return row;
}

EffectDecision SeparationRow(const LightGrouping& grouping, int lights, SolutionMode mode, double polygons)
{
  EffectDecision row{ "LightSeparation", true, "" };
  if (mode == SolutionMode::StandardCombined)
  {
    row.Simulated = false;
    row.Reason = "skipped: StandardCombined solves one solution with every light";
  }
  else if (grouping.Solutions < lights)
  {
    row.Simulated = false;
    row.Reason = Format("merged: %.0f lights share %.0f solutions (banks or static lights); "
                        "saved %.2f MB of output",
      lights, grouping.Solutions, Megabytes((lights - grouping.Solutions) * polygons * 3 * 4.0 * 2));
  }
  else
  {
    row.Reason = Format("simulated: %.0f lights, one solution each", lights);
  }
  return row;
}

EffectDecision ConvergedRow(const SolverOptions& options, const SolverStatistics& s, double polygons)
{
  EffectDecision row{ "ConvergedLights", s.DistributionsSkipped == 0, "" };
  if (options.ConvergedLights == EffectMode::On)
  {
    row.Reason = "simulated: forced on, every solution shot until all converge";
  }
  else if (s.DistributionsSkipped > 0)
  {
    row.Reason = Format("skipped: %.0f shots of solutions already below the threshold "
                        "(saved %.0f element updates)",
      static_cast<double>(s.DistributionsSkipped), static_cast<double>(s.DistributionsSkipped) * polygons);
  }
  else
  {
    row.Reason = "simulated: no solution converged before the others";
  }
  return row;
}

EffectDecision SplitRow(const SolverOptions& options, double polygons, int solutions)
{
  return { "DirectIndirectSplit", options.SeparateDirect,
    options.SeparateDirect
      ? "simulated: asked for (SeparateDirect)"
      : Format("skipped: not asked for (SeparateDirect off); saved %.2f MB", Megabytes(polygons * solutions * 3 * 4.0 * 2)) };
}
EffectDecision GatherRow(const SolverOptions& options, const Solution& solution)
{
  const GatherSettings& g = options.Gather;
  if (g.Rays <= 0)
  {
    return { "FinalGather", false, "skipped: not asked for (GatherRays 0); the points show their elements' mean" };
  }
  if (solution.PointRadiosity.empty() && solution.GatherOutOfTime)
  {
    return { "FinalGather", false,
      "skipped: the TimeBudget was spent before the points (by the solve, or the sweep over the elements); the "
      "points show their elements' mean" };
  }
  if (solution.PointRadiosity.empty())
  {
    return { "FinalGather", false, "skipped: stopped before it ended; the points show their elements' mean" };
  }
  const std::string fewer = solution.GatherPointRays < g.Rays
    ? Format(" (of %.0f asked: what the TimeBudget left)", g.Rays)
    : std::string();
  const std::string shared = solution.GatherRecords > 0
    ? Format(" at %.0f of %.0f points (irradiance cache, CacheAccuracy %.2f; the others interpolate them)",
        solution.GatherRecords, solution.GatherPoints, g.CacheAccuracy)
    : std::string();
  return { "FinalGather", true,
    Format("simulated: %.0f sweep(s) over the elements, then %.0f rays", g.Sweeps, solution.GatherPointRays) + fewer +
      shared +
      Format(" and %.0f shadow rays a light a point; %.0f rays", g.LightRays, static_cast<double>(solution.GatherRays)) };
}
} // namespace

std::vector<EffectDecision> DescribeEffects(const SceneMesh& mesh, const SolverOptions& options,
  const Solution& solution, const LightGrouping& grouping, int lights, SolutionMode mode)
{
  const SolverStatistics& s = solution.Statistics;
  const double n = mesh.NumberOfPolygons();
  return { VisibilityRow(options, s), InterreflectionRow(mesh, options, s), ColorRow(options, s, n, solution.Solutions),
    SeparationRow(grouping, lights, mode, n), ConvergedRow(options, s, n), SplitRow(options, n, solution.Solutions),
    GatherRow(options, solution), { "MovingLightBasis", false, "skipped: not asked for (no patch basis built)" } };
}

std::string SummarizeEffects(const std::vector<EffectDecision>& effects)
{
  std::string line;
  for (const EffectDecision& e : effects)
  {
    line += (line.empty() ? "" : ", ") + e.Effect + (e.Simulated ? " simulated" : " skipped");
  }
  return line;
}

} // namespace radiosity
