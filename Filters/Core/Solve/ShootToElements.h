// A shot to every element at once (the progressive method, and every method's direct light):
// factors for all elements, scaled to conserve power, then distributed to all solutions.
#ifndef RadiosityCore_ShootToElements_h
#define RadiosityCore_ShootToElements_h

#include "Solve/ShootingState.h"

namespace radiosity
{

/// Every element receives the shot through factors[e] = F(e -> shooter); returns the
/// power that arrived. Radiosity is updated in parallel, patch sums in element order.
template <typename Channel>
double DistributeToElements(ShootingState<Channel>& state, const WorkerPool& pool, const std::vector<double>& factors)
{
  pool.For(state.Elements, 512, [&](int begin, int end) {
    for (int e = begin; e < end; ++e)
    {
      if (factors[e] > 0)
      {
        state.Gather(e, factors[e]);
      }
    }
  });
  double received = 0;
  for (int e = 0; e < state.Elements; ++e)
  {
    if (factors[e] > 0)
    {
      received += state.ShotTotal() * factors[e] * state.Geometry.Area[e];
      state.Deposit(e, factors[e]);
    }
  }
  return received;
}

/// One shot from `shooter` to every element (TakeShot done): factors with their rays,
/// scaled so the shot delivers no more power than it has (exactly that in a closed scene),
/// then distributed to all solutions and booked.
template <typename Channel>
void ShootToElements(ShootingState<Channel>& state, const WorkerPool& pool, ShooterFormFactors& estimator,
  int shooter, FormFactorMethod method, int samples, SolverStatistics& stats, std::vector<double>& factors)
{
  factors.resize(state.Elements);
  // The expensive part, done once per shot whatever the number of solutions.
  const long long rays = estimator.Compute(shooter, method, samples, stats.Shots, factors);
  // The sampling methods cast the shot's rays on every rank: counted once, on rank 0.
  stats.RayCount += method == FormFactorMethod::Analytic || state.Ranks().Rank() == 0 ? rays : 0;
  stats.FormFactorCount += state.OwnedElements();
  state.Conserve(estimator, shooter, factors);
  state.EndShot(shooter, DistributeToElements(state, pool, factors));
}

} // namespace radiosity

#endif
