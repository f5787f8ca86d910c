// A work plane: the calculation grid a lighting designer lays at a height over a floor
// (EN 12464-1, CIE), and its illuminance statistics. The illuminance itself is gathered at
// the grid's points (IrradianceAtPoints, FinalGather.h).
#ifndef RadiosityCore_WorkPlane_h
#define RadiosityCore_WorkPlane_h

#include "Base/Vec3.h"

#include <array>
#include <string>
#include <vector>

namespace radiosity
{

/// EN 12464-1's grid spacing for an area whose longer side is `longer` metres:
/// p = 0.2 * 5^log10(d), at most 10 m (0.2 m at 1 m, 0.6 m at 5 m, 1 m at 10 m).
double WorkPlaneSpacing(double longer);

class Visibility;

/// Points at the centres of an Nu x Nv grid of cells over a rectangle, facing Normal.
struct WorkPlaneGrid
{
  std::vector<Vec3> Points; ///< row by row: point (i, j) at j * Nu + i (until some are left out)
  std::vector<std::array<int, 4>> Quads; ///< between neighbouring points, for a picture
  int Nu = 0, Nv = 0;
  Vec3 Normal;
  double SpacingU = 0, SpacingV = 0;
};

/// The grid `height` above the floor of `bounds` (xmin, xmax, ymin, ymax, zmin, zmax; the
/// floor the lowest plane along axis `up`, 0-2), `border` in from its sides, at most
/// `spacing` apart (0: WorkPlaneSpacing of the longer side); empty with `error` where the
/// area left or the height does not fit the bounds.
WorkPlaneGrid LayWorkPlane(const double bounds[6], int up, double height, double border, double spacing,
  std::string& error);

/// Which of `grid`'s points stand in a room (1): a floor, a surface facing up along axis
/// `up` (element normals `normals`), at most 1.5 `height` under the point, and where
/// `ceiling`, a surface facing down above it. A plane laid in a room's box so leaves out
/// its points over an open hall, outside a sloping roof or inside a wall. A height of 0
/// keeps every point.
std::vector<char> PointsInRoom(
  const WorkPlaneGrid& grid, int up, double height, bool ceiling, const Visibility& rays, const std::vector<Vec3>& normals);

/// `grid` with only the points `keep` marks and the quads between them.
WorkPlaneGrid KeptPoints(const WorkPlaneGrid& grid, const std::vector<char>& keep);

/// Mean, minimum, maximum and uniformity (minimum over mean, EN 12464-1's U0).
struct PlaneStatistics
{
  double Mean = 0, Minimum = 0, Maximum = 0, Uniformity = 0;
};
PlaneStatistics WorkPlaneStatistics(const std::vector<double>& illuminance);

} // namespace radiosity

#endif
