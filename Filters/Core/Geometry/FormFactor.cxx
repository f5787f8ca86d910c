#include "Geometry/FormFactor.h"
#include "Geometry/Polygon.h"

#include <cmath>

namespace radiosity
{

namespace
{

/// One edge's term of Lambert's contour integral, seen from the origin.
inline double EdgeTerm(const Vec3& normal, const Vec3& a, const Vec3& b)
{
  const Vec3 c = Cross(a, b);
  const double cn = Norm(c);
  // An edge collinear with the point subtends no solid angle (or lies on the point,
  // which only happens for points on the boundary, a set of measure zero).
  if (cn <= 1e-300)
  {
    return 0.0;
  }
  // atan2 keeps full precision for tiny edge angles, where acos of a dot product does not.
  return std::atan2(cn, Dot(a, b)) * Dot(normal, c) / cn;
}

double LambertContour(const Vec3& point, const Vec3& normal, const Vec3* loop, int count)
{
  double sum = 0;
  for (int i = 0; i < count; ++i)
  {
    sum += EdgeTerm(normal, loop[i] - point, loop[(i + 1) % count] - point);
  }
  return std::fabs(sum) / (2.0 * Pi);
}
} // namespace

double PointToPolygonFormFactor(const Vec3& point, const Vec3& normal, const Vec3* loop,
  int count, std::vector<Vec3>& scratch)
{
  bool allFront = true;
  bool anyFront = false;
  for (int i = 0; i < count; ++i)
  {
    const double d = Dot(normal, loop[i] - point);
    allFront = allFront && d >= 0;
    anyFront = anyFront || d > 0;
  }
  if (!anyFront)
  {
    return 0.0;
  }
  if (allFront)
  {
    return LambertContour(point, normal, loop, count);
  }
  ClipToHalfSpace(loop, count, point, normal, scratch);
  if (scratch.size() < 3)
  {
    return 0.0;
  }
  return LambertContour(point, normal, scratch.data(), static_cast<int>(scratch.size()));
}

double PointToPolygonFormFactor(const Vec3& point, const Vec3& normal, const Vec3* loop, int count)
{
  std::vector<Vec3> scratch;
  return PointToPolygonFormFactor(point, normal, loop, count, scratch);
}

double EdgeSetFormFactor(
  const Vec3& point, const Vec3& normal, const Vec3* edges, int edgeCount)
{
  double sum = 0;
  for (int i = 0; i < edgeCount; ++i)
  {
    sum += EdgeTerm(normal, edges[2 * i] - point, edges[2 * i + 1] - point);
  }
  return std::fabs(sum) / (2.0 * Pi);
}

double PolygonToPolygonFormFactor(const Vec3* from, int fromCount, const Vec3* to, int toCount,
  int subdivisions)
{
  const Vec3 areaNormal = NewellVector(from, fromCount);
  const double area = 0.5 * Norm(areaNormal);
  if (area <= 0 || subdivisions < 1)
  {
    return 0.0;
  }
  const Vec3 normal = Normalized(areaNormal);
  const int s = subdivisions;
  std::vector<Vec3> scratch;
  double integral = 0;
  for (int t = 1; t + 1 < fromCount; ++t)
  {
    const Vec3 o = from[0];
    const Vec3 u = (from[t] - o) * (1.0 / s);
    const Vec3 v = (from[t + 1] - o) * (1.0 / s);
    const double subArea = 0.5 * Norm(Cross(u, v));
    // Sub-triangles of a regular split: "upright" ones at (i + 1/3, j + 1/3) and
    // "inverted" ones at (i + 2/3, j + 2/3) in (u, v) lattice coordinates.
    for (int i = 0; i < s; ++i)
    {
      for (int j = 0; i + j < s; ++j)
      {
        const Vec3 up = o + u * (i + 1.0 / 3.0) + v * (j + 1.0 / 3.0);
        integral += subArea * PointToPolygonFormFactor(up, normal, to, toCount, scratch);
        if (i + j + 1 < s)
        {
          const Vec3 down = o + u * (i + 2.0 / 3.0) + v * (j + 2.0 / 3.0);
          integral += subArea * PointToPolygonFormFactor(down, normal, to, toCount, scratch);
        }
      }
    }
  }
  return integral / area;
}

} // namespace radiosity
