// A non-convex polygon of many corners (a CAD gear, a flange, a floor plan with bays) as a
// few convex pieces, so it is meshed by area like a convex one: its ear-clipped triangles
// alone are slivers from rim to rim (a 4,000-corner gear made 72,796 elements).
#ifndef RadiosityCore_ConvexPieces_h
#define RadiosityCore_ConvexPieces_h

#include "Base/Vec3.h"

#include <vector>

namespace radiosity
{

/// The polygon `loop` as convex pieces: ears clipped smallest first until the rest is
/// convex, then pieces merged across each diagonal where the union stays convex (Hertel &
/// Mehlhorn 1983; within `noise`, as IsConvex). Each lists indices into `loop` in its
/// order; straight corners clipped make no piece. Empty for a loop that crosses itself.
std::vector<std::vector<int>> ConvexPieces(const std::vector<Vec3>& loop, double noise);

} // namespace radiosity

#endif
