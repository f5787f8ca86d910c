#include "Mesh/LampGrading.h"
#include "Geometry/Visibility.h"
#include "Geometry/Polygon.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

namespace radiosity
{

namespace
{
/// The sphere around a loop's corners: its centroid, and the farthest corner's distance.
/// Every point of the (convex hull of the) loop lies within it.
std::pair<Vec3, double> CornerSphere(const Vec3* corners, int count)
{
  const Vec3 centre = PolygonCentroid(corners, count);
  double radius = 0;
  for (int k = 0; k < count; ++k)
  {
    radius = std::max(radius, Norm(corners[k] - centre));
  }
  return { centre, radius };
}
} // namespace

LampSpots::LampSpots(std::vector<LampSpot> spots, double cell)
{
  auto binned = std::make_shared<Binned>();
  binned->Spots = std::move(spots);
  binned->Cell = cell > 0 && std::isfinite(cell) ? cell : 1.0;
  for (size_t i = 0; i < binned->Spots.size(); ++i)
  {
    const Vec3& c = binned->Spots[i].Centre;
    binned->LargestRadius = std::max(binned->LargestRadius, binned->Spots[i].Radius);
    binned->Bins[CellHash(static_cast<long long>(std::floor(c.x / binned->Cell)),
      static_cast<long long>(std::floor(c.y / binned->Cell)), static_cast<long long>(std::floor(c.z / binned->Cell)))]
      .push_back(static_cast<int>(i));
  }
  Bins = std::move(binned);
}

LampSpots FindLampSpots(const std::vector<Vec3>& points, const std::vector<int>& offsets,
  const std::vector<int>& connectivity, const std::vector<char>& lamps, double cell,
  const std::vector<LampSpot>& pointLamps)
{
  std::vector<LampSpot> spots = pointLamps;
  for (size_t i = 0; i < lamps.size() && i + 1 < offsets.size(); ++i)
  {
    if (!lamps[i])
    {
      continue;
    }
    const std::vector<Vec3> loop = GatherLoop(points, offsets, connectivity, static_cast<int>(i));
    const Vec3 newell = loop.size() >= 3 ? NewellVector(loop.data(), static_cast<int>(loop.size())) : Vec3{};
    if (!(Norm(newell) > 0))
    {
      continue; // the solver names a degenerate lamp
    }
    LampSpot spot;
    std::tie(spot.Centre, spot.Radius) = CornerSphere(loop.data(), static_cast<int>(loop.size()));
    spot.Normal = Normalized(newell);
    spot.Corners = loop;
    spots.push_back(spot);
  }
  return spots.empty() ? LampSpots() : LampSpots(std::move(spots), cell);
}

namespace
{
/// The distance from `p` to the segment a-b.
double ToSegment(const Vec3& p, const Vec3& a, const Vec3& b)
{
  const Vec3 ab = b - a;
  const double length2 = Dot(ab, ab);
  const double t = length2 > 0 ? std::min(std::max(Dot(p - a, ab) / length2, 0.0), 1.0) : 0.0;
  return Norm(p - (a + ab * t));
}

/// The distance from `p` to the flat convex polygon (its inside, not only its outline).
double ToConvexPolygon(const Vec3& p, const Vec3* corners, int count, const Vec3& unitNormal)
{
  const double height = Dot(p - corners[0], unitNormal);
  const Vec3 foot = p - unitNormal * height;
  bool inside = true;
  double outline = 1e300;
  for (int k = 0; k < count; ++k)
  {
    const Vec3& a = corners[k];
    const Vec3& b = corners[(k + 1) % count];
    inside = inside && Dot(Cross(b - a, foot - a), unitNormal) >= 0;
    outline = std::min(outline, ToSegment(p, a, b));
  }
  return inside ? std::fabs(height) : outline;
}
/// How far the patch is from the lamp: the nearest corner of either to the other (two
/// flat convex polygons that do not cross are nearest at a corner, or along two edges,
/// which this overrates a little).
double Apart(const LampSpot& lamp, const Vec3* corners, int count, const Vec3& unitNormal)
{
  double apart = ToConvexPolygon(lamp.Centre, corners, count, unitNormal);
  for (const Vec3& c : lamp.Corners)
  {
    apart = std::min(apart, ToConvexPolygon(c, corners, count, unitNormal));
  }
  for (int k = 0; k < count && lamp.Corners.size() >= 3; ++k) // a point lamp has no polygon
  {
    apart = std::min(apart,
      ToConvexPolygon(corners[k], lamp.Corners.data(), static_cast<int>(lamp.Corners.size()), lamp.Normal));
  }
  return apart;
}
/// A flat patch's unit normal and the sphere around its corners; false where it has no area.
bool FrameOf(const Vec3* corners, int count, Vec3& normal, Vec3& centre, double& radius)
{
  const Vec3 newell = NewellVector(corners, count);
  if (!(Norm(newell) > 0))
  {
    return false;
  }
  normal = Normalized(newell);
  std::tie(centre, radius) = CornerSphere(corners, count);
  return true;
}
} // namespace

double GradedElementSize(const LampSpots& lamps, const Vec3* corners, int count, double elementSize, double grading)
{
  if (lamps.empty() || !(grading > 0) || count < 3)
  {
    return elementSize;
  }
  Vec3 normal, centre;
  double radius = 0;
  if (!FrameOf(corners, count, normal, centre, radius))
  {
    return elementSize;
  }
  double size = elementSize;
  lamps.Near(centre, radius, elementSize / grading, [&](const LampSpot& lamp) {
    // Lit only where some corner is in front of the lamp and the lamp is in front of the patch.
    bool front = !(Dot(lamp.Normal, lamp.Normal) > 0); // a lamp shining every way
    for (int k = 0; k < count && !front; ++k)
    {
      front = Dot(corners[k] - lamp.Centre, lamp.Normal) > 0;
    }
    // Within reach only, exactly: the bins hand over a few more lamps, which must not count.
    const double apart = front && Dot(lamp.Centre - centre, normal) > 0 ? Apart(lamp, corners, count, normal) : HUGE_VAL;
    if (apart < elementSize / grading)
    {
      size = std::min(size, grading * apart);
    }
  });
  return std::max(size, elementSize / 4);
}

namespace
{
/// Points of a convex patch to test for a shadow's edge: its centre and, pulled a tenth of
/// the way in (a corner may touch a wall standing on it), its corners and edge middles;
/// lifted off its plane.
std::vector<Vec3> ShadowProbes(const Vec3* corners, int count, const Vec3& centre, const Vec3& normal, double lift)
{
  std::vector<Vec3> probes{ centre + normal * lift };
  for (int k = 0; k < count; ++k)
  {
    const Vec3 middle = (corners[k] + corners[(k + 1) % count]) * 0.5;
    probes.push_back(corners[k] + (centre - corners[k]) * 0.1 + normal * lift);
    probes.push_back(middle + (centre - middle) * 0.1 + normal * lift);
  }
  return probes;
}

/// Whether some of `probes` see the lamp and others do not (those behind it aside).
bool EdgeOfShadow(const Visibility& rays, const LampSpot& lamp, const std::vector<Vec3>& probes)
{
  const bool oneSided = Dot(lamp.Normal, lamp.Normal) > 0;
  const Vec3 target = lamp.Centre + lamp.Normal * (1e-3 * std::max(lamp.Radius, 1e-300)); // off its face
  int open = 0, facing = 0;
  for (const Vec3& p : probes)
  {
    if (!oneSided || Dot(p - lamp.Centre, lamp.Normal) > 0)
    {
      ++facing;
      open += rays.Occluded(p, target) ? 0 : 1;
    }
  }
  return open > 0 && open < facing;
}
} // namespace

double ShadowGradedSize(const LampSpots& lamps, const Visibility* rays, const Vec3* corners, int count,
  double elementSize, double grading, double reach)
{
  if (!rays || lamps.empty() || !(grading > 0) || count < 3)
  {
    return elementSize;
  }
  Vec3 normal, centre;
  double radius = 0;
  if (!FrameOf(corners, count, normal, centre, radius))
  {
    return elementSize;
  }
  const std::vector<Vec3> probes = ShadowProbes(corners, count, centre, normal, 1e-4 * std::max(radius, 1e-300));
  bool edge = false;
  lamps.Near(centre, radius, reach, [&](const LampSpot& lamp) {
    // Within reach only, exactly (the bins hand over a few more), and in front of the patch.
    edge = edge || (Dot(lamp.Centre - centre, normal) > 0 && Norm(lamp.Centre - centre) <= reach + radius &&
                     EdgeOfShadow(*rays, lamp, probes));
  });
  return edge ? std::max(grading, 0.25) * elementSize : elementSize;
}

bool MayGrade(const LampSpots& lamps, const std::vector<Vec3>& loop, double elementSize, double grading)
{
  if (lamps.empty() || !(grading > 0) || loop.size() < 3)
  {
    return false;
  }
  Vec3 centre;
  double radius = 0;
  std::tie(centre, radius) = CornerSphere(loop.data(), static_cast<int>(loop.size()));
  // Every point of the polygon, so of its patches, is within `radius` of `centre`.
  bool near = false;
  lamps.Near(centre, radius, elementSize / grading, [&](const LampSpot& lamp) {
    near = near || Norm(lamp.Centre - centre) < elementSize / grading + radius + lamp.Radius;
  });
  return near;
}

} // namespace radiosity
