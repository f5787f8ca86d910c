#include "Solve/LightSolutions.h"
#include "Solve/Effects.h"

#include <algorithm>
#include <set>

namespace radiosity
{

LightGrouping LightGrouping::OnePerLight(int lights)
{
  LightGrouping g;
  g.Solutions = lights;
  for (int i = 0; i < lights; ++i)
  {
    g.SolutionOfLight.push_back(i);
  }
  return g;
}

std::string LightGrouping::FromBanks(const std::vector<int>& banks, int lights, LightGrouping& out)
{
  if (static_cast<int>(banks.size()) != lights)
  {
    return "LightBanks has " + std::to_string(banks.size()) + " entries; it needs one per light (" +
      std::to_string(lights) + ")";
  }
  const std::set<int> used(banks.begin(), banks.end());
  if (*used.begin() != 0 || *used.rbegin() != static_cast<int>(used.size()) - 1)
  {
    return "LightBanks must number banks 0..b-1 without gaps";
  }
  out.SolutionOfLight = banks;
  out.Solutions = static_cast<int>(used.size());
  return std::string();
}

namespace
{
std::vector<int> LightsPerSolution(const LightGrouping& grouping)
{
  std::vector<int> count(grouping.Solutions, 0);
  for (int s : grouping.SolutionOfLight)
  {
    ++count[s];
  }
  return count;
}
} // namespace

std::vector<Vec3> SolutionEmission(
  const SceneMesh& mesh, const LightGrouping& grouping, const std::vector<Vec3>& emissionColor)
{
  const int n = mesh.NumberOfPolygons();
  const int L = grouping.Solutions;
  const std::vector<int> members = LightsPerSolution(grouping);
  std::vector<Vec3> emission(static_cast<size_t>(n) * L);
  for (int e = 0; e < n; ++e)
  {
    if (mesh.lightId[e] < 0)
    {
      continue;
    }
    const int s = grouping.SolutionOfLight[mesh.lightId[e]];
    const bool bank = members[s] > 1 && !emissionColor.empty();
    emission[static_cast<size_t>(e) * L + s] = bank ? emissionColor[e] : Vec3{ 1, 1, 1 };
  }
  return emission;
}

std::vector<Vec3> DefaultColors(
  const SceneMesh& mesh, const LightGrouping& grouping, const std::vector<Vec3>& emissionColor)
{
  const int L = grouping.Solutions;
  const std::vector<int> members = LightsPerSolution(grouping);
  std::vector<Vec3> sum(L);
  std::vector<int> cells(L, 0);
  if (!emissionColor.empty())
  {
    for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
    {
      if (mesh.lightId[e] >= 0)
      {
        const int s = grouping.SolutionOfLight[mesh.lightId[e]];
        sum[s] += emissionColor[e];
        ++cells[s];
      }
    }
  }
  std::vector<Vec3> colors(L, Vec3{ 1, 1, 1 });
  for (int s = 0; s < L; ++s)
  {
    if (members[s] == 1 && cells[s] > 0) // zero Emission stays zero, as in a combined solve
    {
      colors[s] = sum[s] * (1.0 / cells[s]);
    }
  }
  return colors;
}

namespace
{
Solution SolveInMode(const RadiositySolver& solver, const SceneMesh& mesh, const LightGrouping& grouping,
  const std::vector<Vec3>& emissionColor, SolutionMode mode, const SolverOptions& options)
{
  const int n = mesh.NumberOfPolygons();
  if (mode == SolutionMode::StandardCombined)
  {
    std::vector<Vec3> emission(n);
    for (int e = 0; e < n; ++e)
    {
      if (mesh.lightId[e] >= 0)
      {
        emission[e] = emissionColor.empty() ? Vec3{ 1, 1, 1 } : emissionColor[e];
      }
    }
    return solver.Solve(emission, 1, options);
  }
  const int L = grouping.Solutions;
  const std::vector<Vec3> emission = SolutionEmission(mesh, grouping, emissionColor);
  if (mode == SolutionMode::LightTagged)
  {
    return solver.Solve(emission, L, options);
  }

  // StandardSeparate: the baseline the paper beats, form factors recomputed per solution.
  Solution out;
  out.Solutions = L;
  out.Radiosity.assign(static_cast<size_t>(n) * L, Vec3());
  if (options.SeparateDirect)
  {
    out.Direct.assign(static_cast<size_t>(n) * L, Vec3());
  }
  out.Ambient.assign(L, Vec3());
  SolverStatistics& total = out.Statistics;
  total = SolverStatistics::Sequence();
  std::vector<double> lastRemaining(L, 1.0);
  // Each solution's emitted power, so the history is total remaining / total initial, as
  // in the one-pass modes.
  std::vector<double> initialPower(L, 0.0);
  double totalInitial = 0;
  for (int e = 0; e < n; ++e)
  {
    for (int m = 0; m < L; ++m)
    {
      const Vec3& v = emission[static_cast<size_t>(e) * L + m];
      initialPower[m] += (v.x + v.y + v.z) * solver.Geometry().area[e];
    }
  }
  for (double p : initialPower)
  {
    totalInitial += p;
  }
  std::vector<Vec3> single(n);
  double elapsed = 0;
  for (int m = 0; m < L; ++m)
  {
    for (int e = 0; e < n; ++e)
    {
      single[e] = emission[static_cast<size_t>(e) * L + m];
    }
    SolverOptions each = options;
    if (options.Progress)
    {
      each.Progress = [&, m](double f) { return options.Progress((m + f) / L); };
    }
    if (options.TimeBudget > 0)
    {
      each.TimeBudget = std::max(1e-9, options.TimeBudget - elapsed);
    }
    const Solution s = solver.Solve(single, 1, each);
    for (int e = 0; e < n; ++e)
    {
      out.Radiosity[static_cast<size_t>(e) * L + m] = s.Radiosity[e];
      if (options.SeparateDirect)
      {
        out.Direct[static_cast<size_t>(e) * L + m] = s.Direct[e];
      }
    }
    out.Ambient[m] = s.Ambient[0];
    const SolverStatistics& t = s.Statistics;
    for (int shot = 0; shot < t.Shots; ++shot)
    {
      lastRemaining[m] = t.RemainingPerSolution[shot];
      double remaining = 0;
      for (int j = 0; j < L; ++j)
      {
        remaining += lastRemaining[j] * initialPower[j];
      }
      total.RemainingPerSolution.insert(
        total.RemainingPerSolution.end(), lastRemaining.begin(), lastRemaining.end());
      total.RemainingHistory.push_back(totalInitial > 0 ? remaining / totalInitial : 0.0);
      total.TimeHistory.push_back(elapsed + t.TimeHistory[shot]);
    }
    elapsed += t.TimeHistory.empty() ? 0.0 : t.TimeHistory.back();
    total.Append(t);
    if (t.Aborted || t.OutOfTime)
    {
      break;
    }
  }
  return out;
}
} // namespace

Solution SolveLights(const RadiositySolver& solver, const SceneMesh& mesh,
  const LightGrouping& grouping, const std::vector<Vec3>& emissionColor, SolutionMode mode,
  const SolverOptions& options)
{
  Solution out = SolveInMode(solver, mesh, grouping, emissionColor, mode, options);
  out.Effects = DescribeEffects(
    mesh, options, out, grouping, static_cast<int>(grouping.SolutionOfLight.size()), mode);
  return out;
}

double SolveMemory(long long elements, long long points, int solutions, bool separateDirect)
{
  const double perSolution = elements * (3 * sizeof(Vec3) + 3 * sizeof(float)) + points * (sizeof(Vec3) + 3 * sizeof(float));
  return perSolution * solutions * (separateDirect ? 2 : 1);
}

} // namespace radiosity
