// Undoing a triangulating exporter: two triangles of one material that together form a flat
// convex quad become that quad again, which the mesher grids with a quarter of the elements.
#ifndef RadiosityCore_TrianglePairs_h
#define RadiosityCore_TrianglePairs_h

#include "Base/Vec3.h"

#include <vector>

namespace radiosity
{

struct PairedPolygons
{
  std::vector<int> Offsets{ 0 };
  std::vector<int> Connectivity;
  std::vector<int> Source; ///< the input polygon each output polygon came from (the first)
  int Merged = 0;          ///< triangle pairs joined into quads
  /// The points the polygons index where overlap cuts made new corners (the input's, then
  /// those); empty where they index the input's points.
  std::vector<Vec3> Points;
};

/// The points `polygons` index: their own where they have them, else `input`.
inline const std::vector<Vec3>& PointsOf(const PairedPolygons& polygons, const std::vector<Vec3>& input)
{
  return polygons.Points.empty() ? input : polygons.Points;
}

/// Joins triangles that share an edge (by position within `tolerance`, so split vertices
/// count), have the same `surfaceKey`, face the same way, lie in one plane (every corner
/// within `flatness` of the quad's, a length: the input's noise, so that float input far
/// from the origin pairs as it does near it) and form a convex quad; each triangle joins
/// its neighbour across its longest edge first (the diagonal a quad was split along).
/// Every other polygon passes through unchanged.
PairedPolygons MergeTrianglePairs(const std::vector<Vec3>& points, const std::vector<int>& offsets,
  const std::vector<int>& connectivity, const std::vector<int>& surfaceKey, double tolerance, double flatness);

} // namespace radiosity

#endif
