#include "Geometry/Polygon.h"
#include "Geometry/CornerGrid.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <unordered_map>

namespace radiosity
{
namespace
{
/// Below this fraction of its longest edge squared, an area is zero: what PolygonProblem
/// rejects, Triangulate must not make.
constexpr double ZeroAreaFraction = 1e-12;
}

double StraightLimit(const Vec3& a, const Vec3& b, const Vec3& c, double noise)
{
  const double longest = std::max({ Norm(b - a), Norm(c - b), Norm(a - c) });
  return 2 * ZeroAreaFraction * longest * longest + 4 * noise * longest;
}

Bounds::Bounds(const std::vector<Vec3>& points)
{
  if (points.empty())
  {
    Lo = Hi = Vec3();
    return;
  }
  for (const Vec3& p : points)
  {
    Add(p);
  }
}

void Bounds::Add(const Vec3& p)
{
  for (int c = 0; c < 3; ++c)
  {
    Lo[c] = std::min(Lo[c], p[c]);
    Hi[c] = std::max(Hi[c], p[c]);
  }
}

void Bounds::Add(const Bounds& b)
{
  if (b.Lo.x <= b.Hi.x)
  {
    Add(b.Lo);
    Add(b.Hi);
  }
}

bool Bounds::Overlaps(const Bounds& b, double tolerance) const
{
  for (int c = 0; c < 3; ++c)
  {
    if (b.Lo[c] > Hi[c] + tolerance || Lo[c] > b.Hi[c] + tolerance)
    {
      return false;
    }
  }
  return true;
}

std::array<long long, 4> PlaneKey(const Vec3& unitNormal, double offset, double normalStep, double offsetStep)
{
  return { std::llround(unitNormal.x / normalStep), std::llround(unitNormal.y / normalStep),
    std::llround(unitNormal.z / normalStep), std::llround(offset / offsetStep) };
}

std::array<long long, 3> QuantizedPoint(const Vec3& p, double step)
{
  return { std::llround(p.x / step), std::llround(p.y / step), std::llround(p.z / step) };
}

std::vector<int> WeldedPointIds(const std::vector<Vec3>& points, double tolerance)
{
  std::unordered_map<long long, std::vector<int>> cells; // first points, by cell
  std::vector<int> ids(points.size(), -1);
  int next = 0;
  for (size_t i = 0; i < points.size(); ++i)
  {
    const std::array<long long, 3> at = QuantizedPoint(points[i], tolerance);
    for (int step = 0; step < 27 && ids[i] < 0; ++step)
    {
      const auto found = cells.find(CellHash(at[0] + step % 3 - 1, at[1] + step / 3 % 3 - 1, at[2] + step / 9 - 1));
      for (size_t k = 0; found != cells.end() && k < found->second.size() && ids[i] < 0; ++k)
      {
        const int j = found->second[k];
        ids[i] = Norm(points[j] - points[i]) <= tolerance ? ids[j] : -1;
      }
    }
    if (ids[i] < 0)
    {
      ids[i] = next++;
      cells[CellHash(at[0], at[1], at[2])].push_back(static_cast<int>(i));
    }
  }
  return ids;
}

Vec3 NewellVector(const Vec3* loop, int count)
{
  // Relative to the first point: the sums of far-away coordinates would cancel the
  // digits that a small polygon's normal lives in.
  Vec3 n;
  if (count <= 0)
  {
    return n;
  }
  const Vec3 o = loop[0];
  for (int i = 0; i < count; ++i)
  {
    const Vec3 a = loop[i] - o;
    const Vec3 b = loop[(i + 1) % count] - o;
    n.x += (a.y - b.y) * (a.z + b.z);
    n.y += (a.z - b.z) * (a.x + b.x);
    n.z += (a.x - b.x) * (a.y + b.y);
  }
  return n;
}

Vec3 PolygonCentroid(const Vec3* loop, int count)
{
  // Area-weighted centroid of the fan triangles with signed areas (along the polygon's
  // normal), which is exact for non-convex polygons too.
  const Vec3 normal = Normalized(NewellVector(loop, count));
  Vec3 weighted;
  double total = 0;
  for (int i = 1; i + 1 < count; ++i)
  {
    const double a = 0.5 * Dot(normal, Cross(loop[i] - loop[0], loop[i + 1] - loop[0]));
    weighted += (loop[i] - loop[0] + loop[i + 1] - loop[0]) * (a / 3.0);
    total += a;
  }
  if (total > 0)
  {
    return loop[0] + weighted * (1.0 / total);
  }
  Vec3 mean;
  for (int i = 0; i < count; ++i)
  {
    mean += loop[i];
  }
  return count > 0 ? mean * (1.0 / count) : mean;
}

double WarpOffset(const std::vector<Vec3>& loop, double* longest)
{
  const Vec3 n = Normalized(NewellVector(loop.data(), static_cast<int>(loop.size())));
  const Vec3 c = PolygonCentroid(loop.data(), static_cast<int>(loop.size()));
  double offset = 0, edge = 0;
  for (size_t v = 0; v < loop.size(); ++v)
  {
    offset = std::max(offset, std::fabs(Dot(n, loop[v] - c)));
    edge = std::max(edge, Norm(loop[(v + 1) % loop.size()] - loop[v]));
  }
  if (longest)
  {
    *longest = edge;
  }
  return offset;
}

double Span(const std::vector<Vec3>& points)
{
  Vec3 mean{};
  for (const Vec3& p : points)
  {
    mean += p * (1.0 / static_cast<double>(points.size()));
  }
  double radius = 0;
  for (const Vec3& p : points)
  {
    radius = std::max(radius, Norm(p - mean));
  }
  return 2.0 * radius;
}

double FloatNoise(double span)
{
  // The span, not the distance from the origin: a tolerance that grew with the distance
  // would straighten real millimetre details of a building moved 1 km (measured: the
  // FZK-Haus lost 4,000 of its 31,833 elements), so the same scene would mesh otherwise.
  return 2 * 1.1920929e-7 * span;
}

bool IsConvex(const Vec3* loop, int count, double noise)
{
  const Vec3 unit = Normalized(NewellVector(loop, count));
  for (int i = 0; i < count; ++i)
  {
    const Vec3& a = loop[(i + count - 1) % count];
    const Vec3& b = loop[i];
    const Vec3& c = loop[(i + 1) % count];
    if (Dot(unit, Cross(b - a, c - b)) < -StraightLimit(a, b, c, noise)) // a straight corner bends neither way
    {
      return false;
    }
  }
  return true;
}

namespace
{
/// Ear clipping in the loop's order: each step cuts off the first ear (by corner index),
/// or, where none is left, the last straight corner. A corner's state changes only when a
/// neighbour is cut off or when the corner found inside its triangle is, so only those
/// are looked at again: a 20,000-corner gear is cut in linear time where scanning every
/// corner for an ear at each step was quadratic (10 s to mesh).
class EarClipper
{
public:
  EarClipper(const Vec3* loop, int count, double noise, const Vec3& unit)
    : Loop(loop)
    , Noise(noise)
    , Unit(unit)
    , Prev(count)
    , Next(count)
    , State(count, Kind::Reflex)
    , Blocker(count, -1)
    , Blocks(count)
    , Grid(loop, count, unit, AllCorners(count))
  {
    for (int i = 0; i < count; ++i)
    {
      Prev[i] = (i + count - 1) % count;
      Next[i] = (i + 1) % count;
    }
    for (int i = 0; i < count; ++i)
    {
      Classify(i);
    }
  }

