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
  void Add(const PolygonPlane& f, int group, const Vec3& centre)
  {
    Cells[Cell(f.Key, f.Normal, 0, 0, 0)].emplace(Dot(f.Normal, f.Centroid - centre), group);
  }
};

struct Candidate
{
  int Group = -1;
  double Distance = 1; ///< as a fraction of the pair's tolerances: at most 1 to join
};

/// The tolerance class a polygon is taken in: classes a factor of 16 wide, so that float
/// rounding of a scaled or turned copy does not reorder polygons of one size (sorting by
/// the tolerance itself chose other founders: the FZK-Haus grouped 23 of its 7,639 patches
/// otherwise).
int ToleranceClass(double tolerance)
{
  return static_cast<int>(std::floor(std::log2(tolerance / kLeastTolerance) / 4));
}

/// What the grouping keeps while it goes through the polygons.
struct Grouping
{
  const std::vector<PolygonPlane>& Planes;
  const double OffsetTolerance;
  const Vec3 Centre;
  double Reach = 0;         ///< the farthest centroid from the centre
  double FounderWidest = 0; ///< the largest tolerance of a founder so far
  FounderIndex Index;
  std::vector<int> Founders;

  /// The nearest founder polygon `a` may join, by the join test of GroupCoplanar.
  Candidate Nearest(const PolygonPlane& a) const;
  /// Polygon `p`'s group: the nearest founder's, or a new one it founds.
  int Place(int p);
  /// The index with normal cells of `step` (twice the widest tolerance of a class).
  void Reindex(double step);
};

Candidate Grouping::Nearest(const PolygonPlane& a) const
{
  const double own = Dot(a.Normal, a.Centroid - Centre), d = Norm(a.Centroid - Centre);
  // A founder f that passes the test has an offset along its own normal within this of
  // this polygon's along its own: the normals differ by up to both tolerances over d, and
  // f's plane is uncertain by its tolerance over the distance between them (at most d + Reach).
  const double slack = (OffsetTolerance + a.Tolerance * d + FounderWidest * (2 * d + Reach)) * (1 + 1e-9);
  Candidate best;
  for (int step = 0; step < 27; ++step)
  {
    const auto found = Index.Cells.find(Index.Cell(a.Key, a.Normal, step % 3 - 1, step / 3 % 3 - 1, step / 9 - 1));
    if (found == Index.Cells.end())
    {
      continue;
    }
    const auto end = found->second.upper_bound(own + slack);
    for (auto it = found->second.lower_bound(own - slack); it != end; ++it)
    {
      const PolygonPlane& f = Planes[Founders[it->second]];
      const double lever = Norm(a.Centroid - f.Centroid);
      const double distance = std::max(Norm(a.Normal - f.Normal) / (a.Tolerance + f.Tolerance),
        std::fabs(Dot(f.Normal, a.Centroid - f.Centroid)) / (OffsetTolerance + f.Tolerance * lever));
      if (distance <= best.Distance && (best.Group < 0 || distance < best.Distance || it->second < best.Group))
      {
        best = { it->second, distance };
      }
    }
  }
  return best;
}

int Grouping::Place(int p)
{
  const Candidate best = Nearest(Planes[p]);
  if (best.Group >= 0)
  {
    return best.Group;
  }
  const int group = static_cast<int>(Founders.size());
  Founders.push_back(p);
  FounderWidest = std::max(FounderWidest, Planes[p].Tolerance);
  Index.Add(Planes[p], group, Centre);
  return group;
}

void Grouping::Reindex(double step)
{
  Index = FounderIndex();
  Index.Step = step;
  for (size_t g = 0; g < Founders.size(); ++g)
  {
    Index.Add(Planes[Founders[g]], static_cast<int>(g), Centre);
  }
}

/// The groups numbered by first appearance (the surfaces are made in the input's order).
CoplanarGroups Numbered(const std::vector<int>& group, const std::vector<int>& founders)
{
  CoplanarGroups out;
  std::vector<int> renumber(founders.size(), -1);
  for (int g : group)
  {
    int& id = renumber[g];
    if (id < 0)
    {
      id = static_cast<int>(out.Founder.size());
      out.Founder.push_back(founders[g]);
    }
    out.Group.push_back(id);
  }
  return out;
}
} // namespace

PolygonPlane PlaneOf(const std::vector<Vec3>& loop, double noise, int key)
{
  const int count = static_cast<int>(loop.size());
  const double perimeter = Perimeter(loop);
  // Newell's vector is 2 A n; moving each corner by `noise` changes it by about noise times
  // the perimeter, so the unit normal turns by about noise P / (2 A), taken twice for margin.
  const Vec3 newell = NewellVector(loop.data(), count);
  const double area = 0.5 * Norm(newell);
  const double turn = area > 0 && std::isfinite(noise * perimeter / area) ? noise * perimeter / area : kMostTolerance;
  return { Normalized(newell), PolygonCentroid(loop.data(), count), std::clamp(turn, kLeastTolerance, kMostTolerance), key };
}

CoplanarGroups GroupCoplanar(const std::vector<PolygonPlane>& planes, double offsetTolerance, const Vec3& centre)
{
  const int count = static_cast<int>(planes.size());
  std::vector<int> order(count), rankOf(count);
  std::iota(order.begin(), order.end(), 0);
  for (int i = 0; i < count; ++i)
  {
    rankOf[i] = ToleranceClass(planes[i].Tolerance);
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return rankOf[a] < rankOf[b]; });
  Grouping grouping{ planes, offsetTolerance, centre, 0, 0, {}, {} };
  for (const PolygonPlane& p : planes)
  {
    grouping.Reach = std::max(grouping.Reach, Norm(p.Centroid - centre));
  }
  std::vector<int> group(count, -1);
  for (int begin = 0; begin < count;)
  {
    // Normal cells as wide as this class needs (a joining pair's normals are at most its
    // widest tolerance and an earlier founder's apart): one sliver capped at the most
    // tolerance would otherwise widen the cells of every precise polygon.
    const int rank = rankOf[order[begin]];
    int end = begin;
    double widest = kLeastTolerance;
    for (; end < count && rankOf[order[end]] == rank; ++end)
    {
      widest = std::max(widest, planes[order[end]].Tolerance);
    }
    grouping.Reindex(2 * widest * (1 + 1e-9));
    for (int k = begin; k < end; ++k)
    {
      group[order[k]] = grouping.Place(order[k]);
    }
    begin = end;
  }
  return Numbered(group, grouping.Founders);
}

} // namespace radiosity
