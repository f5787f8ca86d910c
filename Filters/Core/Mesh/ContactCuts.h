// Where one surface stands on another (a wall on a floor, a box on a table), the lower
// surface is cut along the contact line, so that no element lies on both sides of it.
// An element straddling a sealed wall would receive light on one side and show or shoot
// it on the other: light behind the wall would not be exactly zero.
#ifndef RadiosityCore_ContactCuts_h
#define RadiosityCore_ContactCuts_h

#include "Base/Vec3.h"

#include <vector>

namespace radiosity
{

/// An edge of another polygon lying on a polygon's plane (projected onto it).
struct ContactSegment
{
  Vec3 A, B;
};

/// Polygons as flat arrays (as SceneMesh and the mesher hold them), by reference.
struct PolygonArrays
{
  const std::vector<Vec3>& Points;
  const std::vector<int>& Offsets;
  const std::vector<int>& Connectivity;
};

/// For every polygon of `polygons`, the edges of the non-parallel polygons of `standing`
/// whose two ends lie within `touch` of its plane and which run through its inside (not
/// along its outline only, as where neighbouring walls meet a floor along its border).
/// `standing` is the whole scene: the polygons themselves, or more where they are one
/// process's piece of it.
std::vector<std::vector<ContactSegment>> FindContacts(
  const PolygonArrays& polygons, const PolygonArrays& standing, double touch);

/// Cuts the convex elements of one polygon along its contact segments. The segments are
/// binned on a grid in the plane, so an element meets only those near it (a floor with
/// thousands of boxes on it costs elements plus segments, not their product).
class ContactCutter
{
public:
  /// `normal`: the polygon's; parts thinner than `tolerance` are not made.
  ContactCutter(const std::vector<ContactSegment>& segments, const Vec3& normal, double tolerance);

  /// The parts of one convex element, cut by every segment that crosses its inside along
  /// the segment's line; returns their number, or 0 (and `parts` untouched) where no
  /// segment cuts it: most elements, which then cost no copy.
  int Cut(const Vec3* loop, int count, std::vector<std::vector<Vec3>>& parts) const;

private:
  void Cells(const Vec3* points, int count, int& x0, int& y0, int& x1, int& y1) const;

  const std::vector<ContactSegment>& Segments;
  Vec3 Normal, U, V, Origin;
  double Tolerance;
  double Lo[2] = { 0, 0 }, Cell = 1;
  int Resolution = 1;
  std::vector<std::vector<int>> Grid;
  mutable std::vector<int> Near; ///< scratch: one cutter serves one thread
};

} // namespace radiosity

#endif
