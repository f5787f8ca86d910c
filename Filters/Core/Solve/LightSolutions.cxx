#include "Solve/LightSolutions.h"
#include "Lights/LightColors.h"
#include "Solve/Effects.h"
#include "Solve/PointLightShots.h"

#include <algorithm>
#include <chrono>
#include <set>
#include <stdexcept>
#include <string>

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

void CheckGrouping(const SceneMesh& mesh, const LightGrouping& grouping)
{
  // A grouping of fewer lights than the scene has indexed past its end and wrote over the
  // heap (a test that passed 3 for the furnished room's 8 lamps): said instead.
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    if (mesh.LightId[e] >= static_cast<int>(grouping.SolutionOfLight.size()))
    {
      throw std::invalid_argument("polygon " + std::to_string(e) + " belongs to light " +
        std::to_string(mesh.LightId[e]) + ", but the grouping covers " +
        std::to_string(grouping.SolutionOfLight.size()) + " lights");
    }
  }
  for (int solution : grouping.SolutionOfLight)
  {
    if (solution < 0 || solution >= grouping.Solutions)
    {
      throw std::invalid_argument("the grouping names solution " + std::to_string(solution) + " of " +
        std::to_string(grouping.Solutions));
    }
  }
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
  CheckGrouping(mesh, grouping);
  const int n = mesh.NumberOfPolygons();
  const int L = grouping.Solutions;
  const std::vector<int> members = LightsPerSolution(grouping);
  std::vector<Vec3> emission(static_cast<size_t>(n) * L);
  for (int e = 0; e < n; ++e)
  {
    if (mesh.LightId[e] < 0)
    {
      continue;
    }
    const int s = grouping.SolutionOfLight[mesh.LightId[e]];
    const bool bank = members[s] > 1 && !emissionColor.empty();
    emission[static_cast<size_t>(e) * L + s] = bank ? emissionColor[e] : Vec3{ 1, 1, 1 };
  }
  return emission;
}

std::vector<Vec3> DefaultColors(
  const SceneMesh& mesh, const LightGrouping& grouping, const std::vector<Vec3>& emissionColor)
{
  CheckGrouping(mesh, grouping);
  const std::vector<int> members = LightsPerSolution(grouping);
  // Each cell's solution where it is its light's own; a bank's cells count for none, so a
  // bank stays white (its lights keep their colours in its emission).
  std::vector<int> solution(mesh.LightId.size(), -1);
  for (size_t e = 0; e < solution.size(); ++e)
  {
    const int s = mesh.LightId[e] >= 0 ? grouping.SolutionOfLight[mesh.LightId[e]] : -1;
    solution[e] = s >= 0 && members[s] == 1 ? s : -1;
  }
  return LightDefaultColors(grouping.Solutions, {}, solution, emissionColor);
}

namespace
{
namespace
{
/// StandardCombined's one solution: every light's patches emitting together.
std::vector<Vec3> CombinedEmission(const SceneMesh& mesh, const std::vector<Vec3>& emissionColor)
{
  std::vector<Vec3> emission(mesh.NumberOfPolygons());
  for (size_t e = 0; e < emission.size(); ++e)
  {
    if (mesh.LightId[e] >= 0)
    {
      emission[e] = emissionColor.empty() ? Vec3{ 1, 1, 1 } : emissionColor[e];
    }
  }
  return emission;
}

/// StandardSeparate: the baseline the paper beats, one solve per solution with the form
/// factors computed again each time, their results and histories put side by side.
class SeparateSolves
{
public:
  SeparateSolves(const RadiositySolver& solver, const std::vector<Vec3>& emission, int polygons, int solutions,
    const SolverOptions& options)
    : Solver(solver)
    , Emission(emission)
    , N(polygons)
    , L(solutions)
    , Options(options)
    , LastRemaining(solutions, 1.0)
    , InitialPower(solutions, 0.0)
  {
    // Each solution's emitted power, so the history is total remaining / total initial, as
    // in the one-pass modes.
    for (int e = 0; e < N; ++e)
    {
      for (int m = 0; m < L; ++m)
      {
        const Vec3& v = Emission[At(e, m)];
        InitialPower[m] += (v.x + v.y + v.z) * solver.Geometry().Area[e];
      }
    }
    for (double p : InitialPower)
    {
      TotalInitial += p;
    }
  }

