// Coplanar faces that overlap without being copies (a slab drawn over a floor, a panel
// traced twice with other corners, two exports of one wall merged): each would receive the
// full light where they overlap, so the surfaces around them would get more than was
// emitted. A later face of one surface keeps only what the earlier ones leave uncovered;
// faces of different surfaces that overlap are said, not cut.
#ifndef RadiosityCore_OverlapCuts_h
#define RadiosityCore_OverlapCuts_h

#include "Mesh/TrianglePairs.h"
#include "Base/Vec3.h"

#include <utility>
#include <vector>

namespace radiosity
{

struct OverlapCuts
{
  std::vector<int> Trimmed; ///< input polygons (source ids) cut to what earlier faces leave
  std::vector<int> Covered; ///< input polygons wholly under earlier ones: left out
  /// Pairs of input polygons (earlier, later) of different surfaces that overlap in one
  /// plane, facing one side: kept as they are, to be said (see CutFaces in the .cxx).
  std::vector<std::pair<int, int>> Differing;
};

/// Cuts every convex polygon of `polygons` by the earlier convex polygons of the same
/// `surfaceKey` (per source id) that lie in its plane (within `tolerance`, a length), face
/// the same side and overlap it by more than `tolerance` across; each cut polygon becomes
/// the convex pieces of what they leave. Where any is cut, `polygons.Points` becomes a copy
/// of `points` with the new corners after them (PointsOf), and the polygons index it.
/// Overlapping faces of different surfaces are listed in Differing, not cut.
OverlapCuts CutOverlaps(
  const std::vector<Vec3>& points, const std::vector<int>& surfaceKey, double tolerance, PairedPolygons& polygons);

} // namespace radiosity

#endif
