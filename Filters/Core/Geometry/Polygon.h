// Planar convex polygon helpers shared by the form-factor code, the solver and the mesher.
#ifndef RadiosityCore_Polygon_h
#define RadiosityCore_Polygon_h

#include "Base/Vec3.h"

#include <array>
#include <string>
#include <vector>

namespace radiosity
{

/// Axis-aligned bounds: of a point set, or grown point by point from empty.
struct Bounds
{
  Vec3 Lo{ 1e300, 1e300, 1e300 }, Hi{ -1e300, -1e300, -1e300 }; ///< empty: Lo above Hi
  Bounds() = default;
  /// Of `points` (none: both corners at the origin).
  explicit Bounds(const std::vector<Vec3>& points);
  void Add(const Vec3& p);
  void Add(const Bounds& b); ///< an empty `b` adds nothing
  /// True when the boxes overlap or lie within `tolerance` of each other.
  bool Overlaps(const Bounds& b, double tolerance) const;
  double Diagonal() const { return Norm(Hi - Lo); }
  Vec3 Centre() const { return (Lo + Hi) * 0.5; }
};

/// A plane as a hash key: the unit normal in steps of `normalStep` and `offset`, the plane's
/// distance along the normal past the scene's centre, in steps of `offsetStep`. Measure the
/// offset from the scene's centre, not the origin: far from the origin the normal's
/// round-off times the distance would split one floor into many keys. Planes closer than a
/// step can still round apart: a caller that must join them probes the neighbouring keys
/// (the mesher's surfaces use CoplanarGroups instead; the shooters' blocker groups need not).
std::array<long long, 4> PlaneKey(const Vec3& unitNormal, double offset, double normalStep, double offsetStep);

/// A point as a hash key: each coordinate in steps of `step` (welding equal points).
std::array<long long, 3> QuantizedPoint(const Vec3& p, double step);

/// One hash of a grid cell's three indices (the hashed grids of the mesher share it).
inline long long CellHash(long long x, long long y, long long z)
{
  return (x * 73856093LL) ^ (y * 19349663LL) ^ (z * 83492791LL);
}

/// One id per place, numbered in order of first appearance: each point takes the id of the
/// first point before it within `tolerance` (found in the 27 cells of that size around it,
/// so two points that close never round apart, as hashing alone lets them where a cell
/// border falls between). Points i and j are the same place when ids[i] == ids[j].
std::vector<int> WeldedPointIds(const std::vector<Vec3>& points, double tolerance);

/// Newell's vector: normal direction of the right-hand-rule loop, length = 2 * area.
/// Robust for non-planar or nearly degenerate loops, unlike a single cross product.
Vec3 NewellVector(const Vec3* loop, int count);

inline double PolygonArea(const Vec3* loop, int count)
{
  return 0.5 * Norm(NewellVector(loop, count));
}

Vec3 PolygonCentroid(const Vec3* loop, int count);

/// The length of the closed loop's edges.
inline double Perimeter(const std::vector<Vec3>& loop)
{
  double length = 0;
  for (size_t k = 0; k < loop.size(); ++k)
  {
    length += Norm(loop[(k + 1) % loop.size()] - loop[k]);
  }
  return length;
}

/// How far the loop's farthest corner is off its (Newell) plane through its centroid, a
/// length; `longest`, if given, receives its longest edge.
double WarpOffset(const std::vector<Vec3>& loop, double* longest = nullptr);

/// Keeps the part of a convex loop with dot(normal, x - origin) >= 0 (Sutherland-Hodgman).
/// The analytic form factor integrates over the whole polygon, so parts behind the receiver
/// must be removed first or they cancel visible parts.
void ClipToHalfSpace(const Vec3* loop, int count, const Vec3& origin, const Vec3& normal,
  std::vector<Vec3>& clipped);

/// Triangles covering a simple planar polygon (convex or not), as index triples into
/// `loop`: a fan when the polygon is convex, ear clipping otherwise. A fan over a
/// non-convex polygon would cover area outside it and miss area inside.
/// `noise`: how far the points may be off their true places (float rounding of the scene's
/// coordinates); corners straight up to it make no triangle and bend neither way.
std::vector<int> Triangulate(const Vec3* loop, int count, double noise = 0);

/// The point of triangle (a, b, c) that two uniform numbers in [0, 1) pick: uniform over
/// its area (the unit square's far half folded back onto the near one).
inline Vec3 TrianglePoint(const Vec3& a, const Vec3& b, const Vec3& c, double s, double t)
{
  if (s + t > 1)
  {
    s = 1 - s;
    t = 1 - t;
  }
  return a + (b - a) * s + (c - a) * t;
}

/// Chains start/end segment pairs (exactly matching ends) into one closed loop of corners;
/// empty unless they form exactly one loop.
std::vector<Vec3> ChainLoop(const std::vector<Vec3>& segments);

/// Polygon i's corners, from flat offsets/connectivity arrays (as SceneMesh holds them).
std::vector<Vec3> GatherLoop(const std::vector<Vec3>& points, const std::vector<int>& offsets,
  const std::vector<int>& connectivity, int i);

/// True if every corner turns the same way about the polygon's normal (straight ones, up
/// to `noise` as in Triangulate, turn neither way).
bool IsConvex(const Vec3* loop, int count, double noise = 0);

/// Twice the area below which corner a-b-c is straight: zero area for PolygonProblem, or
/// no more than moving its points by `noise` can make of three points in a line. So a
/// corner that is straight stays straight when a float-stored scene is turned or scaled,
/// and the polygon is cut into the same triangles.
double StraightLimit(const Vec3& a, const Vec3& b, const Vec3& c, double noise);

/// Twice the largest distance of a point from the points' mean: a scene's size that turning
/// or moving it does not change (a bounding box's diagonal turns with the axes).
double Span(const std::vector<Vec3>& points);

/// How far float coordinates (VTK stores points as floats) can move a scene's points
/// near the origin: a few float steps of its span. Far from the origin floats are coarser
/// than this, and a straight corner of a long edge can come out bent.
double FloatNoise(double span);

/// Largest coordinate magnitude the ray tracer's single precision handles with room to
/// spare (squares of lengths stay finite in float).
constexpr double MaximumCoordinate = 1e18;

/// Empty when the loop can be a radiosity polygon; otherwise what is wrong with it, to be
/// prefixed with the cell's name: a non-finite or too large coordinate, zero area (its
/// points collinear or coincident, judged against its own size, not the scene's), or
/// edges that cross (a figure 8).
std::string PolygonProblem(const Vec3* loop, int count);

} // namespace radiosity

#endif
