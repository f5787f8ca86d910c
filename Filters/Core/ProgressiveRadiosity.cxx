#include "ProgressiveRadiosity.h"
#include "FormFactor.h"
#include "Parallel.h"

#include <algorithm>
#include <cstdint>

namespace radiosity
{

namespace
{
/// Counter-based random numbers: a sample depends only on (shooter, receiver, index), so
/// results are the same for any number of threads.
struct SampleStream
{
  std::uint64_t State;
  SampleStream(std::uint64_t a, std::uint64_t b)
    : State(a * 0x9E3779B97F4A7C15ull ^ (b + 0x632BE59BD9B4E019ull))
  {
  }
  double Next()
  {
    std::uint64_t z = (State += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * (1.0 / 9007199254740992.0);
  }
};

double ChannelSum(const Vec3& v)
{
  return v.x + v.y + v.z;
}
} // namespace

ProgressiveRadiosity::ProgressiveRadiosity(const SceneMesh& mesh)
  : Mesh(mesh)
  , Geometry_(mesh)
  , Rays(new Visibility(mesh))
{
  Error_ = Rays->Error();
  Loops.reserve(mesh.connectivity.size());
  for (int id : mesh.connectivity)
  {
    Loops.push_back(mesh.points[id]);
  }
  PatchTriangles.resize(Geometry_.patchElements.size());
  for (size_t p = 0; p < PatchTriangles.size(); ++p)
  {
    double total = 0;
    for (int e : Geometry_.patchElements[p])
    {
      const Vec3* loop = Loops.data() + mesh.offsets[e];
      for (int t = 1; t + 1 < mesh.PolygonSize(e); ++t)
      {
        total += 0.5 * Norm(Cross(loop[t] - loop[0], loop[t + 1] - loop[0]));
        PatchTriangles[p].push_back({ loop[0], loop[t], loop[t + 1], total });
      }
    }
    for (SampleTriangle& tri : PatchTriangles[p])
    {
      tri.Cdf = total > 0 ? tri.Cdf / total : 1.0;
    }
  }
}

ProgressiveRadiosity::~ProgressiveRadiosity() = default;

const std::string& ProgressiveRadiosity::Error() const
{
  return Error_;
}

void ProgressiveRadiosity::ShootFormFactors(
  int patch, const SolverOptions& options, std::vector<double>& factors, long long& rays) const
{
  const SceneGeometry& g = Geometry_;
  const int n = static_cast<int>(g.normal.size());
  const std::vector<int>& shooters = g.patchElements[patch];
  const std::vector<SampleTriangle>& triangles = PatchTriangles[patch];
  // Offsets keep rays from starting or ending inside their own surfaces; relative to the
  // scene so the result does not depend on its units.
  const double eps = 1e-6 * g.sceneDiagonal;
  std::vector<long long> raysPerElement(n, 0);

  ParallelFor(n, ResolveThreadCount(options.Threads), 64, [&](int begin, int end) {
    std::vector<Vec3> scratch;
    for (int e = begin; e < end; ++e)
    {
      factors[e] = 0;
      if (g.elementPatch[e] == patch)
      {
        continue;
      }
      const Vec3& x = g.centroid[e];
      double f = 0;
      for (int s : shooters)
      {
        // Emitters and reflectors radiate only from their front side.
        if (Dot(g.normal[s], x - g.centroid[s]) <= 0)
        {
          continue;
        }
        f += PointToPolygonFormFactor(
          x, g.normal[e], Loops.data() + Mesh.offsets[s], Mesh.PolygonSize(s), scratch);
      }
      if (f <= 0 || options.ShadowRays <= 0)
      {
        factors[e] = f;
        continue;
      }
      SampleStream random(static_cast<std::uint64_t>(patch), static_cast<std::uint64_t>(e));
      const Vec3 from = x + g.normal[e] * eps;
      const int count = options.ShadowRays;
      int visible = 0;
      for (int r = 0; r < count; ++r)
      {
        // Stratified in the area CDF, so the samples cover the whole patch.
        const double u = (r + random.Next()) / count;
        const auto it = std::lower_bound(triangles.begin(), triangles.end(), u,
          [](const SampleTriangle& t, double value) { return t.Cdf < value; });
        const SampleTriangle& tri = it == triangles.end() ? triangles.back() : *it;
        double a = random.Next(), b = random.Next();
        if (a + b > 1)
        {
          a = 1 - a;
          b = 1 - b;
        }
        const Vec3 target = tri.A + (tri.B - tri.A) * a + (tri.C - tri.A) * b;
        const Vec3 toward = Normalized(Cross(tri.B - tri.A, tri.C - tri.A));
        if (!Rays->Occluded(from, target + toward * eps, 1e-6))
        {
          ++visible;
        }
      }
      raysPerElement[e] = count;
      factors[e] = f * visible / count;
    }
  });
  for (long long r : raysPerElement)
  {
    rays += r;
  }
}

SolverStatistics ProgressiveRadiosity::Solve(const std::vector<Vec3>& emission, int solutions,
  const SolverOptions& options, std::vector<Vec3>& radiosity) const
{
  SolverStatistics stats;
  const SceneGeometry& g = Geometry_;
  const int n = static_cast<int>(g.normal.size());
  const int patches = static_cast<int>(g.patchElements.size());
  const int L = solutions;
  radiosity = emission;
  if (L <= 0 || n == 0)
  {
    stats.Converged = true;
    return stats;
  }

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
  auto patchPower = [&](int p) {
    double sum = 0;
    for (int m = 0; m < L; ++m)
    {
      sum += ChannelSum(unshot[p * L + m]);
    }
    return sum * g.patchArea[p];
  };
  double initial = 0;
  for (int p = 0; p < patches; ++p)
  {
    initial += patchPower(p);
  }
  if (!(initial > 0))
  {
    stats.Converged = true;
    return stats;
  }

  std::vector<double> factors(n);
  std::vector<Vec3> shot(L);
  std::vector<Vec3> delta(static_cast<size_t>(n) * L);
  double remaining = initial;
  const int threads = ResolveThreadCount(options.Threads);
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
      const double power = patchPower(p);
      if (power > best)
      {
        best = power;
        shooter = p;
      }
    }

