// Finer elements where lamps light a surface up close. Direct light from a lamp changes on
// the scale of the distance to it, so an element of the scene's size interpolates a peak
// by a lamp (or a shadow edge a few centimetres from it) over its whole width.
#ifndef RadiosityCore_LampGrading_h
#define RadiosityCore_LampGrading_h

#include "Base/Vec3.h"
#include "Geometry/Polygon.h"

#include <cmath>
#include <memory>
#include <unordered_map>
#include <vector>

namespace radiosity
{

/// A lamp as the grading sees it: where it is, which way it shines, how large. A lamp
/// polygon has its corners; a luminaire is a point (no corners, radius 0).
struct LampSpot
{
  Vec3 Centre;
  Vec3 Normal; ///< unit; a lamp lights the side its normal points to (zero: every side)
  double Radius = 0; ///< of the sphere around its corners
  std::vector<Vec3> Corners;
};

/// The lamps of a scene, binned in a grid so that a patch looks only at those near it (a
/// scene may mark thousands of small polygons as lamps). Copies share the bins.
class LampSpots
{
public:
  LampSpots() = default;
  /// `cell`: the bins' size, about the reach of the grading (ElementSize / LampGrading).
  LampSpots(std::vector<LampSpot> spots, double cell);
  bool empty() const { return !Bins || Bins->Spots.empty(); }
  void clear() { Bins.reset(); }
  /// Calls visit(lamp) for every lamp that may come within `reach` of the sphere (centre,
  /// radius), and perhaps a few more (callers measure the distance themselves).
  template <typename Visit>
  void Near(const Vec3& centre, double radius, double reach, const Visit& visit) const;

private:
  struct Binned
  {
    std::vector<LampSpot> Spots;
    double Cell = 1;
    double LargestRadius = 0;
    std::unordered_map<long long, std::vector<int>> Bins; ///< by the cell of a lamp's centre
  };
  std::shared_ptr<const Binned> Bins;
};

/// The lamp polygons of a scene (`lamps[i]` set for polygon i) and the point lamps
/// (luminaires) beside them, binned by `cell`.
LampSpots FindLampSpots(const std::vector<Vec3>& points, const std::vector<int>& offsets,
  const std::vector<int>& connectivity, const std::vector<char>& lamps, double cell,
  const std::vector<LampSpot>& pointLamps = {});

/// The element size wanted over a convex patch (its `count` corners): `elementSize`, or
/// where the patch faces a lamp `distance` away (the nearest corner of either to the
/// other), `grading * distance`, never below `elementSize / 4`. A patch behind a lamp, or
/// facing away, keeps the size.
double GradedElementSize(const LampSpots& lamps, const Vec3* corners, int count, double elementSize, double grading);

class Visibility;

/// The element size wanted over a convex patch where a shadow's edge may cross it: where
/// some of its points see a lamp within `reach` and others do not (`rays`, the scene's
/// polygons), `grading` times `elementSize` (never below a quarter of it); else
/// `elementSize`. Across such an edge direct light changes on the scale of its penumbra,
/// which a furniture leg or a door's head makes a few centimetres wide, and the points of
/// coarser elements smear it over their width.
double ShadowGradedSize(const LampSpots& lamps, const Visibility* rays, const Vec3* corners, int count,
  double elementSize, double grading, double reach);

/// Whether any patch of the polygon `loop` may be graded: a lamp within the reach of the
/// grading (`elementSize / grading`) of its bounding sphere. Cheap, and never wrong when false.
bool MayGrade(const LampSpots& lamps, const std::vector<Vec3>& loop, double elementSize, double grading);

template <typename Visit>
void LampSpots::Near(const Vec3& centre, double radius, double reach, const Visit& visit) const
{
  if (!Bins)
  {
    return;
  }
  const double grow = radius + reach + Bins->LargestRadius; // a lamp's centre within this
  const double lo[3] = { centre.x - grow, centre.y - grow, centre.z - grow };
  const double hi[3] = { centre.x + grow, centre.y + grow, centre.z + grow };
  long long first[3] = { 0, 0, 0 }, last[3] = { -1, -1, -1 };
  double cells = std::isfinite(lo[0] + lo[1] + lo[2] + hi[0] + hi[1] + hi[2]) ? 1.0 : HUGE_VAL;
  for (int a = 0; a < 3 && cells <= static_cast<double>(Bins->Bins.size()); ++a)
  {
    const double from = std::floor(lo[a] / Bins->Cell), to = std::floor(hi[a] / Bins->Cell);
    cells *= to - from + 1;
    if (cells <= static_cast<double>(Bins->Bins.size())) // else all lamps: no cast out of range
    {
      first[a] = static_cast<long long>(from);
      last[a] = static_cast<long long>(to);
    }
  }
  if (!(cells <= static_cast<double>(Bins->Bins.size())))
  {
    for (const LampSpot& lamp : Bins->Spots) // fewer bins than cells to look in: all of them
    {
      visit(lamp);
    }
    return;
  }
  for (long long x = first[0]; x <= last[0]; ++x)
    for (long long y = first[1]; y <= last[1]; ++y)
      for (long long z = first[2]; z <= last[2]; ++z)
      {
        const auto bin = Bins->Bins.find(CellHash(x, y, z)); // a collision: a few more lamps
        if (bin != Bins->Bins.end())
        {
          for (int i : bin->second)
          {
            visit(Bins->Spots[i]);
          }
        }
      }
}

} // namespace radiosity

#endif
