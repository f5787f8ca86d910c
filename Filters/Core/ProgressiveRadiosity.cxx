#include "ProgressiveRadiosity.h"
#include "WorkerPool.h"

#include <algorithm>
#include <chrono>

namespace radiosity
{

namespace
{
/// The solver's arithmetic for an RGB value (Vec3) or a single grey channel (double).
/// A grey scene solved as one channel gives the same numbers with a third of the work.
struct Rgb
{
  using Value = Vec3;
  static Value From(const Vec3& v) { return v; }
  static Vec3 To(const Value& v) { return v; }
  static double Sum(const Value& v) { return v.x + v.y + v.z; }
  static Value Reflect(const Vec3& rho, const Value& u, double f)
  {
    return { rho.x * u.x * f, rho.y * u.y * f, rho.z * u.z * f };
  }
};

struct Grey
{
  using Value = double;
  static Value From(const Vec3& v) { return (v.x + v.y + v.z) / 3.0; }
  static Vec3 To(Value v) { return { v, v, v }; }
  static double Sum(Value v) { return 3.0 * v; } // powers stay comparable with RGB runs
  static Value Reflect(const Vec3& rho, Value u, double f) { return (rho.x + rho.y + rho.z) / 3.0 * u * f; }
};

using Clock = std::chrono::steady_clock;

template <typename Channel>
void Shoot(const SceneMesh& mesh, const SceneGeometry& g, const Visibility& rays,
  const std::vector<Vec3>& emission, int L, const SolverOptions& options, Clock::time_point start,
  Solution& out)
{
  using Value = typename Channel::Value;
  SolverStatistics& stats = out.Statistics;
  const int n = static_cast<int>(g.normal.size());
  const int patches = static_cast<int>(g.patchElements.size());
  const bool direct = options.SeparateDirect;
  const bool reflect = options.Interreflection != EffectMode::Off;
  const bool skipConverged = options.ConvergedSolutions != EffectMode::On;

  std::vector<Value> radiosity(static_cast<size_t>(n) * L), directPart;
  std::vector<Value> unshot(static_cast<size_t>(patches) * L);
  for (int e = 0; e < n; ++e)
  {
    const int p = g.elementPatch[e];
    for (int m = 0; m < L; ++m)
    {
      const Value v = Channel::From(emission[static_cast<size_t>(e) * L + m]);
      radiosity[static_cast<size_t>(e) * L + m] = v;
      // Unshot radiosity of a patch: the area average of its elements' emission.
      unshot[static_cast<size_t>(p) * L + m] += v * (g.area[e] / g.patchArea[p]);
    }
  }
  if (direct)
  {
    directPart = radiosity;
  }
  // The part of the unshot energy that is still emission (for the direct/indirect split).
  std::vector<Value> unshotEmission;
  if (direct)
  {
    unshotEmission = unshot;
  }
  auto power = [&](int p, int m) { return Channel::Sum(unshot[static_cast<size_t>(p) * L + m]) * g.patchArea[p]; };
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
  remainingPer = initialPer;
  // A solution is done once its unshot power is below the threshold of its own emission:
  // then every light is accurate on its own scale, however dim it is.
  std::vector<char> active(L, 0);
  auto update = [&] {
    bool any = false;
    for (int m = 0; m < L; ++m)
    {
      active[m] = initialPer[m] > 0 && remainingPer[m] >= options.ConvergenceThreshold * initialPer[m];
      any = any || active[m];
    }
    return any;
  };

  WorkerPool pool(options.Threads);
  const bool cull = options.Visibility == EffectMode::Auto && options.Method == FormFactorMethod::Analytic;
  ShooterFormFactors estimator(mesh, g, rays, pool, cull);
  const int samples =
    options.Visibility == EffectMode::Off && options.Method == FormFactorMethod::Analytic ? 0 : options.Samples;
  std::vector<double> factors(n);
  std::vector<Value> shot(L), shotEmission(L);
  std::vector<char> distribute(L, 1);
  while (true)
  {
    if (!update())
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
    for (int m = 0; m < L; ++m)
    {
      distribute[m] = skipConverged ? active[m] : 1;
    }
    int shooter = 0;
    double best = -1;
    for (int p = 0; p < patches; ++p)
    {
      double sum = 0;
      for (int m = 0; m < L; ++m)
      {
        sum += distribute[m] ? power(p, m) : 0.0;
      }
      if (sum > best)
      {
        best = sum;
        shooter = p;
      }
    }

    // The expensive part, done once per shot whatever the number of solutions.
    stats.RayCount += estimator.Compute(shooter, options.Method, samples, stats.Shots, factors);
    stats.FormFactorCount += n;
    double shotSum = 0;
    for (int m = 0; m < L; ++m)
    {
      if (!distribute[m])
      {
        shot[m] = Value();
        if (direct)
        {
          shotEmission[m] = Value();
        }
        ++stats.DistributionsSkipped;
        continue;
      }
      shot[m] = unshot[static_cast<size_t>(shooter) * L + m];
      unshot[static_cast<size_t>(shooter) * L + m] = Value();
      shotSum += Channel::Sum(shot[m]);
      if (direct)
      {
        shotEmission[m] = unshotEmission[static_cast<size_t>(shooter) * L + m];
        unshotEmission[static_cast<size_t>(shooter) * L + m] = Value();
      }
    }
    stats.ShotPower += shotSum * g.patchArea[shooter];

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
        const Vec3& rho = mesh.reflectance[e];
        for (int m = 0; m < L; ++m)
        {
          radiosity[static_cast<size_t>(e) * L + m] += Channel::Reflect(rho, shot[m], f);
          if (direct)
          {
            directPart[static_cast<size_t>(e) * L + m] += Channel::Reflect(rho, shotEmission[m], f);
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
      received += shotSum * f * g.area[e];
      if (!reflect)
      {
        continue; // direct light only: what is received is not shot again
      }
      const int p = g.elementPatch[e];
      const double w = f * g.area[e] / g.patchArea[p];
      for (int m = 0; m < L; ++m)
      {
        unshot[static_cast<size_t>(p) * L + m] += Channel::Reflect(mesh.reflectance[e], shot[m], w);
      }
    }
    stats.ReceivedPower += received;
    stats.EscapedPower += shotSum * g.patchArea[shooter] - received;

    std::fill(remainingPer.begin(), remainingPer.end(), 0.0);
    for (int p = 0; p < patches; ++p)
    {
      for (int m = 0; m < L; ++m)
      {
        remainingPer[m] += power(p, m);
      }
    }
    double remaining = 0;
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
  stats.RaysSkipped = estimator.RaysSkipped();
  stats.PairsUnblockable = estimator.PairsUnblockable();
  stats.BlockingSurfaces = estimator.BlockingPlanes();

  if (options.AmbientTerm && reflect)
  {
    // Cohen et al. 1988: ambient = R * (sum_p U_p A_p) / (sum_p A_p), with the
    // interreflection factor R = 1 / (1 - mean reflectance) per channel; each element
    // shows rho * ambient on top of what it received.
    Vec3 meanRho;
    double area = 0;
    for (int e = 0; e < n; ++e)
    {
      meanRho += mesh.reflectance[e] * g.area[e];
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
        unshotPower += Channel::To(unshot[static_cast<size_t>(p) * L + m]) * g.patchArea[p];
      }
      const Vec3 a = unshotPower * (1.0 / area);
      out.Ambient[m] = { interreflection.x * a.x, interreflection.y * a.y, interreflection.z * a.z };
    }
  }
  out.Radiosity.resize(radiosity.size());
  for (int e = 0; e < n; ++e)
  {
    for (int m = 0; m < L; ++m)
    {
      const Vec3& rho = mesh.reflectance[e];
      const Vec3& a = out.Ambient[m];
      out.Radiosity[static_cast<size_t>(e) * L + m] = Channel::To(radiosity[static_cast<size_t>(e) * L + m]) + Vec3{ rho.x * a.x, rho.y * a.y, rho.z * a.z };
    }
  }
  if (direct)
  {
    out.Direct.resize(directPart.size());
    for (size_t i = 0; i < directPart.size(); ++i)
    {
      out.Direct[i] = Channel::To(directPart[i]);
    }
  }
}

bool Grey3(const Vec3& v)
{
  return v.x == v.y && v.y == v.z;
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
  const auto start = Clock::now();
  Solution out;
  const int n = static_cast<int>(Geometry_.normal.size());
  out.Solutions = solutions;
  out.Ambient.assign(std::max(solutions, 0), Vec3());
  if (solutions <= 0 || n == 0)
  {
    out.Radiosity = emission;
    out.Statistics.Converged = true;
    return out;
  }
  bool grey = options.Color == EffectMode::Off;
  if (options.Color == EffectMode::Auto)
  {
    grey = std::all_of(Mesh.reflectance.begin(), Mesh.reflectance.end(), Grey3) &&
      std::all_of(emission.begin(), emission.end(), Grey3);
  }
  out.Statistics.SingleChannel = grey;
  if (grey)
  {
    Shoot<Grey>(Mesh, Geometry_, *Rays_, emission, solutions, options, start, out);
  }
  else
  {
    Shoot<Rgb>(Mesh, Geometry_, *Rays_, emission, solutions, options, start, out);
  }
  return out;
}

} // namespace radiosity
