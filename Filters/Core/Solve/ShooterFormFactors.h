// Form factors from one shooting patch to every element, by three methods.
#ifndef RadiosityCore_ShooterFormFactors_h
#define RadiosityCore_ShooterFormFactors_h

#include "Base/SampleStream.h"
#include "Geometry/ClusterTree.h"
#include "Geometry/Polygon.h"
#include "Geometry/Scene.h"
#include "Geometry/Visibility.h"
#include "Base/WorkerPool.h"

#include <atomic>
#include <map>
#include <memory>
#include <vector>

namespace radiosity
{

enum class FormFactorMethod
{
  /// Lambert's exact point-to-polygon formula at each receiver, times the fraction of
  /// `samples` stratified shadow rays to the shooter that are unblocked (0: none cast).
  /// Exact for unoccluded pairs however close, including adjacent ones.
  Analytic = 0,
  /// A hemicube of resolution `samples` (top face samples^2 pixels) at the shooter's
  /// centre, its pixels cast as Embree rays (Cohen & Greenberg 1985).
  Hemicube = 1,
  /// `samples` cosine-distributed rays from stratified points on the shooter; each hit
  /// carries 1/samples. Cost independent of the number of receivers.
  MonteCarlo = 2
};

/// Per-solve helper that owns the buffers, so shots allocate nothing.
class ShooterFormFactors
{
public:
  /// `cullVisibility`: find the surfaces that can block (see SolverOptions::Visibility) and
  /// cast no shadow rays for pairs none of them can come between.
  ShooterFormFactors(const SceneMesh& mesh, const SceneGeometry& geometry, const Visibility& rays,
    const WorkerPool& pool, bool cullVisibility = false);

  /// factors[e] = F(element e -> patch), the factor shooting needs
  /// (delta B_e = rho_e * unshot_patch * factors[e]). `shot` decorrelates repeated shots
  /// of one patch for the sampling methods. Returns the number of rays cast.
  long long Compute(int patch, FormFactorMethod method, int samples, int shot,
    std::vector<double>& factors);

  /// Rays cast and pairs proven unblockable, counted per thread and added up once.
  struct RayCounts
  {
    long long Rays = 0;
    long long Unblockable = 0;
  };

  /// Unoccluded F(dA at x with `normal` -> patch); 0 where the patch's front faces away.
  double PointFactor(int patch, const Vec3& x, const Vec3& normal, std::vector<Vec3>& scratch) const;
  /// The vector V with PointFactor(patch, x, n) = n . V for every n whose front half-space
  /// holds the whole patch (ClusterTree::FactorVector).
  Vec3 FactorVector(int patch, const Vec3& x) const;
  /// Unoccluded F(element e -> patch): PointFactor at the centroid, or, where the element
  /// is within twice its size of the patch, the area mean over its fan triangles.
  double ReceiverFactor(int patch, int e, std::vector<Vec3>& scratch) const;
  /// The analytic method's factor for one element: ReceiverFactor times the
  /// unblocked fraction of `samples` shadow rays (none where culling proves them useless).
  double ElementFactor(int patch, int element, int samples, std::vector<Vec3>& scratch, RayCounts& counts) const;
  /// Unblocked rays of `samples` between stratified points of two patches.
  int VisibleRaysBetweenPatches(int receiver, int shooter, int samples) const;
  /// The factor by which a shooter's factors must be scaled so that the power they deliver
  /// (`receiving`: sum of factor x receiver area) never exceeds what the patch shoots from
  /// its open area. Where every probe ray from the patch lands on a receiver's front (the
  /// patch sees a closed scene), the delivered power equals the shot power exactly: the
  /// point rule's excess near the shooter and its deficit at corners cancel out of the
  /// total, so a closed room neither creates nor loses energy, even at rho = 0.999.
  double ConservationScale(int patch, double receiving);
  /// True where every probe ray from the (planar) patch lands on a receiver's front: the
  /// patch sees a closed scene, so the factors from each of its elements sum to one.
  bool ViewIsClosed(int patch) { return SeesClosedScene(patch); }
  /// Restricts the analytic method to the elements of these patches (1 = receives), the
  /// share of one process when several solve together; the others get factor 0. Null
  /// (the default): every element. The sampling methods' cost is the shooter's, so they
  /// compute every factor anyway.
  void SetReceivers(const std::vector<char>* patches) { Receivers = patches; }

  /// Adds a thread's counts to the totals reported by RaysSkipped and PairsUnblockable.
  void Count(const RayCounts& counts, int samples);
  /// False when no blocking surface can come between the two patches.
  bool MayBeBlockedBetweenPatches(int receiver, int shooter) const;
  bool Culling() const { return CullVisibility; }