  Solution Run()
  {
    Out.Solutions = L;
    Out.Radiosity.assign(static_cast<size_t>(N) * L, Vec3());
    if (Options.SeparateDirect)
    {
      Out.Direct.assign(static_cast<size_t>(N) * L, Vec3());
    }
    Out.Ambient.assign(L, Vec3());
    Out.Statistics = SolverStatistics::Sequence();
    for (int m = 0; m < L; ++m)
    {
      const Solution s = SolveOne(m);
      Place(s, m);
      if (s.Statistics.Aborted || s.Statistics.OutOfTime)
      {
        break;
      }
    }
    return Out;
  }

private:
  size_t At(int e, int m) const { return static_cast<size_t>(e) * L + m; }

  Solution SolveOne(int m) const
  {
    std::vector<Vec3> single(N);
    for (int e = 0; e < N; ++e)
    {
      single[e] = Emission[At(e, m)];
    }
    SolverOptions each = Options;
    if (Options.Progress)
    {
      each.Progress = [this, m](double f) { return Options.Progress((m + f) / L); };
    }
    if (Options.TimeBudget > 0)
    {
      each.TimeBudget = std::max(1e-9, Options.TimeBudget - Elapsed);
    }
    return Solver.Solve(single, 1, each);
  }

  /// Solution m's radiosity into its column, its shots into the histories.
  void Place(const Solution& s, int m)
  {
    for (int e = 0; e < N; ++e)
    {
      Out.Radiosity[At(e, m)] = s.Radiosity[e];
      if (Options.SeparateDirect)
      {
        Out.Direct[At(e, m)] = s.Direct[e];
      }
    }
    Out.Ambient[m] = s.Ambient[0];
    const SolverStatistics& t = s.Statistics;
    SolverStatistics& total = Out.Statistics;
    for (int shot = 0; shot < t.Shots; ++shot)
    {
      LastRemaining[m] = t.RemainingPerSolution[shot];
      double remaining = 0;
      for (int j = 0; j < L; ++j)
      {
        remaining += LastRemaining[j] * InitialPower[j];
      }
      total.RemainingPerSolution.insert(total.RemainingPerSolution.end(), LastRemaining.begin(), LastRemaining.end());
      total.RemainingHistory.push_back(TotalInitial > 0 ? remaining / TotalInitial : 0.0);
      total.TimeHistory.push_back(Elapsed + t.TimeHistory[shot]);
    }
    Elapsed += t.TimeHistory.empty() ? 0.0 : t.TimeHistory.back();
    total.Append(t);
  }

