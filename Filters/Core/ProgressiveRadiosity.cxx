#include "ProgressiveRadiosity.h"
#include "WorkerPool.h"

#include <algorithm>
#include <chrono>

namespace radiosity
{

namespace
{
double ChannelSum(const Vec3& v)
{
  return v.x + v.y + v.z;
}

Vec3 Times(const Vec3& a, const Vec3& b)
{
  return { a.x * b.x, a.y * b.y, a.z * b.z };
}
} // namespace

ProgressiveRadiosity::ProgressiveRadiosity(const SceneMesh& mesh)
  : Mesh(mesh)
  , Geometry_(mesh)
  , Rays_(new Visibility(mesh))
{
  Error_ = Rays_->Error();
}

ProgressiveRadiosity::~ProgressiveRadiosity() = default;

const std::string& ProgressiveRadiosity::Error() const
{
  return Error_;
}

Solution ProgressiveRadiosity::Solve(
  const std::vector<Vec3>& emission, int solutions, const SolverOptions& options) const
{
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  Solution out;
  SolverStatistics& stats = out.Statistics;
  const SceneGeometry& g = Geometry_;
  const int n = static_cast<int>(g.normal.size());
  const int patches = static_cast<int>(g.patchElements.size());
  const int L = solutions;
  out.Solutions = L;
  out.Radiosity = emission;
  out.Ambient.assign(std::max(L, 0), Vec3());
  if (options.SeparateDirect)
  {
    out.Direct = emission;
  }
  if (L <= 0 || n == 0)
  {
    stats.Converged = true;
    return out;
  }
  std::vector<Vec3>& radiosity = out.Radiosity;

  // Unshot radiosity per patch and solution: the area average of its elements' emission.
  // Doubles throughout: at reflectance near 1 float accumulation drifts (REFERENCES.md).
  std::vector<Vec3> unshot(static_cast<size_t>(patches) * L);
  for (int e = 0; e < n; ++e)
  {
    const int p = g.elementPatch[e];
    for (int m = 0; m < L; ++m)
    {
      unshot[p * L + m] += emission[e * L + m] * (g.area[e] / g.patchArea[p]);
    }
  }
  // The part of the unshot energy that is still emission (for the direct/indirect split).
  std::vector<Vec3> unshotEmission;
  if (options.SeparateDirect)
  {
    unshotEmission = unshot;
  }
  auto power = [&](int p, int m) { return ChannelSum(unshot[p * L + m]) * g.patchArea[p]; };
  std::vector<double> initialPer(L, 0.0), remainingPer(L, 0.0);
  for (int p = 0; p < patches; ++p)
  {
    for (int m = 0; m < L; ++m)
    {
      initialPer[m] += power(p, m);
    }
  }
  double initial = 0;
  for (double v : initialPer)
  {
    initial += v;
  }
  stats.EmittedPower = stats.UnshotPower = initial;
  if (!(initial > 0))
  {
    stats.Converged = true;
    return out;
  }

  WorkerPool pool(options.Threads);
  ShooterFormFactors estimator(Mesh, g, *Rays_, pool);
  std::vector<double> factors(n);
  std::vector<Vec3> shot(L), shotEmission(L);
  double remaining = initial;
  while (true)
  {
    if (remaining / initial < options.ConvergenceThreshold)
    {
      stats.Converged = true;
      break;
    }
    if (stats.Shots >= options.MaximumShots)
    {
      break;
    }
    if (options.TimeBudget > 0 &&
      std::chrono::duration<double>(Clock::now() - start).count() >= options.TimeBudget)
    {
      stats.OutOfTime = true;
      break;
    }
    if (options.Progress &&
      !options.Progress(std::min(1.0, static_cast<double>(stats.Shots) / options.MaximumShots)))
    {
      stats.Aborted = true;
      break;
    }
    int shooter = 0;
    double best = -1;
    for (int p = 0; p < patches; ++p)
    {
      double sum = 0;
      for (int m = 0; m < L; ++m)
      {
        sum += power(p, m);
      }
      if (sum > best)
      {
        best = sum;
        shooter = p;
      }
    }

    // The expensive part, done once per shot whatever the number of solutions.
    stats.RayCount += estimator.Compute(shooter, options.Method, options.Samples, stats.Shots, factors);
    stats.FormFactorCount += n;
    double shotSum = 0;
    for (int m = 0; m < L; ++m)
    {
      shot[m] = unshot[shooter * L + m];
      unshot[shooter * L + m] = Vec3();
      shotSum += ChannelSum(shot[m]);
      if (options.SeparateDirect)
      {
        shotEmission[m] = unshotEmission[shooter * L + m];
        unshotEmission[shooter * L + m] = Vec3();
      }
    }
    stats.ShotPower += best;

    // Distribute every solution's unshot energy with the same form factors. Each element
    // is written by one thread; the patch sums below run in element order.
    pool.For(n, 512, [&](int begin, int end) {
      for (int e = begin; e < end; ++e)
      {
        const double f = factors[e];
        if (f <= 0)
        {
          continue;
        }
        const Vec3 rf = Mesh.reflectance[e] * f;
        for (int m = 0; m < L; ++m)
        {
          radiosity[e * L + m] += Times(rf, shot[m]);
        }
        if (options.SeparateDirect)
        {
          for (int m = 0; m < L; ++m)
          {
            out.Direct[e * L + m] += Times(rf, shotEmission[m]);
          }
        }
      }
    });
    double received = 0;
    for (int e = 0; e < n; ++e)
    {
      const double f = factors[e];
      if (f <= 0)
      {
        continue;
      }
      const int p = g.elementPatch[e];
      const Vec3 rf = Mesh.reflectance[e] * (f * g.area[e] / g.patchArea[p]);
      for (int m = 0; m < L; ++m)
      {
        unshot[p * L + m] += Times(rf, shot[m]);
      }
      received += shotSum * f * g.area[e];
    }
    stats.ReceivedPower += received;
    stats.EscapedPower += best - received;

    std::fill(remainingPer.begin(), remainingPer.end(), 0.0);
    for (int p = 0; p < patches; ++p)
    {
      for (int m = 0; m < L; ++m)
      {
        remainingPer[m] += power(p, m);
      }
    }
    remaining = 0;
    for (int m = 0; m < L; ++m)
    {
      remaining += remainingPer[m];
      stats.RemainingPerSolution.push_back(initialPer[m] > 0 ? remainingPer[m] / initialPer[m] : 0.0);
    }
    ++stats.Shots;
    stats.UnshotPower = remaining;
    stats.RemainingHistory.push_back(remaining / initial);
    stats.TimeHistory.push_back(std::chrono::duration<double>(Clock::now() - start).count());
  }

  if (options.AmbientTerm)
  {
    // Cohen et al. 1988: ambient = R * (sum_p U_p A_p) / (sum_p A_p), with the
    // interreflection factor R = 1 / (1 - mean reflectance) per channel; each element
    // shows rho * ambient on top of what it received.
    Vec3 meanRho;
    double area = 0;
    for (int e = 0; e < n; ++e)
    {
      meanRho += Mesh.reflectance[e] * g.area[e];
      area += g.area[e];
    }
    meanRho = meanRho * (1.0 / area);
    Vec3 interreflection;
    for (int c = 0; c < 3; ++c)
    {
      // Capped: a closed scene of perfect reflectors has no finite ambient.
      interreflection[c] = 1.0 / std::max(1.0 - meanRho[c], 1e-6);
    }
    for (int m = 0; m < L; ++m)
    {
      Vec3 unshotPower;
      for (int p = 0; p < patches; ++p)
      {
        unshotPower += unshot[p * L + m] * g.patchArea[p];
      }
      out.Ambient[m] = Times(interreflection, unshotPower * (1.0 / area));
    }
    for (int e = 0; e < n; ++e)
    {
      for (int m = 0; m < L; ++m)
      {
        radiosity[e * L + m] += Times(Mesh.reflectance[e], out.Ambient[m]);
      }
    }
  }
  return out;
}

} // namespace radiosity
