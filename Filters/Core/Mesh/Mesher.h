// Two-level uniform meshing for substructured radiosity: polygons -> patches -> elements.
#ifndef RadiosityCore_Mesher_h
#define RadiosityCore_Mesher_h

#include "Mesh/ContactCuts.h"
#include "Mesh/LampGrading.h"
#include "Mesh/WholeSceneCuts.h"
#include "Base/Vec3.h"

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace radiosity
{

struct MesherOptions
{
  double PatchSize = 1.0;   ///< longest patch edge, world units (slivers: by area)
  double ElementSize = 0.25; ///< longest element edge, world units
  long long MaximumElements = 20000000; ///< refuse settings that would exhaust memory
  /// Join adjacent flat same-material triangle pairs into quads first (see TrianglePairs.h).
  bool MergeTriangles = true;
  /// Polygons that fit in one patch share it with the other such polygons of their flat,
  /// same-material surface in the same PatchSize cell of the plane.
  bool SharePatches = true;
  /// Small patches of a curved surface (its tessellation's many polygons, each on its own
  /// plane) are grouped into face clusters of about PatchSize whose normals stay within
  /// this many degrees of each other (FaceClusters.h); 0: never.
  double ClusterAngle = 30;
  /// Element budget (0: none): above it the smallest larger element size that fits is used.
  double ElementBudget = 0;
  /// How finely the coordinates were given (SceneMesh::PointQuantum: float input's step at
  /// its farthest coordinate, 0 for double): corners may sit that far off, and the
  /// tests of what is straight, convex or flat allow it.
  double PointQuantum = 0;
  /// The whole scene where the polygons are one process's piece of it: surfaces of other
  /// pieces standing on these cut them too (see ContactCuts.h). Null: the polygons are all.
  const PolygonArrays* WholeScene = nullptr;
  /// With WholeScene: its surfaces and lamps and where these polygons begin in it; the
  /// coincident copies and overlapping faces are then found over the whole scene
  /// (WholeSceneCuts.h), and warnings name its cells. Null: found among these polygons.
  const WholeSceneSurfaces* WholeSurfaces = nullptr;
  /// Per input polygon, 1 where it emits (empty: none does). Of coincident copies in other
  /// materials one is kept (CoincidentCopies.h): a lamp over the surface it doubles.
  std::vector<char> Lamps;
  /// Elements on surfaces a lamp lights from up close are made finer (LampGrading.h): at a
  /// distance d, LampGrading * d, down to a quarter of ElementSize; 0: one size everywhere.
  /// Quads grade whole rows and columns of their grid (no T-junctions inside a polygon),
  /// triangles their whole lattice; lamps, and convex polygons of many corners meshed by
  /// area (AreaGrid.h), are not graded.
  double LampGrading = 0;
  /// Where a shadow's edge crosses a patch a lamp lights (some of its points see the lamp,
  /// others do not), its elements are ShadowGrading times ElementSize (down to a quarter);
  /// 0: never. Graded as LampGrading grades (whole rows and columns of a quad's grid), by
  /// the lamps within six times LampGrading's reach; only with LampGrading.
  double ShadowGrading = 0;
  /// Lamps at points (the scene's luminaires): graded by as the lamp polygons are, each
  /// with the normal of the side it lights (zero where it lights every side).
  std::vector<LampSpot> PointLamps;
  /// The lamps the grading looks at: filled by MeshPolygons from Lamps and PointLamps (the
  /// whole scene's with WholeSurfaces).
  LampSpots GradingLamps;
  /// The scene's polygons for ShadowGrading's test: filled by MeshPolygons.
  std::shared_ptr<const Visibility> ShadowRays;
  std::function<bool(double)> Progress; ///< return false to abort
  /// Told, before meshing, when the budget changed the element size or the mesh is huge.
  std::function<void(const std::string&)> Warning;
};

struct MeshedPolygons
{
  std::vector<Vec3> Points;
  std::vector<int> Offsets{ 0 };
  std::vector<int> Connectivity;
  std::vector<int> SourcePolygon; ///< input polygon each element came from
  std::vector<int> MeshedPolygon; ///< the mesher's polygon (input paired, warped split) it came from
  std::vector<int> PatchId;       ///< 0..Patches-1
  int Patches = 0;
  int MergedTrianglePairs = 0; ///< triangle pairs meshed as one quad
  int ClusteredPatches = 0;    ///< small patches merged into face clusters
  double ElementSize = 0;      ///< the element size used (see ElementBudget)
};

/// The number of elements MeshPolygons makes at these sizes without meshing, for a warning
/// or a budget before the work: exact for valid input of flat polygons where MeshPolygons
/// merges no triangle pairs and grades no elements (ElementCounter with the options counts
/// what it makes always, LampGrading included).
/// `wholeScene`: as MesherOptions::WholeScene.
double CountElements(const std::vector<Vec3>& points, const std::vector<int>& offsets,
  const std::vector<int>& connectivity, double patchSize, double elementSize,
  const PolygonArrays* wholeScene = nullptr);

/// CountElements for many sizes (a budget's search, a panel's estimate as it is typed):
/// the contacts are found once. Holds references to the arrays.
class ElementCounter
{
public:
  ElementCounter(const std::vector<Vec3>& points, const std::vector<int>& offsets,
    const std::vector<int>& connectivity, const PolygonArrays* wholeScene = nullptr);
  /// Counts what MeshPolygons makes of these polygons with `options`: triangle pairs
  /// merged as it merges them (MergeTriangles, with the same surface keys), contacts cut
  /// (options.WholeScene), exactly, without meshing. Sizes are the call's, not options'.
  ElementCounter(const std::vector<Vec3>& points, const std::vector<int>& offsets,
    const std::vector<int>& connectivity, const std::vector<int>& surfaceKey, const MesherOptions& options);
  ~ElementCounter();
  double operator()(double patchSize, double elementSize) const;

private:
  struct Internals;
  std::unique_ptr<Internals> Impl;
};

/// The smallest element size, at least `elementSize`, whose mesh has at most `budget`
/// elements (the patch size when even one element per patch is over it).
double ElementSizeForBudget(const std::vector<Vec3>& points, const std::vector<int>& offsets,
  const std::vector<int>& connectivity, double patchSize, double elementSize, double budget);

/// The same search over any count of elements by size (the whole scene's, for a mesh
/// split over several processes: every process makes the same calls in the same order).
double ElementSizeForBudget(
  const std::function<double(double)>& count, double patchSize, double elementSize, double budget);

/// Splits each planar polygon (convex quads on a bilinear grid, others ear-clipped into
/// triangles and split on a barycentric lattice) into patches with edges <= PatchSize (a
/// sliver triangle, narrower than a quarter of its length, into patches of about that area), and each patch
/// into elements with edges <= ElementSize. Points are shared between elements of input
/// polygons that lie in one plane with the same `surfaceKey` (the caller's material id)
/// and touch; everywhere else they are split, so smoothing over shared vertices never
/// mixes two materials or orientations. Where a polygon stands on another (a wall on a
/// floor), the elements it stands across are cut along its foot (ContactCuts.h). The
/// connectivity is held in OpenMesh meshes, one per surface. Returns an empty string or
/// an error naming the problem.
std::string MeshPolygons(const std::vector<Vec3>& points, const std::vector<int>& offsets,
  const std::vector<int>& connectivity, const std::vector<int>& surfaceKey,
  const MesherOptions& options, MeshedPolygons& out);

/// Sizes that suit a scene whatever its unit, placement and orientation: PatchSize about
/// a sixth of the scene's extent (twice the largest distance of a corner from the
/// corners' mean; a box's diagonal), rounded down to 1, 2, 2.5 or 5 times a power of ten,
/// and ElementSize a quarter of it (1 and 0.25 for a 4 x 2.5 x 4 room in metres; 1000
/// and 250 in mm).
struct SuggestedSizes
{
  double PatchSize = 1.0;
  double ElementSize = 0.25;
  double Area = 0.0;     ///< the polygons' total area
  double Elements = 0.0; ///< the elements these sizes make (CountElements)
};

/// A sixth of the scene's extent (its span, which turning does not change), rounded down to
/// 1, 2, 2.5 or 5 times a power of ten; 0 for an empty or degenerate scene.
double SuggestPatchSize(const std::vector<Vec3>& points, const std::vector<int>& connectivity);

/// A sixth of `span`, rounded down as SuggestPatchSize rounds; 0 for no span.
double PatchSizeForSpan(double span);

/// The sizes to mesh at: a patch size of 0 (or less) takes `suggestedPatch` (1 where there
/// is none), an element size of 0 a quarter of the patch size in use.
inline std::pair<double, double> SizesInUse(double patch, double element, double suggestedPatch)
{
  const double p = patch > 0 ? patch : (suggestedPatch > 0 ? suggestedPatch : 1.0);
  return { p, element > 0 ? element : p / 4.0 };
}

/// The suggestion for a scene; the defaults (1, 0.25) for an empty or degenerate one.
/// `span` (where positive) stands for the scene's own: a model set in a room is meshed
/// for the model, not for the room around it (a 1.5 m figure in its 4.5 m room got
/// 0.6 m elements, and a blocky shadow).
SuggestedSizes SuggestMeshSizes(const std::vector<Vec3>& points, const std::vector<int>& offsets,
  const std::vector<int>& connectivity, double span = 0);

} // namespace radiosity

#endif