  const RadiositySolver& Solver;
  const std::vector<Vec3>& Emission;
  const int N, L;
  const SolverOptions& Options;
  std::vector<double> LastRemaining, InitialPower;
  double TotalInitial = 0, Elapsed = 0;
  Solution Out;
};
} // namespace

/// The solve's point lights: their first shot's irradiance ([e * lights + k], white) and
/// the solution of the first (-1: StandardCombined, where they share the one solution).
struct PointLightSolutions
{
  std::vector<PointLight> Lights;
  std::vector<Vec3> Irradiance;
  int First = -1;
};

/// The share of a solve's progress the shots report when a gather follows (the gather
/// takes about a third of a solve at its default rays: SolverStatistics::Steps).
constexpr double kSolveShare = 0.7;

/// The final gather over the solve's elements into out's point values, and the cell
/// values from them; a stopped gather leaves the element solution as it was. `spent`: the
/// seconds the solve took of options.TimeBudget (the gather has the rest, or is skipped).
void GatherInto(const RadiositySolver& solver, const SceneMesh& mesh, const std::vector<Vec3>& emission,
  const SolverOptions& options, const PointLightSolutions& lights, double spent, Solution& out)
{
  GatherSettings settings = options.Gather;
  settings.Group = options.Group;
  if (!lights.Lights.empty())
  {
    settings.PointLights = &lights.Lights;
    settings.FirstPointSolution = std::max(0, lights.First);
    settings.PointLightsCombined = lights.First < 0;
  }
  if (options.TimeBudget > 0)
  {
    // The slowest rank's clock: every rank skips the gather, or none does.
    settings.TimeBudget = options.TimeBudget - LargestOverRanks(options.Group, spent);
    if (!(settings.TimeBudget > 0))
    {
      out.GatherOutOfTime = true;
      return;
    }
  }
  std::function<bool(double)> progress;
  if (options.Progress)
  {
    progress = [&options](double f) { return options.Progress(kSolveShare + (1 - kSolveShare) * f); };
  }
  GatheredPoints points = GatherAtPoints(mesh, solver.Geometry(), solver.Rays(), emission, out.Radiosity,
    out.Solutions, settings, options.Threads, progress, out.Statistics.BlockingSurfaces != 0);
  out.GatherRays = points.Rays;
  out.GatherPointRays = points.PointRays;
  out.GatherRecords = points.Records;
  out.GatherPoints = points.Points;
  out.GatherOutOfTime = points.OutOfTime;
  for (const auto& step : points.Steps)
  {
    out.Statistics.Took(step.first, step.second);
  }
  if (points.Aborted)
  {
    out.Statistics.Aborted = true;
    return;
  }
  const bool swept = !points.Cells.empty();
  out.Radiosity = swept ? std::move(points.Cells)
                        : CellsFromPoints(mesh, solver.Geometry(), points.Radiosity, out.Radiosity, out.Solutions);
  if (!out.Direct.empty())
  {
    out.Direct = swept ? std::move(points.CellsDirect)
                       : CellsFromPoints(mesh, solver.Geometry(), points.Direct, out.Direct, out.Solutions);
    out.PointDirect = std::move(points.Direct);
  }
  out.Irradiance = swept ? std::move(points.CellsIrradiance)
                         : CellsFromPoints(mesh, solver.Geometry(), points.Irradiance, out.Irradiance, out.Solutions);
  out.PointIrradiance = std::move(points.Irradiance);
  out.PointRadiosity = std::move(points.Radiosity);
}

/// Each element's irradiance from its radiosity: what it reflects over its reflectance,
/// per channel (0 where the reflectance is 0: a black surface shows nothing of it).
std::vector<Vec3> IrradianceOfElements(const SceneMesh& mesh, const std::vector<Vec3>& emission,
  const std::vector<Vec3>& radiosity, int solutions)
{
  std::vector<Vec3> out(radiosity.size());
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    const Vec3& rho = mesh.Reflectance[e];
    for (int m = 0; m < solutions; ++m)
    {
      const size_t at = static_cast<size_t>(e) * solutions + m;
      const Vec3 reflected = radiosity[at] - (at < emission.size() ? emission[at] : Vec3());
      for (int c = 0; c < 3; ++c)
      {
        out[at][c] = rho[c] > 0 ? std::max(0.0, reflected[c]) / rho[c] : 0.0;
      }
    }
  }
  return out;
}

/// The emission each mode solves for (the cells' own, with room for the point lights'
/// solutions after the grouping's where they have their own).
std::vector<Vec3> ModeEmission(const SceneMesh& mesh, const LightGrouping& grouping,
  const std::vector<Vec3>& emissionColor, SolutionMode mode, int pointLights)
{
  if (mode == SolutionMode::StandardCombined)
  {
    return CombinedEmission(mesh, emissionColor);
  }
  const std::vector<Vec3> cells = SolutionEmission(mesh, grouping, emissionColor);
  if (pointLights == 0)
  {
    return cells;
  }
  const int from = grouping.Solutions, to = from + pointLights;
  std::vector<Vec3> wider(static_cast<size_t>(mesh.NumberOfPolygons()) * to);
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    std::copy_n(cells.begin() + static_cast<size_t>(e) * from, from, wider.begin() + static_cast<size_t>(e) * to);
  }
  return wider;
}

/// The point lights' reflected direct light, laid out as the solve's start ([element *
/// solutions + m]; StandardCombined: at their colors, into the one solution).
std::vector<Vec3> ReflectedLight(const SceneMesh& mesh, size_t size, int solutions, const PointLightSolutions& points)
{
  std::vector<Vec3> reflected(size);
  const int k = static_cast<int>(points.Lights.size());
  if (points.First >= 0)
  {
    AddReflectedDirect(mesh, points.Irradiance, k, reflected, solutions, points.First);
    return reflected;
  }
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    for (int i = 0; i < k; ++i)
    {
      const Vec3 colored = Times(points.Lights[i].Color, points.Irradiance[static_cast<size_t>(e) * k + i]);
      reflected[e] += Times(mesh.Reflectance[e], colored);
    }
  }
  return reflected;
}