  /// Cuts ears off until three corners are left, or none can be cut (a loop crossing
  /// itself); appends their triangles and returns the corners left, in the loop's order.
  std::vector<int> Run(std::vector<int>& triangles)
  {
    int left = static_cast<int>(Prev.size());
    while (left > 3)
    {
      int cut = -1;
      if (!Ears.empty())
      {
        cut = *Ears.begin();
        triangles.insert(triangles.end(), { Prev[cut], cut, Next[cut] });
      }
      else if (!Straights.empty())
      {
        cut = *Straights.rbegin(); // lies on its neighbours' edge: dropping it changes no area
      }
      else
      {
        break; // self-intersecting input: fan what is left rather than loop forever
      }
      Remove(cut);
      --left;
    }
    std::vector<int> rest;
    for (int i = 0; i < static_cast<int>(Prev.size()); ++i)
    {
      if (State[i] != Kind::Gone)
      {
        for (int k = i; rest.empty() || k != i; k = Next[k])
        {
          rest.push_back(k);
        }
        break;
      }
    }
    return rest;
  }

private:
  enum class Kind
  {
    Straight,
    Reflex,
    Blocked,
    Ear,
    Gone
  };

  static std::vector<int> AllCorners(int count)
  {
    std::vector<int> all(count);
    for (int i = 0; i < count; ++i)
    {
      all[i] = i;
    }
    return all;
  }

  double Turn(int a, int b, int c) const { return Dot(Unit, Cross(Loop[b] - Loop[a], Loop[c] - Loop[b])); }

