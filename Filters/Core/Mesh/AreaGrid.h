// Elements of a convex polygon with many corners (a CAD circle of thousands): the cells of
// a grid laid over its plane, cut to it. Its triangles would be slivers from rim to rim,
// each split along its length: a 10,000-corner disk of 3 m^2 made 363,000 elements.
#ifndef RadiosityCore_AreaGrid_h
#define RadiosityCore_AreaGrid_h

#include "Base/Vec3.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace radiosity
{

/// Pieces of at most `size` along `length`. A length within a millionth of a whole number
/// of sizes, or within twice `noise` (how far its ends may be off: MeshNoise), counts as
/// that number: VTK stores points as floats (7 digits), so a wall 5 m long rotated or
/// scaled comes back 5.0000003 m, and 10 km from the origin 5.0001 m, and would otherwise
/// gain a row.
inline int Divisions(double length, double size, double noise = 0)
{
  return std::max(1, static_cast<int>(std::ceil((length - 2 * noise) / size * (1 - 1e-6))));
}

/// Calls cell(corners, count, patch) for each cell of a grid of patches and elements (as a
/// quad's) over the convex `loop`'s extent in its plane, cut to the loop; pieces thinner
/// than `noise` are left out. The grid runs along the line from the first corner to the
/// one farthest from it, so it turns with the polygon. Returns the grid's patch count.
int SplitByAreaGrid(const std::vector<Vec3>& loop, double patchSize, double elementSize, double noise,
  const std::function<void(const Vec3*, int, int)>& cell);

/// The cells of the grid before they are cut (an upper bound of CountAreaGrid's, at once).
double AreaGridCells(const std::vector<Vec3>& loop, double patchSize, double elementSize);

/// The cells SplitByAreaGrid makes.
double CountAreaGrid(const std::vector<Vec3>& loop, double patchSize, double elementSize, double noise);

} // namespace radiosity

#endif
