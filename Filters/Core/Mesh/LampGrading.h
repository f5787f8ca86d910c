// Finer elements where lamps light a surface up close. Direct light from a lamp changes on
// the scale of the distance to it, so an element of the scene's size interpolates a peak
// by a lamp (or a shadow edge a few centimetres from it) over its whole width.
#ifndef RadiosityCore_LampGrading_h
#define RadiosityCore_LampGrading_h

#include "Base/Vec3.h"

#include <vector>

namespace radiosity
{

/// A lamp polygon as the grading sees it: where it is, which way it shines, how large.
struct LampSpot
{
  Vec3 Centre;
  Vec3 Normal; ///< unit; a lamp lights the side its normal points to
  double Radius = 0; ///< of the sphere around its corners
  std::vector<Vec3> Corners;
};

/// The lamp polygons of a scene (`lamps[i]` set for polygon i). Lamps are few: a list.
std::vector<LampSpot> FindLampSpots(const std::vector<Vec3>& points, const std::vector<int>& offsets,
  const std::vector<int>& connectivity, const std::vector<char>& lamps);

/// The element size wanted over a convex patch (its `count` corners): `elementSize`, or
/// where the patch faces a lamp `distance` away (the nearest corner of either to the
/// other), `grading * distance`, never below `elementSize / 4`. A patch behind a lamp, or facing
/// away, keeps the size.
double GradedElementSize(const std::vector<LampSpot>& lamps, const Vec3* corners, int count, double elementSize,
  double grading);

/// Whether any patch of the polygon `loop` may be graded: a lamp within the reach of the
/// grading (`elementSize / grading`) of its bounding sphere. Cheap, and never wrong when false.
bool MayGrade(const std::vector<LampSpot>& lamps, const std::vector<Vec3>& loop, double elementSize, double grading);

} // namespace radiosity

#endif