  void Classify(int b)
  {
    Ears.erase(b);
    Straights.erase(b);
    const int a = Prev[b], c = Next[b];
    if (std::fabs(Turn(a, b, c)) <= StraightLimit(Loop[a], Loop[b], Loop[c], Noise))
    {
      State[b] = Kind::Straight;
      Straights.insert(b);
      return;
    }
    if (Turn(a, b, c) <= 0)
    {
      State[b] = Kind::Reflex;
      return;
    }
    int inside = -1;
    Grid.Any(a, b, c, [&](int p) {
      const bool in = p != a && p != b && p != c && Turn(a, b, p) >= 0 && Turn(b, c, p) >= 0 && Turn(c, a, p) >= 0;
      inside = in ? p : inside;
      return in;
    });
    if (inside >= 0)
    {
      State[b] = Kind::Blocked;
      Blocker[b] = inside;
      Blocks[inside].push_back(b);
      return;
    }
    State[b] = Kind::Ear;
    Ears.insert(b);
  }

  void Remove(int b)
  {
    const int a = Prev[b], c = Next[b];
    Ears.erase(b);
    Straights.erase(b);
    State[b] = Kind::Gone;
    Grid.Remove(b);
    Next[a] = c;
    Prev[c] = a;
    Classify(a);
    Classify(c);
    std::vector<int> freed;
    freed.swap(Blocks[b]);
    for (int j : freed)
    {
      if (State[j] == Kind::Blocked && Blocker[j] == b)
      {
        Classify(j);
      }
    }
  }