  const Vec3& Centre(int patch) const { return PatchCentre[patch]; }
  const Vec3& Normal(int patch) const { return PatchNormal[patch]; }
  /// Largest distance from the centre to a point of the patch.
  double Radius(int patch) const { return PatchRadius[patch]; }
  /// The patch's cluster tree (null for a flat patch or one of few elements).
  const ClusterTree* Tree(int patch) const { return Trees[patch].get(); }
  /// Unblocked rays of `samples` from stratified points of the shooter to the centroids
  /// of `count` elements (picked evenly over them), `seed` decorrelating calls.
  int VisibleRaysToElements(int shooter, const int* elements, int count, int samples, std::uint64_t seed) const;
  /// 1 when every ray from stratified points of the shooter to the centroids of those of
  /// `count` elements (picked evenly over them) whose fronts face each point is unblocked,
  /// 0 when every one is blocked or none faces, 0.5 (cast no further) when some are and
  /// some are not; of `samples` in all, counting the rays cast into `rays`.
  double VisibleFractionOfFacing(
    int shooter, const int* elements, int count, int samples, std::uint64_t seed, long long& rays) const;
  /// The cone of the patch's normals (spread 0 for a flat patch, more for a face cluster).
  const NormalCone& Cone(int patch) const { return PatchCone[patch]; }
  /// True when the patch is flat: one element, or coplanar elements with one outline.
  bool Planar(int patch) const
  {
    return !PatchOutline[patch].empty() || Geometry.PatchElements[patch].size() == 1;
  }
  /// Each patch's outline as one loop of corners (empty where it is not one simple loop).
  const std::vector<std::vector<Vec3>>& PatchLoops() const { return PatchLoop; }
  const std::vector<Vec3>& Centres() const { return PatchCentre; }

  /// Planes of elements with scene geometry strictly behind them: the only surfaces that
  /// can block a pair. -1 when not examined.
  int BlockingPlanes() const { return CullVisibility ? BlockingPlaneCount : -1; }
  /// Pairs and rays skipped by the culling since construction.
  long long PairsUnblockable() const { return Unblockable; }
  long long RaysSkipped() const { return Skipped; }

private:
  long long Analytic(int patch, int samples, std::vector<double>& factors);
  long long Hemicube(int patch, int resolution, std::vector<double>& factors);
  long long MonteCarlo(int patch, int samples, int shot, std::vector<double>& factors);
  void BuildOutlines();
  void BuildLoops();
  /// Turns F(patch -> e) sums in `factors` into F(e -> patch) by reciprocity, for a
  /// shooter whose power leaves from `shooterArea`.
  void Reciprocal(int patch, double shooterArea, std::vector<double>& factors) const;
  /// Closest polygon hit by the ray that faces the ray (receives on its front), else -1.
  int FrontHit(const Vec3& origin, const Vec3& direction) const;

  const SceneMesh& Mesh;
  const SceneGeometry& Geometry;
  const Visibility& Rays;
  const WorkerPool& Pool;
  std::vector<Vec3> Loops; ///< element points, laid out like Mesh.Connectivity
  struct SampleTriangle
  {
    Vec3 A, B, C, Normal;
  };
  std::vector<std::vector<SampleTriangle>> PatchTriangles;
  /// Per patch, each of its triangles' cumulative area fraction, ending at 1: apart from
  /// the triangles, so PickTriangle's search reads 8 bytes a step, not a triangle's 96 (a
  /// shooter of a million-element room has thousands of triangles).
  std::vector<std::vector<double>> PatchCdf;
  std::vector<Vec3> PatchCentre, PatchNormal;
  std::vector<double> PatchRadius;
  std::vector<NormalCone> PatchCone;
  /// For a patch of many elements that are not coplanar (a face cluster of a curved
  /// surface): form factors to it in log time. Null for the others.
  std::vector<std::unique_ptr<ClusterTree>> Trees;
  void BuildTrees();
  /// Outline of each planar patch (interior edges cancelled), as start/end point pairs;
  /// empty for a patch whose elements are not coplanar.
  std::vector<std::vector<Vec3>> PatchOutline;
  std::vector<std::vector<Vec3>> PatchLoop;
  std::vector<char> ConvexLoop;
  /// For a patch with sheltered elements, its other elements: where patch links land, so
  /// where visibility to a linked shooter is sampled (empty for the other patches).
  std::vector<std::vector<int>> OpenElements;
  /// Per patch: 1 when all of its probe rays reach a receiver's front, 0 when not, -1 unknown.
  std::vector<signed char> ClosedView;
  bool SeesClosedScene(int patch);
  /// Hemicube pixel directions in the local frame (x, y, z = normal) and delta factors.
  std::vector<Vec3> CubeDirections;
  std::vector<double> CubeWeights;
  int CubeResolution = 0;
  std::vector<int> HitElement; ///< per ray, -1 for a miss
  std::vector<double> HitWeight;
  double Epsilon = 0;

  const SampleTriangle& PickTriangle(int patch, double u) const;
  /// The r-th of `samples` points stratified over the patch, just off its front;
  /// `picked` (if given) receives the triangle it lies on.
  Vec3 SamplePoint(int patch, int r, int samples, SampleStream& random, const SampleTriangle** picked = nullptr) const;
  /// The same, as a receiver: over the patch's unsheltered elements (their centroids).
  Vec3 ReceiverPoint(int patch, int r, int samples, SampleStream& random) const;
  int VisibleRays(int patch, int element, int samples) const;

  void FindBlockers();
  bool MayBeBlocked(int patch, int element) const;
  bool ShaftMayBeBlocked(const Bounds& from, const Bounds& to) const;
  bool CullVisibility = false;
  const std::vector<char>* Receivers = nullptr;
  int BlockingPlaneCount = 0;
  std::vector<Bounds> ElementBox, PatchBox, Blockers;
  Bounds AllBlockers;
  std::atomic<long long> Unblockable{ 0 }, Skipped{ 0 };
};

} // namespace radiosity

#endif
