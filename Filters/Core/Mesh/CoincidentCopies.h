// Duplicate faces, everyday in CAD and BIM exports: two or three copies of one panel on the
// same side each receive the full light, so the surfaces around them get more than was
// emitted. They are found by their corners before meshing.
#ifndef RadiosityCore_CoincidentCopies_h
#define RadiosityCore_CoincidentCopies_h

#include "Mesh/TrianglePairs.h"
#include "Base/Vec3.h"

#include <utility>
#include <vector>

namespace radiosity
{

struct CoincidentCopies
{
  /// Input polygons (source ids) left out: a later copy of a polygon with the same corners,
  /// facing the same side, of the same surface (material and light).
  std::vector<int> Dropped;
  /// Pairs of input polygons with the same corners and side but other surfaces: kept both
  /// (which one is meant cannot be told), and said.
  std::vector<std::pair<int, int>> Differing;
};

/// Removes the coincident copies from `polygons` (corners equal to `tolerance`, a length).
CoincidentCopies DropCoincidentCopies(
  const std::vector<Vec3>& points, const std::vector<int>& surfaceKey, double tolerance, PairedPolygons& polygons);

} // namespace radiosity

#endif
