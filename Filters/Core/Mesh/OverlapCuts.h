// Coplanar faces that overlap without being copies (a slab drawn over a floor, a panel
// traced twice with other corners, a poster on a wall, a lamp drawn on its ceiling): each
// would receive the full light where they overlap, so the surfaces around them would get
// more than was emitted. One of them keeps the overlap; the others are cut around it.
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
/// and come before it in one order: lamps first (`lightIds` per source id, -1 for none;
/// may be empty), then the smaller surface (the area of the polygon's edge-connected
/// region of one `surfaceKey` and plane: a poster before the wall it hangs on, however
/// finely the wall is tessellated), then the earlier polygon. One total order, so exactly
/// one polygon keeps each overlap. Each cut polygon becomes the convex pieces of what is
/// left. Where any is cut, `polygons.points` becomes a copy of `points` with the new
/// corners after them (PointsOf), and the polygons index it.
OverlapCuts CutOverlaps(const std::vector<Vec3>& points, const std::vector<int>& surfaceKey,
  const std::vector<int>& lightIds, double tolerance, PairedPolygons& polygons);

} // namespace radiosity

#endif
