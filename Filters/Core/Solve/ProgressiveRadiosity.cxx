#include "Solve/ProgressiveRadiosity.h"
#include "Solve/ShootToElements.h"
#include "Base/WorkerPool.h"

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
  WorkerPool pool(options.Threads);
  const bool cull = options.Visibility == EffectMode::Auto && options.FormFactorMethod == FormFactorMethod::Analytic;
  ShooterFormFactors estimator(mesh, g, rays, pool, cull);
  estimator.SetReceivers(&state.OwnedPatchFlags());
  const int samples =
    options.Visibility == EffectMode::Off && options.FormFactorMethod == FormFactorMethod::Analytic ? 0 : options.FormFactorSamples;
  std::vector<double> factors;
  const StepTimer timer(stats, "shots");
  while (state.Continue())
  {
    const int shooter = state.PickShooter();
    state.TakeShot(shooter);
    ShootToElements(state, pool, estimator, shooter, options.FormFactorMethod, samples, stats, factors);
  }
  state.Finish(estimator);
}
} // namespace

void SolveProgressive(const SceneMesh& mesh, const SceneGeometry& geometry, const Visibility& rays,
  const std::vector<Vec3>& emission, int solutions, bool grey, const SolverOptions& options,
  SolverClock::time_point start, Solution& out)
{
  out.Statistics.SolverMethod = SolverMethod::ProgressiveRefinement;
  WithChannel(grey, [&](auto channel) {
    Shoot<decltype(channel)>(mesh, geometry, rays, emission, solutions, options, start, out);
  });
}

} // namespace radiosity
