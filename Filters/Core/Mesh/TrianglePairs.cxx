#include "Mesh/TrianglePairs.h"
#include "Geometry/Polygon.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace radiosity
{

namespace
{
using PointKey = std::array<long long, 3>;

struct TriangleEdges
{
  const std::vector<Vec3>& Points;
  const std::vector<int>& Offsets;
  const std::vector<int>& Connectivity;
  double Quantum;
  std::map<std::pair<PointKey, PointKey>, std::vector<int>> Triangles; ///< by undirected edge

  PointKey Key(int id) const { return QuantizedPoint(Points[id], Quantum); }
  std::pair<PointKey, PointKey> Edge(int a, int b) const
  {
    const PointKey x = Key(a), y = Key(b);
    return x < y ? std::make_pair(x, y) : std::make_pair(y, x);
  }
  const int* Corners(int t) const { return Connectivity.data() + Offsets[t]; }
  bool IsTriangle(int t) const { return Offsets[t + 1] - Offsets[t] == 3; }
};

/// The quad t + u across t's edge (corner e, corner e+1), or empty if they do not make a
/// flat convex one.
std::vector<int> JoinedQuad(const TriangleEdges& edges, int t, int e, int u, double flatness)
{
  const int* a = edges.Corners(t);
  const int* b = edges.Corners(u);
  const int p = a[e], q = a[(e + 1) % 3], r = a[(e + 2) % 3];
  int opposite = -1;
  for (int k = 0; k < 3; ++k)
  {
    if (edges.Key(b[k]) != edges.Key(p) && edges.Key(b[k]) != edges.Key(q))
    {
      opposite = b[k];
    }
  }
  if (opposite < 0)
  {
    return {};
  }
  const std::vector<int> quad = { p, opposite, q, r };
  std::vector<Vec3> loop;
  for (int id : quad)
  {
    loop.push_back(edges.Points[id]);
  }
  // A length, not an angle between the triangles' normals: float noise of a far scene
  // turns a small triangle's normal by noise / size, which no fixed angle would allow for.
  const Vec3 triangle[3] = { loop[0], loop[2], loop[3] };
  const Vec3 nt = NewellVector(triangle, 3);
  const Vec3 nu = Cross(edges.Points[b[1]] - edges.Points[b[0]], edges.Points[b[2]] - edges.Points[b[0]]);
  const bool flat = Dot(nt, nu) > 0 && WarpOffset(loop) <= flatness;
  return flat && IsConvex(loop.data(), 4) ? quad : std::vector<int>();
}
} // namespace

PairedPolygons MergeTrianglePairs(const std::vector<Vec3>& points, const std::vector<int>& offsets,
  const std::vector<int>& connectivity, const std::vector<int>& surfaceKey, double tolerance, double flatness)
{
  const int count = static_cast<int>(offsets.size()) - 1;
  const double joinFlatness = std::max(tolerance, flatness);
  TriangleEdges edges{ points, offsets, connectivity, std::max(tolerance, 1e-300), {} };
  for (int t = 0; t < count; ++t)
  {
    for (int e = 0; edges.IsTriangle(t) && e < 3; ++e)
    {
      edges.Triangles[edges.Edge(edges.Corners(t)[e], edges.Corners(t)[(e + 1) % 3])].push_back(t);
    }
  }
  std::vector<char> used(count, 0);
  PairedPolygons out;
  auto emit = [&](const std::vector<int>& loop, int source) {
    out.Connectivity.insert(out.Connectivity.end(), loop.begin(), loop.end());
    out.Offsets.push_back(static_cast<int>(out.Connectivity.size()));
    out.Source.push_back(source);
  };
  for (int t = 0; t < count; ++t)
  {
    if (used[t])
    {
      continue;
    }
    used[t] = 1;
    std::vector<int> loop(connectivity.begin() + offsets[t], connectivity.begin() + offsets[t + 1]);
    if (edges.IsTriangle(t))
    {
      const int* c = edges.Corners(t);
      std::array<int, 3> order = { 0, 1, 2 };
      auto length = [&](int e) { return Norm(points[c[(e + 1) % 3]] - points[c[e]]); };
      std::sort(order.begin(), order.end(), [&](int x, int y) { return length(x) > length(y); });
      for (int e : order)
      {
        bool joined = false;
        for (int u : edges.Triangles[edges.Edge(c[e], c[(e + 1) % 3])])
        {
          if (u == t || used[u] || surfaceKey[u] != surfaceKey[t])
          {
            continue;
          }
          const std::vector<int> quad = JoinedQuad(edges, t, e, u, joinFlatness);
          if (!quad.empty())
          {
            loop = quad;
            used[u] = 1;
            ++out.Merged;
            joined = true;
            break;
          }
        }
        if (joined)
        {
          break;
        }
      }
    }
    emit(loop, t);
  }
  return out;
}

} // namespace radiosity
