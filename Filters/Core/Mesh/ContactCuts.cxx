#include "Mesh/ContactCuts.h"
#include "Geometry/Polygon.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace radiosity
{

namespace
{
/// A polygon seen in its own plane: 2D corners in a tangent frame, for inside tests.
struct FlatPolygon
{
  Vec3 Normal, Origin, U, V;
  std::vector<double> X, Y;
  Bounds Box; ///< in 3D

  double Along(const Vec3& p) const { return Dot(Normal, p - Origin); }

  /// True when `p` (in the plane) is inside, farther than `margin` from the outline.
  bool InsideBy(const Vec3& p, double margin) const
  {
    const double px = Dot(U, p - Origin), py = Dot(V, p - Origin);
    bool inside = false;
    const size_t n = X.size();
    for (size_t i = 0, j = n - 1; i < n; j = i++)
    {
      const double dx = X[i] - X[j], dy = Y[i] - Y[j], length = std::hypot(dx, dy);
      if (length > 0)
      {
        const double t = std::clamp(((px - X[j]) * dx + (py - Y[j]) * dy) / (length * length), 0.0, 1.0);
        if (std::hypot(px - X[j] - t * dx, py - Y[j] - t * dy) <= margin)
        {
          return false;
        }
      }
      if ((Y[i] > py) != (Y[j] > py) && px < X[j] + (py - Y[j]) * dx / dy)
      {
        inside = !inside;
      }
    }
    return inside;
  }

  /// Parameters in [0, 1] where the segment a-b crosses the outline, with 0 and 1.
  std::vector<double> Crossings(const Vec3& a, const Vec3& b) const
  {
    std::vector<double> ts{ 0.0, 1.0 };
    const double ax = Dot(U, a - Origin), ay = Dot(V, a - Origin);
    const double bx = Dot(U, b - Origin), by = Dot(V, b - Origin);
    const size_t n = X.size();
    for (size_t i = 0, j = n - 1; i < n; j = i++)
    {
      const double ex = X[i] - X[j], ey = Y[i] - Y[j], sx = bx - ax, sy = by - ay;
      const double denominator = sx * ey - sy * ex;
      if (denominator == 0)
      {
        continue;
      }
      const double t = ((X[j] - ax) * ey - (Y[j] - ay) * ex) / denominator;
      const double u = ((X[j] - ax) * sy - (Y[j] - ay) * sx) / denominator;
      if (t > 0 && t < 1 && u >= 0 && u <= 1)
      {
        ts.push_back(t);
      }
    }
    std::sort(ts.begin(), ts.end());
    return ts;
  }
};

FlatPolygon Flatten(const std::vector<Vec3>& loop)
{
  FlatPolygon f;
  f.Normal = Normalized(NewellVector(loop.data(), static_cast<int>(loop.size())));
  f.Origin = PolygonCentroid(loop.data(), static_cast<int>(loop.size()));
  TangentFrame(f.Normal, f.U, f.V);
  f.Box = Bounds(loop);
  for (const Vec3& p : loop)
  {
    f.X.push_back(Dot(f.U, p - f.Origin));
    f.Y.push_back(Dot(f.V, p - f.Origin));
  }
  return f;
}

/// True when the segment (in the polygon's plane) runs through its inside somewhere.
bool RunsInside(const FlatPolygon& f, const Vec3& a, const Vec3& b, double touch)
{
  const std::vector<double> ts = f.Crossings(a, b);
  const double length = Norm(b - a);
  for (size_t k = 0; k + 1 < ts.size(); ++k)
  {
    if ((ts[k + 1] - ts[k]) * length > 2 * touch && f.InsideBy(a + (b - a) * (0.5 * (ts[k] + ts[k + 1])), touch))
    {
      return true;
    }
  }
  return false;
}

/// The largest side of a box.
double Extent(const Bounds& box)
{
  return std::max({ box.Hi.x - box.Lo.x, box.Hi.y - box.Lo.y, box.Hi.z - box.Lo.z });
}

/// Polygons by the grid cells their bounds cover: candidates near an edge. Those larger than
/// a fine cell sit in a uniform grid over the scene (at most 64 cells a side); the many small
/// ones of a tessellated model in a sparse grid of cells about their size. In the uniform
/// grid alone, a tessellated model's cells held hundreds of triangles each, and finding
/// contacts took most of its meshing (docs/benchmarks.md, "Meshing real scenes").
class PolygonGrid
{
public:
  PolygonGrid(const std::vector<FlatPolygon>& polygons, double touch)
    : Touch(touch)
  {
    Bounds box;
    std::vector<double> sizes;
    for (const FlatPolygon& f : polygons)
    {
      box.Add(f.Box);
      sizes.push_back(Extent(f.Box));
    }
    Lo = box.Lo;
    Resolution = std::clamp(static_cast<int>(2 * std::cbrt(static_cast<double>(polygons.size()))), 1, 64);
    Cell = std::max(Extent(box), 1e-300) / Resolution * (1 + 1e-9);
    // Twice the median polygon: most polygons fall in a cell or two of it a side.
    std::nth_element(sizes.begin(), sizes.begin() + sizes.size() / 2, sizes.end());
    Fine = std::clamp(2 * sizes[sizes.size() / 2], Cell / 64, Cell);
    Cells.resize(static_cast<size_t>(Resolution) * Resolution * Resolution);
    for (size_t i = 0; i < polygons.size(); ++i)
    {
      auto add = [&](std::vector<int>& cell) { cell.push_back(static_cast<int>(i)); };
      if (Extent(polygons[i].Box) > Fine)
      {
        Visit(polygons[i].Box, [&](size_t cell) { add(Cells[cell]); });
      }
      else
      {
        VisitFine(polygons[i].Box, [&](long long cell) { add(FineCells[cell]); });
      }
    }
  }

  /// Calls `use` once for every polygon whose cells the segment a-b meets.
  template <typename Use>
  void Near(const Vec3& a, const Vec3& b, std::vector<int>& stamp, int mark, const Use& use) const
  {
    auto once = [&](const std::vector<int>& polygons) {
      for (int i : polygons)
      {
        if (stamp[i] != mark)
        {
          stamp[i] = mark;
          use(i);
        }
      }
    };
    Bounds reach;
    reach.Add(a);
    reach.Add(b);
    Visit(reach, [&](size_t cell) { once(Cells[cell]); });
    if (FineCells.empty())
    {
      return;
    }
    // In pieces no longer than a fine cell: a long edge's box would hold a plane of them.
    const int pieces = static_cast<int>(std::min(std::ceil(Norm(b - a) / Fine), 1e6));
    for (int k = 0; k < std::max(pieces, 1); ++k)
    {
      Bounds piece;
      piece.Add(a + (b - a) * (static_cast<double>(k) / std::max(pieces, 1)));
      piece.Add(a + (b - a) * (static_cast<double>(k + 1) / std::max(pieces, 1)));
      VisitFine(piece, [&](long long cell) {
        const auto found = FineCells.find(cell);
        if (found != FineCells.end())
        {
          once(found->second);
        }
      });
    }
  }

private:
  int Index(double v, double lo) const
  {
    return std::clamp(static_cast<int>(std::floor((v - lo) / Cell)), 0, Resolution - 1);
  }

  template <typename Use>
  void Visit(const Bounds& box, const Use& use) const
  {
    const Vec3 &lo = box.Lo, &hi = box.Hi;
    const int x0 = Index(lo.x - Touch, Lo.x), x1 = Index(hi.x + Touch, Lo.x);
    const int y0 = Index(lo.y - Touch, Lo.y), y1 = Index(hi.y + Touch, Lo.y);
    const int z0 = Index(lo.z - Touch, Lo.z), z1 = Index(hi.z + Touch, Lo.z);
    for (int z = z0; z <= z1; ++z)
    {
      for (int y = y0; y <= y1; ++y)
      {
        for (int x = x0; x <= x1; ++x)
        {
          use((static_cast<size_t>(z) * Resolution + y) * Resolution + x);
        }
      }
    }
  }

  template <typename Use>
  void VisitFine(const Bounds& box, const Use& use) const
  {
    auto index = [&](double v, double lo) { return static_cast<long long>(std::floor((v - lo) / Fine)); };
    const long long x0 = index(box.Lo.x - Touch, Lo.x), x1 = index(box.Hi.x + Touch, Lo.x);
    const long long y0 = index(box.Lo.y - Touch, Lo.y), y1 = index(box.Hi.y + Touch, Lo.y);
    const long long z0 = index(box.Lo.z - Touch, Lo.z), z1 = index(box.Hi.z + Touch, Lo.z);
    for (long long z = z0; z <= z1; ++z)
    {
      for (long long y = y0; y <= y1; ++y)
      {
        for (long long x = x0; x <= x1; ++x)
        {
          use(CellHash(x, y, z));
        }
      }
    }
  }

  double Touch, Cell = 1, Fine = 1;
  int Resolution = 1;
  Vec3 Lo;
  std::vector<std::vector<int>> Cells;
  std::unordered_map<long long, std::vector<int>> FineCells; ///< by CellHash: a shared hash only adds candidates
};

/// Splits one convex loop along the line through `origin` with in-plane normal `side`;
/// false (nothing made) unless both parts reach farther than `tolerance` from the line.
bool SplitLoop(const Vec3* loop, int count, const Vec3& origin, const Vec3& side, double tolerance,
  std::vector<Vec3>& front, std::vector<Vec3>& back)
{
  std::vector<double> s(count);
  double lowest = 0, highest = 0;
  for (int v = 0; v < count; ++v)
  {
    s[v] = Dot(side, loop[v] - origin);
    s[v] = std::fabs(s[v]) <= tolerance ? 0.0 : s[v]; // on the line: in both parts, no sliver
    lowest = std::min(lowest, s[v]);
    highest = std::max(highest, s[v]);
  }
  if (lowest >= 0 || highest <= 0)
  {
    return false;
  }
  front.clear();
  back.clear();
  for (int v = 0; v < count; ++v)
  {
    const int w = (v + 1) % count;
    if (s[v] >= 0)
    {
      front.push_back(loop[v]);
    }
    if (s[v] <= 0)
    {
      back.push_back(loop[v]);
    }
    if ((s[v] > 0 && s[w] < 0) || (s[v] < 0 && s[w] > 0))
    {
      const Vec3 x = loop[v] + (loop[w] - loop[v]) * (s[v] / (s[v] - s[w]));
      front.push_back(x);
      back.push_back(x);
    }
  }
  return front.size() >= 3 && back.size() >= 3;
}

/// The part of the segment's line inside the convex loop, as parameters along a-b.
bool ChordOverlaps(const Vec3* loop, int count, const Vec3& a, const Vec3& b, const Vec3& normal, double tolerance)
{
  const Vec3 d = b - a;
  const double length = Norm(d);
  double t0 = -1e300, t1 = 1e300;
  const double area = Dot(NewellVector(loop, count), normal) >= 0 ? 1.0 : -1.0;
  for (int v = 0; v < count; ++v)
  {
    const Vec3 edge = loop[(v + 1) % count] - loop[v];
    const Vec3 inward = Cross(normal, edge) * area;
    const double start = Dot(inward, a - loop[v]), rate = Dot(inward, d);
    if (rate == 0)
    {
      if (start < 0)
      {
        return false; // parallel to this edge, outside it
      }
      continue;
    }
    const double t = -start / rate;
    (rate > 0 ? t0 : t1) = rate > 0 ? std::max(t0, t) : std::min(t1, t);
  }
  return (std::min(t1, 1.0) - std::max(t0, 0.0)) * length > tolerance;
}
} // namespace

std::vector<std::vector<ContactSegment>> FindContacts(
  const PolygonArrays& polygons, const PolygonArrays& standing, double touch)
{
  const int n = static_cast<int>(polygons.Offsets.size()) - 1;
  std::vector<std::vector<ContactSegment>> contacts(std::max(n, 0));
  std::vector<FlatPolygon> flat;
  flat.reserve(contacts.size());
  for (int i = 0; i < n; ++i)
  {
    flat.push_back(Flatten(GatherLoop(polygons.Points, polygons.Offsets, polygons.Connectivity, i)));
  }
  if (flat.empty())
  {
    return contacts;
  }
  const PolygonGrid grid(flat, touch);
  std::vector<int> stamp(contacts.size(), -1);
  int mark = 0;
  for (size_t j = 0; j + 1 < standing.Offsets.size(); ++j)
  {
    const std::vector<Vec3> loop = GatherLoop(standing.Points, standing.Offsets, standing.Connectivity, static_cast<int>(j));
    const Vec3 newell = NewellVector(loop.data(), static_cast<int>(loop.size()));
    if (loop.size() < 3 || !(Norm(newell) > 0))
    {
      continue; // no plane, nothing that stands
    }
    const Vec3 normal = Normalized(newell);
    const Vec3 centre = PolygonCentroid(loop.data(), static_cast<int>(loop.size()));
    for (size_t v = 0; v < loop.size(); ++v, ++mark)
    {
      const Vec3& a = loop[v];
      const Vec3& b = loop[(v + 1) % loop.size()];
      grid.Near(a, b, stamp, mark, [&](int i) {
        // Parallel polygons (the polygon itself among them) never stand on each other.
        const FlatPolygon& f = flat[i];
        const double da = f.Along(a), db = f.Along(b);
        // It stands on the front (a wall on a floor, a lamp hung from a ceiling); a wall
        // of the storey below a slab drawn as one face is no contact of the floor above.
        if (std::fabs(Dot(f.Normal, normal)) > 1 - 1e-6 || std::fabs(da) > touch || std::fabs(db) > touch ||
          f.Along(centre) <= touch)
        {
          return;
        }
        const ContactSegment onPlane{ a - f.Normal * da, b - f.Normal * db };
        if (Norm(onPlane.B - onPlane.A) > 2 * touch && RunsInside(f, onPlane.A, onPlane.B, touch))
        {
          contacts[i].push_back(onPlane);
        }
      });
    }
  }
  return contacts;
}

ContactCutter::ContactCutter(const std::vector<ContactSegment>& segments, const Vec3& normal, double tolerance)
  : Segments(segments)
  , Normal(normal)
  , Tolerance(tolerance)
{
  if (segments.empty())
  {
    return;
  }
  TangentFrame(normal, U, V);
  Origin = segments[0].A;
  double hi[2] = { -1e300, -1e300 };
  Lo[0] = Lo[1] = 1e300;
  for (const ContactSegment& segment : segments)
  {
    for (const Vec3* p : { &segment.A, &segment.B })
    {
      const double c[2] = { Dot(U, *p - Origin), Dot(V, *p - Origin) };
      for (int k = 0; k < 2; ++k)
      {
        Lo[k] = std::min(Lo[k], c[k]);
        hi[k] = std::max(hi[k], c[k]);
      }
    }
  }
  Resolution = std::clamp(static_cast<int>(2 * std::sqrt(static_cast<double>(segments.size()))), 1, 256);
  Cell = std::max({ hi[0] - Lo[0], hi[1] - Lo[1], 1e-300 }) / Resolution * (1 + 1e-9);
  Grid.resize(static_cast<size_t>(Resolution) * Resolution);
  for (size_t s = 0; s < segments.size(); ++s)
  {
    int x0, y0, x1, y1;
    const Vec3 ends[2] = { segments[s].A, segments[s].B };
    Cells(ends, 2, x0, y0, x1, y1);
    for (int y = y0; y <= y1; ++y)
    {
      for (int x = x0; x <= x1; ++x)
      {
        Grid[static_cast<size_t>(y) * Resolution + x].push_back(static_cast<int>(s));
      }
    }
  }
}

void ContactCutter::Cells(const Vec3* points, int count, int& x0, int& y0, int& x1, int& y1) const
{
  double lo[2] = { 1e300, 1e300 }, hi[2] = { -1e300, -1e300 };
  for (int i = 0; i < count; ++i)
  {
    const double c[2] = { Dot(U, points[i] - Origin), Dot(V, points[i] - Origin) };
    for (int k = 0; k < 2; ++k)
    {
      lo[k] = std::min(lo[k], c[k] - Tolerance);
      hi[k] = std::max(hi[k], c[k] + Tolerance);
    }
  }
  auto index = [&](double v, int k) {
    const double at = std::floor((v - Lo[k]) / Cell);
    return static_cast<int>(std::clamp(at, 0.0, static_cast<double>(Resolution - 1)));
  };
  x0 = index(lo[0], 0);
  x1 = index(hi[0], 0);
  y0 = index(lo[1], 1);
  y1 = index(hi[1], 1);
}

int ContactCutter::Cut(const Vec3* loop, int count, std::vector<std::vector<Vec3>>& parts) const
{
  if (Segments.empty())
  {
    return 0;
  }
  int x0, y0, x1, y1;
  Cells(loop, count, x0, y0, x1, y1);
  Near.clear();
  for (int y = y0; y <= y1; ++y)
  {
    for (int x = x0; x <= x1; ++x)
    {
      const std::vector<int>& cell = Grid[static_cast<size_t>(y) * Resolution + x];
      Near.insert(Near.end(), cell.begin(), cell.end());
    }
  }
  if (Near.empty())
  {
    return 0;
  }
  std::sort(Near.begin(), Near.end()); // the segments' own order, each once: the same cuts every time
  Near.erase(std::unique(Near.begin(), Near.end()), Near.end());
  bool cut = false;
  std::vector<Vec3> front, back;
  for (int s : Near)
  {
    const ContactSegment& segment = Segments[s];
    if (!cut && !ChordOverlaps(loop, count, segment.A, segment.B, Normal, Tolerance))
    {
      continue; // the common case: a segment near the element that misses it
    }
    if (!cut)
    {
      parts.assign(1, std::vector<Vec3>(loop, loop + count));
      cut = true;
    }
    const Vec3 side = Normalized(Cross(Normal, segment.B - segment.A));
    for (size_t k = 0, n = parts.size(); k < n; ++k)
    {
      const int corners = static_cast<int>(parts[k].size());
      if (ChordOverlaps(parts[k].data(), corners, segment.A, segment.B, Normal, Tolerance) &&
        SplitLoop(parts[k].data(), corners, segment.A, side, Tolerance, front, back))
      {
        parts[k] = front;
        parts.push_back(back);
      }
    }
  }
  return cut ? static_cast<int>(parts.size()) : 0;
}

} // namespace radiosity
