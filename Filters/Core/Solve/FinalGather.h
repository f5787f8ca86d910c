// The local pass of two-pass radiosity: the solution evaluated at the points that are
// displayed (Smits, Arvo & Greenberg 1994; Lischinski, Tampieri & Greenberg 1993). Direct
// light is computed at each point from every emitter with shadow rays; interreflection is
// gathered along cosine rays from the point into the element solution. A ray starts on
// the point's own side of every wall, so light cannot leak to it, and an element's value
// is read one bounce away, where averaging over the element no longer shows.
#ifndef RadiosityCore_FinalGather_h
#define RadiosityCore_FinalGather_h

#include "Geometry/Scene.h"
#include "Geometry/Visibility.h"
#include "Solve/GatherSettings.h"

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace radiosity
{

struct GatheredPoints
{
  /// [point * solutions + m]: emission plus reflected direct light plus gathered
  /// interreflection, per solution. Empty where the gather was stopped.
  std::vector<Vec3> Radiosity;
  std::vector<Vec3> Direct; ///< emission plus reflected direct light only, same layout
  /// The light arriving on the front side (irradiance: illuminance in lux for a luminaire
  /// in metres), before the reflectance: a black surface has one too. Same layout.
  std::vector<Vec3> Irradiance;
  /// The last sweep's element values ([element * solutions + m], each gathered at the
  /// element's centroid, inside it) and their direct part; empty without sweeps.
  std::vector<Vec3> Cells, CellsDirect, CellsIrradiance;
  /// Per point, 1 where it saw mostly back faces and no visible neighbour could fill in
  /// for it (see FillHidden in FinalGather.cxx).
  std::vector<char> Hidden;
  long long Rays = 0;       ///< rays cast, shadow rays included
  int PointRays = 0;        ///< the cosine rays a point took (fewer than asked on a TimeBudget)
  int Records = 0;          ///< points that gathered for themselves with the cache on (0: off)
  int Points = 0;           ///< points evaluated (each copy's representative once)
  bool OutOfTime = false;   ///< the TimeBudget left the points ungathered (Cells kept)
  bool Aborted = false;
  /// Where its time went, step by step (the points' frames, their direct light, the
  /// sweeps, the points' interreflection), in seconds.
  std::vector<std::pair<std::string, double>> Steps;
};

/// The gather at every point of `mesh` used by a polygon (others get 0): `radiosity` and
/// `emission` are per element and solution ([e * solutions + m]), the solver's output and
/// input. A point takes the normal, reflectance and emission of the open elements around
/// it (sheltered ones only where it has no open one) and is evaluated a quarter of the way
/// to their centre, so a point on a wall's foot sees only its own room. Every point draws its own numbers
/// (SampleStream by point index): the result does not depend on the thread count.
/// `threads` 0 takes every hardware thread; `progress` (may be empty) is called between
/// blocks of points with the fraction done, and false from it stops the gather. Without
/// `shadows` (where the solve found no surface that can block) no shadow rays are cast.
GatheredPoints GatherAtPoints(const SceneMesh& mesh, const SceneGeometry& geometry, const Visibility& rays,
  const std::vector<Vec3>& emission, const std::vector<Vec3>& radiosity, int solutions,
  const GatherSettings& settings, int threads = 0, const std::function<bool(double)>& progress = {},
  bool shadows = true);

/// The irradiance at free points (a work plane in the air, a meter's cell) facing
/// `normals`, per solution ([point * solutions + m] in Irradiance, and in Radiosity as a
/// white surface there would send it; the direct part in Direct), gathered as the mesh's points are: direct light from every emitter and point
/// light with shadow rays, interreflection along `settings.Rays` cosine rays (0: none) into the
/// element solution `radiosity` (whose emitters' `emission` is left out: they were taken
/// as direct light). No point is on a surface, so none is hidden and none takes a
/// neighbour's value.
GatheredPoints IrradianceAtPoints(const SceneMesh& mesh, const SceneGeometry& geometry, const Visibility& rays,
  const std::vector<Vec3>& emission, const std::vector<Vec3>& radiosity, int solutions,
  const std::vector<Vec3>& points, const std::vector<Vec3>& normals, const GatherSettings& settings, int threads = 0,
  const std::function<bool(double)>& progress = {});

/// Element values from gathered point values: each open element the mean of its corners,
/// sheltered and enclosed ones keep the solver's `cells` (dark for a reason that stops at
/// their edge, as in AverageToPoints).
std::vector<Vec3> CellsFromPoints(const SceneMesh& mesh, const SceneGeometry& geometry,
  const std::vector<Vec3>& points, const std::vector<Vec3>& cells, int solutions);

} // namespace radiosity

#endif
