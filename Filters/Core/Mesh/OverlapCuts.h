// Coplanar faces that overlap without being copies (a slab drawn over a floor, a panel
// traced twice with other corners, two exports of one wall merged, a poster on a wall):
// each would receive the full light where they overlap, so the surfaces around them would
// get more than was emitted. A lamp keeps the overlap, else the earlier face; the other
// keeps only what is left uncovered. Faces of different surfaces that overlap are said.
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
  /// Pairs of input polygons (kept, cut) of different surfaces that overlap in one plane,
  /// facing one side: which one was meant cannot be told, so they are said.
  std::vector<std::pair<int, int>> Differing;
  /// Pairs (kept, cut) of input polygons of different surfaces where the kept one, not a
  /// lamp, lies wholly on the other's surface (a poster on its wall): meant, so said apart
  /// from Differing, whose choice is only the order.
  std::vector<std::pair<int, int>> OnTop;
  /// Pairs of input polygons that are lamps of different lights and overlap: not cut (each
  /// emits the power it was given), to be said.
  std::vector<std::pair<int, int>> LampsKept;
};

/// Cuts every convex polygon of `polygons` by the convex polygons before it in keeping
/// order (the lamps, where `lamps` marks them by source id, then the rest, each in input
/// order) that lie in its plane (within `tolerance`, a length), face the same side and
/// overlap it by more than `tolerance` across; each cut polygon becomes the convex pieces
/// of what they leave. Where any is cut, `polygons.Points` becomes a copy of `points` with
/// the new corners after them (PointsOf), and the polygons index it. `surfaceKey` (per
/// source id) tells which overlaps are of different surfaces (Differing).
OverlapCuts CutOverlaps(const std::vector<Vec3>& points, const std::vector<int>& surfaceKey,
  const std::vector<char>& lamps, double tolerance, PairedPolygons& polygons);

} // namespace radiosity

#endif
