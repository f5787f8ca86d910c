// Which of the mesher's polygons lie in one plane, as far as their coordinates can tell.
// Float input far from the origin moves every corner by up to a float step, which turns a
// small polygon's normal by about that step over its width: one fixed angle would split a
// floor of small tiles into many surfaces there and keep it whole at the origin. So each
// polygon's normal is trusted as far as its noise allows, and surfaces are founded by the
// polygons whose normals are known best.
#ifndef RadiosityCore_CoplanarGroups_h
#define RadiosityCore_CoplanarGroups_h

#include "Base/Vec3.h"

#include <vector>

namespace radiosity
{

/// One polygon as the grouping sees it.
struct PolygonPlane
{
  Vec3 Normal;          ///< unit
  Vec3 Centroid;
  double Tolerance = 0; ///< how far (as a distance between unit normals) noise may turn `Normal`
  int Key = 0;          ///< only polygons of one key share a group (the caller's material)
};

/// The plane of `loop` (its normal by Newell's rule) whose corners may each be `noise` off
/// their places.
PolygonPlane PlaneOf(const std::vector<Vec3>& loop, double noise, int key);

struct CoplanarGroups
{
  std::vector<int> Group;   ///< per polygon, numbered in order of first appearance
  std::vector<int> Founder; ///< per group, the polygon whose plane it is (the best known)
};

/// Groups the polygons by plane: a polygon joins the group whose founder's normal is within
/// both polygons' tolerances of its own and whose founder's plane passes within
/// `offsetTolerance` (plus the founder's own uncertainty over the distance between them)
/// of its centroid, the nearest such; otherwise it founds a group. Polygons are taken from
/// the best-known normal to the worst, so the order of the input does not choose which
/// noisy polygon a plane is measured from; offsets are measured from `centre`.
CoplanarGroups GroupCoplanar(const std::vector<PolygonPlane>& planes, double offsetTolerance, const Vec3& centre);

} // namespace radiosity

#endif
