// One pass of the final gather over a set of frames (the mesh's points, or a sweep's
// elements): direct light from every emitter and point light with shadow rays, and
// interreflection along stratified cosine rays into an element solution. Shared read-only
// by the threads; Solve/FinalGather.cxx runs it.
#ifndef RadiosityCore_GatherPass_h
#define RadiosityCore_GatherPass_h

#include "Geometry/Visibility.h"
#include "Lights/PointLight.h"
#include "Solve/GatherFrames.h"
#include "Solve/GatherSettings.h"
#include "Solve/IrradianceCache.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace radiosity
{
namespace gathering
{

/// How far a point's gather rays went before they hit (misses went infinitely far): the
/// irradiance cache's reach from them.
struct HitDistances
{
  double InverseSum = 0;
  double Nearest = std::numeric_limits<double>::infinity();
  int Backs = 0; ///< hits on back faces
  /// Where given, each ray's direction, distance and what it brought back, for a record's
  /// gradients (IrradianceGradients).
  StratifiedRays* Samples = nullptr;
  void Add(double distance)
  {
    InverseSum += 1.0 / std::max(distance, 1e-300);
    Nearest = std::min(Nearest, distance);
  }
};

/// The whole state of one gather, shared read-only by the threads.
class Gather
{
public:
  /// Evaluates `frames` (with their emission, [frame * solutions + m]; both held by
  /// reference, as are the others) against the element solution `radiosity`; `salt` draws
  /// other numbers for another pass over the same frames.
  Gather(const SceneMesh& mesh, const SceneGeometry& g, const Visibility& rays, const std::vector<Vec3>& emission,
    const std::vector<Vec3>& radiosity, int solutions, const std::vector<Emitter>& emitters,
    const std::vector<PointFrame>& frames, const std::vector<Vec3>& frameEmission, int gatherRays, int lightRays, bool shadows,
    std::uint64_t salt, const GatherSettings& settings);

  /// Point p's values into radiosity[p * S ...], direct[p * S ...] and the light arriving,
  /// irradiance[p * S ...]; returns its rays. `arriving` [0 .. S) holds the direct light
  /// arriving at p: computed into it, or with `known` read from it (a later sweep over the
  /// same elements: direct light does not change from one sweep to the next).
  long long Evaluate(size_t p, Vec3* radiosity, Vec3* direct, Vec3* irradiance, Vec3* arriving, bool known,
    std::vector<Vec3>& scratch, char& hidden) const;

  /// The direct light arriving at point p (before its reflectance), per solution, into
  /// arriving[0 .. S); returns the shadow rays cast.
  long long DirectAt(size_t p, Vec3* arriving, std::vector<Vec3>& scratch) const;

  /// The interreflection arriving at point p, per solution, into gathered[0 .. S), and how
  /// far its rays went; returns the rays cast.
  long long IndirectAt(size_t p, Vec3* gathered, HitDistances& hits) const;

  /// Mostly back faces: behind something resting on the point's surface (see FillHidden).
  bool SeesBacks(const HitDistances& hits) const { return 2 * hits.Backs > Side * Side; }

  /// Point p's emission plus what arrives, reflected: radiosity, its direct part and the
  /// irradiance, per solution.
  void Compose(size_t p, const Vec3* arriving, const Vec3* gathered, Vec3* radiosity, Vec3* direct,
    Vec3* irradiance) const;

  const PointFrame& Frame(size_t p) const { return Frames[p]; }

  int GatherRays() const { return Side * Side; }
  size_t Points() const { return Frames.size(); }

private:
  /// Irradiance from every emitter: Lambert's formula per element, times the fraction of
  /// stratified shadow rays to the emitter that arrive.
  long long DirectLight(size_t p, const PointFrame& f, std::vector<Vec3>& out, std::vector<Vec3>& scratch) const;

  /// Adds `weight` times the direct light of each point light at x (already off its
  /// surface) to its solution; returns the shadow rays cast.
  long long PointLightsAt(const Vec3& x, const Vec3& normal, double weight, std::vector<Vec3>& out) const;

  /// The element mean of the irradiance from every emitter: at each of LightRays points
  /// spread over the element, Lambert's formula to the emitter and one shadow ray to it.
  long long SpreadDirectLight(size_t p, const PointFrame& f, std::vector<Vec3>& out, std::vector<Vec3>& scratch) const;

  /// The emitter wholly behind the point's surface, or the point behind a flat emitter.
  static bool Behind(const Emitter& em, const Vec3& x, const Vec3& normal);

  /// Where ray r of `count` starts: the point itself, or for an element's frame the r-th
  /// of `count` points stratified by area over the element's fan triangles.
  Vec3 Spot(const PointFrame& f, int r, int count, SampleStream& random) const;

  /// The irradiance the emitter gives dA at x with `normal` where nothing blocks it, per
  /// solution; false where it gives none. By the outline where every corner of it is in
  /// front of x (no clipping needed), else element by element.
  bool Unshadowed(const Emitter& em, const Vec3& x, const Vec3& normal, std::vector<Vec3>& out,
    std::vector<Vec3>& loop, std::vector<Vec3>& scratch) const;

  /// F(dA at x with `normal` -> element e), 0 where x is behind the element.
  double ElementFactor(int e, const Vec3& x, const Vec3& normal, std::vector<Vec3>& loop,
    std::vector<Vec3>& scratch) const;

  /// The fraction of LightRays stratified shadow rays to emitter k that arrive. Four strata
  /// spread over the emitter go first; where they agree (a room away, or in full view) the
  /// others are not cast: most of a building's points see a lamp wholly or not at all.
  double SeenFraction(size_t p, size_t k, const Vec3& from, long long& rays) const;

  /// Irradiance from the element solution less its emission (the emitters were taken
  /// directly), along Side x Side stratified cosine rays; back faces send nothing.
  long long Interreflection(size_t p, const PointFrame& f, std::vector<Vec3>& out, HitDistances& hits) const;

  const SceneMesh& Mesh;
  const SceneGeometry& G;
  const Visibility& Rays;
  const std::vector<Vec3>& Emission;
  const std::vector<Vec3>& Radiosity;
  const int S;
  const int Side;
  const int LightRays;
  const bool Shadows;
  /// The start stratum of a ray over an element is its direction's (or its lamp point's)
  /// stratum shuffled by these steps: paired as given, near-normal rays would all start on
  /// one half of a quad and the shadow rays' ends would follow their starts.
  const int RayStep, LightStep;
  const std::uint64_t Salt;
  const std::vector<PointFrame>& Frames;
  const std::vector<Vec3>& PointEmission;
  const std::vector<Emitter>& Emitters;
  std::vector<PointLight> PointLights; ///< white where each is its own solution
  const int FirstPoint;
  const bool PointLightsCombined;
};


} // namespace gathering
} // namespace radiosity

#endif
