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

std::vector<EffectDecision> DescribeEffects(const SceneMesh& mesh, const SolverOptions& options,
  const Solution& solution, const LightGrouping& grouping, int lights, SolutionMode mode)
{
  const SolverStatistics& s = solution.Statistics;
  const double n = mesh.NumberOfPolygons();
  const int L = solution.Solutions;
  std::vector<EffectDecision> rows;

  EffectDecision visibility{ "Visibility", true, "" };
  if (options.Method != FormFactorMethod::Analytic)
  {
    visibility.Reason = "simulated: the hemicube or Monte Carlo rays are the form factors";
  }
  else if (options.Visibility == EffectMode::Off || options.Samples <= 0)
  {
    visibility.Simulated = false;
    visibility.Reason = "skipped: turned off, every pair treated as unoccluded";
  }
  else if (options.Visibility == EffectMode::On)
  {
    visibility.Reason = Format("simulated: forced on, %.0f shadow rays", static_cast<double>(s.RayCount));
  }
  else if (s.BlockingSurfaces == 0)
  {
    visibility.Simulated = false;
    visibility.Reason = Format("skipped: no surface has scene geometry behind it (a convex enclosure), "
                               "so nothing can block; saved %.0f shadow rays",
      static_cast<double>(s.RaysSkipped));
  }
  else
  {
    const double pairs = s.PairsUnblockable + (options.Samples > 0 ? s.RayCount / options.Samples : 0);
    visibility.Reason = Format("simulated where needed: %.0f planes can block; %.0f of %.0f lit pairs "
                               "cannot be blocked, saved %.0f shadow rays",
      s.BlockingSurfaces, static_cast<double>(s.PairsUnblockable), pairs, static_cast<double>(s.RaysSkipped));
  }
  rows.push_back(visibility);

  bool reflects = false;
  for (const Vec3& r : mesh.reflectance)
  {
    reflects = reflects || r.x > 0 || r.y > 0 || r.z > 0;
  }
  EffectDecision bounce{ "Interreflection", true, "" };
  if (options.Interreflection == EffectMode::Off)
  {
    bounce.Simulated = false;
    bounce.Reason = "skipped: turned off, direct light only (emission and its first bounce)";
  }
  else if (!reflects)
  {
    bounce.Simulated = false;
    bounce.Reason = Format("skipped: no surface reflects, each light's patches shoot once (%.0f shots)",
      static_cast<double>(s.Shots));
  }
  else
  {
    bounce.Reason = Format("simulated: %.0f shots", static_cast<double>(s.Shots));
  }
  rows.push_back(bounce);

  EffectDecision color{ "Color", !s.SingleChannel, "" };
  const double saved = 2.0 / 3.0 * n * L * sizeof(double) * 3;
  if (s.SingleChannel && options.Color == EffectMode::Off)
  {
    color.Reason = Format("skipped: turned off, one grey channel (mean reflectance); saved %.2f MB", Megabytes(saved));
  }
  else if (s.SingleChannel)
  {
    color.Reason = Format("skipped: every reflectance and emission is grey, one channel solved and "
                          "expanded; saved %.2f MB and two thirds of the distribution work",
      Megabytes(saved));
  }
  else
  {
    color.Reason = options.Color == EffectMode::On ? "simulated: forced on" : "simulated: colored reflectance or emission";
  }
  rows.push_back(color);

  EffectDecision separation{ "LightSeparation", true, "" };
  if (mode == SolutionMode::StandardCombined)
  {
    separation.Simulated = false;
    separation.Reason = "skipped: StandardCombined solves one solution with every light";
  }
  else if (grouping.Solutions < lights)
  {
    separation.Simulated = false;
    separation.Reason = Format("merged: %.0f lights share %.0f solutions (banks or static lights); "
                               "saved %.2f MB of output",
      lights, grouping.Solutions, Megabytes((lights - grouping.Solutions) * n * 3 * 4.0 * 2));
  }
  else
  {
    separation.Reason = Format("simulated: %.0f lights, one solution each", lights);
  }
  rows.push_back(separation);

  EffectDecision converged{ "ConvergedSolutions", s.DistributionsSkipped == 0, "" };
  if (options.ConvergedSolutions == EffectMode::On)
  {
    converged.Reason = "simulated: forced on, every solution shot until all converge";
  }
  else if (s.DistributionsSkipped > 0)
  {
    converged.Reason = Format("skipped: %.0f shots of solutions already below the threshold "
                              "(saved %.0f element updates)",
      static_cast<double>(s.DistributionsSkipped), static_cast<double>(s.DistributionsSkipped) * n);
  }
  else
  {
    converged.Reason = "simulated: no solution converged before the others";
  }
  rows.push_back(converged);

  EffectDecision split{ "DirectIndirectSplit", options.SeparateDirect, "" };
  split.Reason = options.SeparateDirect
    ? "simulated: asked for (SeparateDirect)"
    : Format("skipped: not asked for (SeparateDirect off); saved %.2f MB", Megabytes(n * L * 3 * 4.0 * 2));
  rows.push_back(split);

  rows.push_back({ "MovingLightBasis", false, "skipped: not asked for (no patch basis built)" });
  return rows;
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
