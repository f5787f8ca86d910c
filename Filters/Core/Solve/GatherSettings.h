// What the final gather is asked to do (Solve/FinalGather.h runs it, Solve/GatherPass.h
// reads its lights): the rays, the sweeps, the irradiance cache, the time it may take.
#ifndef RadiosityCore_GatherSettings_h
#define RadiosityCore_GatherSettings_h

#include "Base/ProcessGroup.h"
#include "Lights/PointLight.h"

#include <vector>

namespace radiosity
{

struct GatherSettings
{
  /// Cosine-distributed rays per point into the element solution (rounded down to a
  /// square, for strata); 0 turns the gather off. 256 is the solver filter's default:
  /// at 64 a point's own noise outweighed what the gather corrects on a furnished room.
  int Rays = 256;
  /// Shares the points' interreflection through an irradiance cache (Solve/IrradianceCache.h):
  /// a point gathers for itself only where no record gathered nearby reaches it, a record
  /// reaching this fraction of the harmonic mean distance its rays went (Ward's a); direct
  /// light is still taken at every point. 0: every point gathers.
  double CacheAccuracy = 0.15;
  /// Shadow rays per point to each emitting patch it can see (four first, the rest only
  /// where those disagree).
  int LightRays = 16;
  /// Passes over the elements before the points: each element's mean gathered anew from
  /// points spread over it (direct light with SweepLightRays shadow rays, SweepRays cosine
  /// rays into the previous pass), so what the element solution lost or leaked shrinks by
  /// the reflectance at each pass before the points read it.
  int Sweeps = 1;
  int SweepRays = 16;
  int SweepLightRays = 4;
  /// Seconds the gather may take (0: no limit; SolveLights gives it what the solve left of
  /// SolverOptions::TimeBudget). The points take fewer rays where Rays would not fit at
  /// the sweep's pace, and none (their elements' mean) where not even a few would.
  double TimeBudget = 0;
  /// Processes gathering the same points together: they agree on the rays the budget
  /// leaves (the fewest any of them can afford), so their pieces match.
  ProcessGroup Group;
  /// Lights at points (luminaires; Solve/PointLightShots.h), light i white in solution
  /// FirstPointSolution + i: their direct light is taken at each point with one shadow ray
  /// (a point source casts a hard shadow), at each of an element's spread points in a sweep.
  const std::vector<PointLight>* PointLights = nullptr;
  int FirstPointSolution = 0;
  /// All of them in solution FirstPointSolution at their colors (StandardCombined).
  bool PointLightsCombined = false;
};

} // namespace radiosity

#endif