    // The expensive part, done once per shot whatever the number of solutions.
    ShootFormFactors(shooter, options, factors, stats.ShadowRayCount);
    stats.FormFactorCount += n;
    for (int m = 0; m < L; ++m)
    {
      shot[m] = unshot[shooter * L + m];
      unshot[shooter * L + m] = Vec3();
    }
    stats.ShotPower += best;

    // Distribute every solution's unshot energy with the same form factors.
    ParallelFor(n, threads, 256, [&](int begin, int end) {
      for (int e = begin; e < end; ++e)
      {
        const double f = factors[e];
        const Vec3& rho = Mesh.reflectance[e];
        for (int m = 0; m < L; ++m)
        {
          const Vec3& u = shot[m];
          const Vec3 d{ rho.x * u.x * f, rho.y * u.y * f, rho.z * u.z * f };
          delta[e * L + m] = d;
          radiosity[e * L + m] += d;
        }
      }
    });
    double shotSum = 0;
    for (int m = 0; m < L; ++m)
    {
      shotSum += ChannelSum(shot[m]);
    }
    double received = 0;
    for (int e = 0; e < n; ++e)
    {
      if (factors[e] <= 0)
      {
        continue;
      }
      const int p = g.elementPatch[e];
      const double w = g.area[e] / g.patchArea[p];
      for (int m = 0; m < L; ++m)
      {
        unshot[p * L + m] += delta[e * L + m] * w;
      }
      received += shotSum * factors[e] * g.area[e];
    }
    stats.ReceivedPower += received;

    remaining = 0;
    for (int p = 0; p < patches; ++p)
    {
      remaining += patchPower(p);
    }
    ++stats.Shots;
    stats.RemainingHistory.push_back(remaining / initial);
  }
  return stats;
}

} // namespace radiosity
