#include "Mesh/CoplanarGroups.h"
#include "Geometry/Polygon.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>

namespace radiosity
{

namespace
{
/// Normals of one surface differ by at least this much in the tolerance (the precise input's
/// own rounding, where noise says less).
constexpr double kLeastTolerance = 1e-6;
/// And at most this much: a polygon whose normal noise could turn further than about half a
/// degree is too small to say which plane it lies in beyond that.
constexpr double kMostTolerance = 1e-2;

using CellKey = std::tuple<int, long long, long long, long long>;

/// The founders, by key and normal cell, each cell sorted by the founder's exact offset.
struct FounderIndex
{
  double Step = 1;
  std::map<CellKey, std::multimap<double, int>> Cells;

  CellKey Cell(int key, const Vec3& n, int dx, int dy, int dz) const
  {
    return { key, static_cast<long long>(std::floor(n.x / Step)) + dx,
      static_cast<long long>(std::floor(n.y / Step)) + dy, static_cast<long long>(std::floor(n.z / Step)) + dz };
  }
};

struct Candidate
{
  int Group = -1;
  double Distance = 1; ///< as a fraction of the pair's tolerances: at most 1 to join
};
} // namespace

PolygonPlane PlaneOf(const std::vector<Vec3>& loop, const Vec3& normal, double noise, int key)
{
  const int count = static_cast<int>(loop.size());
  double perimeter = 0;
  for (int v = 0; v < count; ++v)
  {
    perimeter += Norm(loop[(v + 1) % count] - loop[v]);
  }
  // Newell's vector is 2 A n; moving each corner by `noise` changes it by about noise times
  // the perimeter, so the unit normal turns by about noise P / (2 A), taken twice for margin.
  const double area = PolygonArea(loop.data(), count);
  const double turn = area > 0 ? noise * perimeter / area : kMostTolerance;
  return { normal, PolygonCentroid(loop.data(), count), std::clamp(turn, kLeastTolerance, kMostTolerance), key };
}

CoplanarGroups GroupCoplanar(const std::vector<PolygonPlane>& planes, double offsetTolerance, const Vec3& centre)
{
  const int count = static_cast<int>(planes.size());
  std::vector<int> order(count);
  std::iota(order.begin(), order.end(), 0);
  // By classes of tolerance, a factor of 16 wide, then in the input's order: sorting by the
  // tolerance itself let float rounding of a scaled or turned copy reorder polygons of one
  // size, and so choose other founders (the FZK-Haus grouped 23 of its 7,639 patches otherwise).
  auto rank = [&](int p) { return static_cast<int>(std::floor(std::log2(planes[p].Tolerance / kLeastTolerance) / 4)); };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return rank(a) < rank(b); });
  double widest = kLeastTolerance, reach = 0;
  for (const PolygonPlane& p : planes)
  {
    widest = std::max(widest, p.Tolerance);
    reach = std::max(reach, Norm(p.Centroid - centre));
  }
  FounderIndex index;
  index.Step = 2 * widest; // a joining pair's normals are at most two tolerances apart
  std::vector<int> founders, group(count, -1);
  for (int p : order)
  {
    const PolygonPlane& a = planes[p];
    const double own = Dot(a.Normal, a.Centroid - centre);
    // A founder's offset along its own normal differs from this polygon's along its own by
    // the normals' difference times the distance from the centre, and by its plane's
    // uncertainty over the distance between them.
    const double slack = offsetTolerance + 2 * a.Tolerance * Norm(a.Centroid - centre) + 2 * a.Tolerance * reach;
    Candidate best;
    for (int step = 0; step < 27; ++step)
    {
      const auto found = index.Cells.find(index.Cell(a.Key, a.Normal, step % 3 - 1, step / 3 % 3 - 1, step / 9 - 1));
      if (found == index.Cells.end())
      {
        continue;
      }
      const auto end = found->second.upper_bound(own + slack);
      for (auto it = found->second.lower_bound(own - slack); it != end; ++it)
      {
        const PolygonPlane& f = planes[founders[it->second]];
        const double lever = Norm(a.Centroid - f.Centroid);
        const double distance = std::max(Norm(a.Normal - f.Normal) / (a.Tolerance + f.Tolerance),
          std::fabs(Dot(f.Normal, a.Centroid - f.Centroid)) / (offsetTolerance + f.Tolerance * lever));
        if (distance <= best.Distance && (best.Group < 0 || distance < best.Distance || it->second < best.Group))
        {
          best = { it->second, distance };
        }
      }
    }
    if (best.Group < 0)
    {
      best.Group = static_cast<int>(founders.size());
      founders.push_back(p);
      index.Cells[index.Cell(a.Key, a.Normal, 0, 0, 0)].emplace(own, best.Group);
    }
    group[p] = best.Group;
  }
  // Numbered by first appearance, as the surfaces are made in the input's order.
  CoplanarGroups out;
  std::vector<int> renumber(founders.size(), -1);
  for (int p = 0; p < count; ++p)
  {
    int& id = renumber[group[p]];
    if (id < 0)
    {
      id = static_cast<int>(out.Founder.size());
      out.Founder.push_back(founders[group[p]]);
    }
    out.Group.push_back(id);
  }
  return out;
}

} // namespace radiosity
