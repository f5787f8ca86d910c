// Duplicate faces, everyday in CAD and BIM exports: two or three copies of one panel on the
// same side each receive the full light, so the surfaces around them get more than was
// emitted. They are found by their corners before meshing, and one of each set is kept.
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
  /// Pairs (kept, left out) of input polygons with the same corners and side but other
  /// surfaces. Which one is meant cannot be told, but both would receive the full light and
  /// create energy: the first lamp of the copies is kept (a lamp drawn over the ceiling tile
  /// it replaces), else the first of them; said, naming both.
  std::vector<std::pair<int, int>> Differing;
  /// Pairs of coincident lamps of different lights (or emission): both kept, as either
  /// alone would lose a light, and said.
  std::vector<std::pair<int, int>> LampsKept;
};

/// Removes the coincident copies from `polygons` (corners equal to `tolerance`, a length),
/// keeping one of each set: see CoincidentCopies. `lamps`: per source id, 1 where it emits
/// (empty: none does).
CoincidentCopies DropCoincidentCopies(const std::vector<Vec3>& points, const std::vector<int>& surfaceKey,
  const std::vector<char>& lamps, double tolerance, PairedPolygons& polygons);

} // namespace radiosity

#endif
