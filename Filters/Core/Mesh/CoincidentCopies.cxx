#include "Mesh/CoincidentCopies.h"
#include "Mesh/KeepingOrder.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace radiosity
{
namespace
{
/// The polygon's corners rounded to the tolerance and sorted, and the side it faces (the
/// sign of its normal's largest component): equal for copies, whatever corner they start at.
std::vector<long long> Key(const std::vector<Vec3>& points, const int* ids, int count, double tolerance)
{
  std::vector<std::array<long long, 3>> corners;
  Vec3 normal;
  for (int k = 0; k < count; ++k)
  {
    const Vec3& p = points[ids[k]];
    const Vec3& q = points[ids[(k + 1) % count]];
    normal += Vec3{ (p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y) };
    corners.push_back({ std::llround(p.x / tolerance), std::llround(p.y / tolerance), std::llround(p.z / tolerance) });
  }
  std::sort(corners.begin(), corners.end());
  std::vector<long long> key;
  for (const auto& c : corners)
  {
    key.insert(key.end(), c.begin(), c.end());
  }
  const double largest[3] = { std::fabs(normal.x), std::fabs(normal.y), std::fabs(normal.z) };
  const int axis = static_cast<int>(std::max_element(largest, largest + 3) - largest);
  key.push_back(normal[axis] > 0 ? 1 : -1);
  return key;
}
} // namespace

CoincidentCopies DropCoincidentCopies(const std::vector<Vec3>& points, const std::vector<int>& surfaceKey,
  const std::vector<char>& lamps, double tolerance, PairedPolygons& polygons)
{
  const auto surface = [&](int s) { return s < static_cast<int>(surfaceKey.size()) ? surfaceKey[s] : 0; };
  const KeepingOrder order(lamps, polygons);
  // The polygon kept of each set of copies: the first in the keeping order.
  const size_t count = polygons.Source.size();
  std::map<std::vector<long long>, size_t> chosen; // key -> polygon kept
  std::vector<std::map<std::vector<long long>, size_t>::iterator> set(count);
  for (size_t i = 0; i < count; ++i)
  {
    const int* ids = polygons.Connectivity.data() + polygons.Offsets[i];
    const auto [at, isNew] =
      chosen.emplace(Key(points, ids, polygons.Offsets[i + 1] - polygons.Offsets[i], tolerance), i);
    if (!isNew && order.Before(i, at->second))
    {
      at->second = i;
    }
    set[i] = at;
  }
  CoincidentCopies found;
  PairedPolygons kept;
  kept.Merged = polygons.Merged;
  for (size_t i = 0; i < count; ++i)
  {
    const int source = polygons.Source[i], keeper = polygons.Source[set[i]->second];
    // Two lamps of different lights: both stay (one would be a light lost), and are said.
    const bool otherLamp = order.IsLamp(i) && order.IsLamp(set[i]->second) && surface(keeper) != surface(source);
    if (otherLamp)
    {
      found.LampsKept.emplace_back(keeper, source);
    }
    if (set[i]->second != i && !otherLamp)
    {
      if (surface(keeper) == surface(source))
      {
        found.Dropped.push_back(source);
      }
      else
      {
        found.Differing.emplace_back(keeper, source);
      }
      continue;
    }
    kept.Connectivity.insert(kept.Connectivity.end(), polygons.Connectivity.data() + polygons.Offsets[i],
      polygons.Connectivity.data() + polygons.Offsets[i + 1]);
    kept.Offsets.push_back(static_cast<int>(kept.Connectivity.size()));
    kept.Source.push_back(source);
  }
  polygons = std::move(kept);
  return found;
}

} // namespace radiosity