  const Vec3* Loop;
  const double Noise;
  const Vec3 Unit;
  std::vector<int> Prev, Next;
  std::vector<Kind> State;
  std::vector<int> Blocker;            ///< a corner inside a blocked corner's triangle
  std::vector<std::vector<int>> Blocks; ///< the corners each corner was found blocking
  std::set<int> Ears, Straights;
  CornerGrid Grid; ///< the corners not cut off yet
};
} // namespace

std::vector<int> Triangulate(const Vec3* loop, int count, double noise)
{
  std::vector<int> triangles;
  if (count < 3)
  {
    return triangles;
  }
  const Vec3 unit = Normalized(NewellVector(loop, count));
  std::vector<int> rest;
  if (IsConvex(loop, count, noise))
  {
    for (int i = 0; i < count; ++i)
    {
      rest.push_back(i);
    }
  }
  else
  {
    rest = EarClipper(loop, count, noise, unit).Run(triangles);
  }
  // A corner whose triangle PolygonProblem would call zero area (three points in a line,
  // up to rounding) makes no triangle: it would only be rejected downstream.
  for (size_t i = 1; i + 1 < rest.size(); ++i)
  {
    const Vec3 &a = loop[rest[0]], &b = loop[rest[i]], &c = loop[rest[i + 1]];
    if (std::fabs(Dot(unit, Cross(b - a, c - b))) > StraightLimit(a, b, c, noise))
    {
      triangles.insert(triangles.end(), { rest[0], rest[i], rest[i + 1] });
    }
  }
  return triangles;
}

void ClipToHalfSpace(const Vec3* loop, int count, const Vec3& origin, const Vec3& normal,
  std::vector<Vec3>& clipped)
{
  clipped.clear();
  for (int i = 0; i < count; ++i)
  {
    const Vec3& a = loop[i];
    const Vec3& b = loop[(i + 1) % count];
    const double da = Dot(normal, a - origin);
    const double db = Dot(normal, b - origin);
    if (da >= 0)
    {
      clipped.push_back(a);
    }
    if ((da >= 0) != (db >= 0))
    {
      const double t = da / (da - db);
      clipped.push_back(a + (b - a) * t);
    }
  }
}

/// Chains start/end segments into one closed loop of corners; empty unless they form
/// exactly one simple loop.
std::vector<Vec3> ChainLoop(const std::vector<Vec3>& segments)
{
  const size_t count = segments.size() / 2;
  std::vector<Vec3> loop;
  if (count < 3)
  {
    return loop;
  }
  std::vector<char> used(count, 0);
  size_t current = 0;
  used[0] = 1;
  loop.push_back(segments[0]);
  for (size_t step = 1; step < count; ++step)
  {
    const Vec3& end = segments[2 * current + 1];
    size_t next = count;
    for (size_t s = 0; s < count && next == count; ++s)
    {
      if (!used[s] && Norm(segments[2 * s] - end) == 0)
      {
        next = s;
      }
    }
    if (next == count)
    {
      return {};
    }
    used[next] = 1;
    loop.push_back(segments[2 * next]);
    current = next;
  }
  if (Norm(segments[2 * current + 1] - loop[0]) != 0)
  {
    return {};
  }
  return loop;
}

namespace
{
/// True when segments ab and cd (2-D) cross or touch beyond `tolerance`.
bool SegmentsMeet(const double* a, const double* b, const double* c, const double* d, double tolerance)
{
  auto side = [](const double* p, const double* q, const double* r) {
    return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
  };
  const double d1 = side(c, d, a), d2 = side(c, d, b), d3 = side(a, b, c), d4 = side(a, b, d);
  return ((d1 > tolerance && d2 < -tolerance) || (d1 < -tolerance && d2 > tolerance)) &&
    ((d3 > tolerance && d4 < -tolerance) || (d3 < -tolerance && d4 > tolerance));
}

bool CrossesItself(const Vec3* loop, int count, const Vec3& newell, double extent)
{
  // Project on the plane of the largest normal component; crossings survive projection.
  const int drop = std::fabs(newell.x) >= std::fabs(newell.y) && std::fabs(newell.x) >= std::fabs(newell.z)
    ? 0
    : (std::fabs(newell.y) >= std::fabs(newell.z) ? 1 : 2);
  std::vector<double> flat(2 * count);
  for (int i = 0; i < count; ++i)
  {
    flat[2 * i] = loop[i][drop == 0 ? 1 : 0];
    flat[2 * i + 1] = loop[i][drop == 2 ? 1 : 2];
  }
  const double tolerance = 1e-9 * extent * extent;
  // Two edges that cross overlap in x: swept in order of their left ends, each edge is
  // held against those that start before it ends, not against every other edge (a
  // 20,000-corner gear: 2e8 pairs).
  auto low = [&](int i, int axis) { return std::min(flat[2 * i + axis], flat[2 * ((i + 1) % count) + axis]); };
  auto high = [&](int i, int axis) { return std::max(flat[2 * i + axis], flat[2 * ((i + 1) % count) + axis]); };
  std::vector<int> order(count);
  for (int i = 0; i < count; ++i)
  {
    order[i] = i;
  }
  std::sort(order.begin(), order.end(), [&](int a, int b) { return low(a, 0) < low(b, 0); });
  const double pad = 1e-9 * extent;
  for (int k = 0; k < count; ++k)
  {
    const int i = order[k];
    for (int m = k + 1; m < count && low(order[m], 0) <= high(i, 0) + pad; ++m)
    {
      const int j = order[m];
      const bool neighbours = (i + 1) % count == j || (j + 1) % count == i;
      if (neighbours || low(j, 1) > high(i, 1) + pad || low(i, 1) > high(j, 1) + pad)
      {
        continue;
      }
      if (SegmentsMeet(&flat[2 * i], &flat[2 * ((i + 1) % count)], &flat[2 * j], &flat[2 * ((j + 1) % count)], tolerance))
      {
        return true;
      }
    }
  }
  return false;
}
} // namespace

std::vector<Vec3> GatherLoop(const std::vector<Vec3>& points, const std::vector<int>& offsets,
  const std::vector<int>& connectivity, int i)
{
  std::vector<Vec3> loop;
  for (int k = offsets[i]; k < offsets[i + 1]; ++k)
  {
    loop.push_back(points[connectivity[k]]);
  }
  return loop;
}

std::string PolygonProblem(const Vec3* loop, int count)
{
  double extent = 0;
  for (int i = 0; i < count; ++i)
  {
    const Vec3& p = loop[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    {
      return "has a non-finite point (NaN or infinite)";
    }
    if (std::max({ std::fabs(p.x), std::fabs(p.y), std::fabs(p.z) }) > MaximumCoordinate)
    {
      std::ostringstream why;
      why << "has a coordinate of magnitude " << std::max({ std::fabs(p.x), std::fabs(p.y), std::fabs(p.z) })
          << ", beyond " << MaximumCoordinate << " that single-precision ray tracing can hold; rescale the scene";
      return why.str();
    }
    extent = std::max(extent, Norm(loop[(i + 1) % count] - p));
  }
  // The plane from the widest corner triangle: Newell's vector vanishes for a symmetric
  // figure 8, whose lobes cancel.
  Vec3 plane;
  for (int i = 1; i + 1 < count; ++i)
  {
    const Vec3 c = Cross(loop[i] - loop[0], loop[i + 1] - loop[0]);
    plane = Norm(c) > Norm(plane) ? c : plane;
  }
  if (count > 3 && Norm(plane) > 1e-12 * extent * extent && CrossesItself(loop, count, plane, extent))
  {
    return "crosses itself (edges intersect, like a figure 8); split it into simple polygons";
  }
  if (!(0.5 * Norm(NewellVector(loop, count)) > ZeroAreaFraction * extent * extent))
  {
    return "has zero area (its points are collinear or coincident); remove degenerate cells";
  }
  return std::string();
}

}
