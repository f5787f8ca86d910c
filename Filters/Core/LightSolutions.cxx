#include "LightSolutions.h"

namespace radiosity
{

LightSolutions SolveLights(const ProgressiveRadiosity& solver, const SceneMesh& mesh, int lights,
  const std::vector<Vec3>& emissionColor, SolutionMode mode, const SolverOptions& options)
{
  LightSolutions out;
  const int n = mesh.NumberOfPolygons();
  const Vec3 unit{ 1, 1, 1 };
  if (mode == SolutionMode::StandardCombined)
  {
    std::vector<Vec3> emission(n);
    for (int e = 0; e < n; ++e)
    {
      if (mesh.lightId[e] >= 0)
      {
        emission[e] = emissionColor.empty() ? unit : emissionColor[e];
      }
    }
    out.Solutions = 1;
    out.Statistics = solver.Solve(emission, 1, options, out.Radiosity);
    return out;
  }
  out.Solutions = lights;
  if (mode == SolutionMode::LightTagged)
  {
    std::vector<Vec3> emission(static_cast<size_t>(n) * lights);
    for (int e = 0; e < n; ++e)
    {
      if (mesh.lightId[e] >= 0)
      {
        emission[e * lights + mesh.lightId[e]] = unit;
      }
    }
    out.Statistics = solver.Solve(emission, lights, options, out.Radiosity);
    return out;
  }
  // StandardSeparate: the baseline the paper beats, form factors recomputed per light.
  out.Radiosity.assign(static_cast<size_t>(n) * lights, Vec3());
  out.Statistics.Converged = true;
  std::vector<Vec3> emission(n), single;
  for (int m = 0; m < lights; ++m)
  {
    for (int e = 0; e < n; ++e)
    {
      emission[e] = mesh.lightId[e] == m ? unit : Vec3();
    }
    SolverOptions each = options;
    if (options.Progress)
    {
      each.Progress = [&, m](double f) { return options.Progress((m + f) / lights); };
    }
    const SolverStatistics s = solver.Solve(emission, 1, each, single);
    for (int e = 0; e < n; ++e)
    {
      out.Radiosity[e * lights + m] = single[e];
    }
    SolverStatistics& t = out.Statistics;
    t.Shots += s.Shots;
    t.Converged = t.Converged && s.Converged;
    t.Aborted = s.Aborted;
    t.RemainingHistory.insert(t.RemainingHistory.end(), s.RemainingHistory.begin(),
      s.RemainingHistory.end());
    t.ShadowRayCount += s.ShadowRayCount;
    t.FormFactorCount += s.FormFactorCount;
    t.ShotPower += s.ShotPower;
    t.ReceivedPower += s.ReceivedPower;
    if (s.Aborted)
    {
      break;
    }
  }
  return out;
}

std::vector<Vec3> AverageToPoints(
  const SceneMesh& mesh, const SceneGeometry& geometry, const std::vector<Vec3>& cells, int columns)
{
  const size_t points = mesh.points.size();
  std::vector<Vec3> sums(points * columns);
  std::vector<double> weights(points, 0.0);
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    const double w = geometry.area[e];
    const int* ids = mesh.Polygon(e);
    for (int v = 0; v < mesh.PolygonSize(e); ++v)
    {
      weights[ids[v]] += w;
      for (int m = 0; m < columns; ++m)
      {
        sums[ids[v] * columns + m] += cells[e * columns + m] * w;
      }
    }
  }
  for (size_t p = 0; p < points; ++p)
  {
    const double inv = weights[p] > 0 ? 1.0 / weights[p] : 0.0;
    for (int m = 0; m < columns; ++m)
    {
      sums[p * columns + m] = sums[p * columns + m] * inv;
    }
  }
  return sums;
}

} // namespace radiosity
