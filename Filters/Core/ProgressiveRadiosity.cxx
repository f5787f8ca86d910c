#include "ProgressiveRadiosity.h"
#include "HierarchicalRadiosity.h"
#include "ShootingState.h"
#include "WorkerPool.h"

#include <algorithm>
#include <chrono>

namespace radiosity
{

namespace
{
template <typename Channel>
void Shoot(const SceneMesh& mesh, const SceneGeometry& g, const Visibility& rays,
  const std::vector<Vec3>& emission, int L, const SolverOptions& options, SolverClock::time_point start,
  Solution& out)
{
  ShootingState<Channel> state(mesh, g, emission, L, options, start, out);
  SolverStatistics& stats = out.Statistics;
  const int n = state.Elements;
  WorkerPool pool(options.Threads);
  const bool cull = options.Visibility == EffectMode::Auto && options.Method == FormFactorMethod::Analytic;
  ShooterFormFactors estimator(mesh, g, rays, pool, cull);
  const int samples =
    options.Visibility == EffectMode::Off && options.Method == FormFactorMethod::Analytic ? 0 : options.Samples;
  std::vector<double> factors(n);
  while (state.Continue())
  {
    const int shooter = state.PickShooter();
    // The expensive part, done once per shot whatever the number of solutions.
    stats.RayCount += estimator.Compute(shooter, options.Method, samples, stats.Shots, factors);
    stats.FormFactorCount += n;
    state.TakeShot(shooter);
    state.EndShot(shooter, DistributeToElements(state, pool, factors));
  }
  stats.RaysSkipped = estimator.RaysSkipped();
  stats.PairsUnblockable = estimator.PairsUnblockable();
  stats.BlockingSurfaces = estimator.BlockingPlanes();
  state.Finish();
}

/// Auto: hierarchical links pay once patches hold many elements and the scene is large;
/// the hemicube and Monte Carlo estimators exist only in progressive refinement.
SolverMethod ResolveMethod(const SolverOptions& options, int elements, int patches)
{
  if (options.Solver != SolverMethod::Auto)
  {
    return options.Solver;
  }
  const bool large = elements >= 20000 && elements >= 4 * patches;
  return large && options.Method == FormFactorMethod::Analytic ? SolverMethod::Hierarchical
                                                               : SolverMethod::ProgressiveRefinement;
}

bool Grey3(const Vec3& v)
{
  return v.x == v.y && v.y == v.z;
}
} // namespace

int ShotCap(const SolverOptions& options, int patches)
{
  if (options.MaximumShots > 0)
  {
    return options.MaximumShots;
  }
  return static_cast<int>(std::min<long long>(std::max<long long>(2000, 25LL * patches), 1000000000LL));
}

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
  const auto start = SolverClock::now();
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
  if (ResolveMethod(options, n, static_cast<int>(Geometry_.patchElements.size())) == SolverMethod::Hierarchical)
  {
    SolveHierarchical(Mesh, Geometry_, *Rays_, emission, solutions, grey, options, start, out);
    return out;
  }
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
