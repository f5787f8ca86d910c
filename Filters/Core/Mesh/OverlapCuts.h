// Coplanar faces that overlap without being copies (a slab drawn over a floor, a panel
// traced twice with other corners, a poster on a wall, a slab's edge over a wall's top):
// each would receive the full light where they overlap, so the surfaces around them would
// get more than was emitted. One of each overlapping pair keeps the overlap.
#ifndef RadiosityCore_OverlapCuts_h
#define RadiosityCore_OverlapCuts_h

#include "Mesh/TrianglePairs.h"
#include "Base/Vec3.h"

#include <vector>

namespace radiosity
{

struct OverlapCuts
{
  std::vector<int> Trimmed; ///< input polygons (source ids) cut to what others leave
  std::vector<int> Covered; ///< input polygons wholly under others: left out
};

/// Cuts every convex polygon of `polygons` by the others that lie in its plane (within
/// `tolerance`, a length), face the same side, overlap it by more than `tolerance` across
/// and win the overlap: of one `surfaceKey` (per source id) the earlier polygon wins, of
/// two the smaller (the detail drawn on a larger surface; the earlier if they are as
/// large). Each cut polygon becomes the convex pieces of what the winners leave. Where any
/// is cut, `polygons.points` becomes a copy of `points` with the new corners after them
/// (PointsOf), and the polygons index it.
OverlapCuts CutOverlaps(
  const std::vector<Vec3>& points, const std::vector<int>& surfaceKey, double tolerance, PairedPolygons& polygons);

} // namespace radiosity

#endif