Solution SolveInMode(const RadiositySolver& solver, const std::vector<Vec3>& start, int solutions,
  SolutionMode mode, const SolverOptions& options, int polygons)
{
  if (mode != SolutionMode::StandardSeparate)
  {
    return solver.Solve(start, solutions, options);
  }
  return SeparateSolves(solver, start, polygons, solutions, options).Run();
}
/// The solve from the cells' emission plus the point lights' reflected direct light, a
/// method that may be the clustered one told which part is the reflected light
/// (ReflectedStart); the starting vectors live only as long as the solve.
Solution SolveFromPointLights(const RadiositySolver& solver, const SceneMesh& mesh, const std::vector<Vec3>& emission,
  const PointLightSolutions& points, int solutions, SolutionMode mode, SolverOptions solving)
{
  std::vector<Vec3> reflected = ReflectedLight(mesh, emission.size(), solutions, points);
  std::vector<Vec3> starting = emission;
  for (size_t i = 0; i < starting.size(); ++i)
  {
    starting[i] += reflected[i];
  }
  const bool tell = mode != SolutionMode::StandardSeparate &&
    (solving.SolverMethod == SolverMethod::Auto || solving.SolverMethod == SolverMethod::Clustered);
  if (!tell)
  {
    std::vector<Vec3>().swap(reflected);
  }
  solving.ReflectedStart = tell ? &reflected : nullptr;
  return SolveInMode(solver, starting, solutions, mode, solving, mesh.NumberOfPolygons());
}
} // namespace

Solution SolveLights(const RadiositySolver& solver, const SceneMesh& mesh,
  const LightGrouping& grouping, const std::vector<Vec3>& emissionColor, SolutionMode mode,
  const SolverOptions& options, const std::vector<PointLight>& pointLights)
{
  CheckGrouping(mesh, grouping);
  SolverOptions solving = options;
  if (options.Gather.Rays > 0 && options.Progress)
  {
    solving.Progress = [&options](double f) { return options.Progress(kSolveShare * f); };
  }
  const auto start = std::chrono::steady_clock::now();
  PointLightSolutions points;
  points.Lights = pointLights;
  points.First = mode == SolutionMode::StandardCombined ? -1 : grouping.Solutions;
  const int k = static_cast<int>(pointLights.size());
  const int solutions = mode == SolutionMode::StandardCombined ? 1 : grouping.Solutions + k;
  const std::vector<Vec3> emission = ModeEmission(mesh, grouping, emissionColor, mode, k);
  if (k > 0)
  {
    points.Irradiance = PointLightIrradiance(mesh, solver.Geometry(), solver.Rays(), pointLights, options.Threads);
  }
  Solution out = k > 0 ? SolveFromPointLights(solver, mesh, emission, points, solutions, mode, solving)
                        : SolveInMode(solver, emission, solutions, mode, solving, mesh.NumberOfPolygons());
  if (k > 0)
  {
    SettlePointLights(mesh, solver.Geometry(), pointLights, points.Irradiance, points.First, out);
  }
  // The element values' irradiance first: where the gather runs it replaces it, and a
  // gather stopped short keeps it.
  out.Irradiance = IrradianceOfElements(mesh, emission, out.Radiosity, out.Solutions);
  if (options.Gather.Rays > 0 && !out.Statistics.Aborted)
  {
    const std::chrono::duration<double> spent = std::chrono::steady_clock::now() - start;
    GatherInto(solver, mesh, emission, options, points, spent.count(), out);
  }
  out.Effects = DescribeEffects(
    mesh, options, out, grouping, static_cast<int>(grouping.SolutionOfLight.size()) + k, mode);
  return out;
}

double SolveMemory(long long elements, long long points, int solutions, bool separateDirect)
{
  const double perSolution = elements * (3 * sizeof(Vec3) + 3 * sizeof(float)) + points * (sizeof(Vec3) + 3 * sizeof(float));
  return perSolution * solutions * (separateDirect ? 3 : 2); // radiosity, irradiance, the direct part
}

} // namespace radiosity
