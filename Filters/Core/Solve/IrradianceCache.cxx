#include "Solve/IrradianceCache.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace radiosity
{
namespace
{
/// Normals further apart than this share no record: beyond it, the light a point faces
/// is another part of the scene's.
const double kAgree = std::cos(20.0 * M_PI / 180.0);

/// A point reads the records of earlier levels only where their weights sum to this much:
/// at a record's fringe alone its value is about to stop holding.
const double kCovered = 0.2;

double Coordinate(const Vec3& v, int axis)
{
  return axis == 0 ? v.x : axis == 1 ? v.y : v.z;
}

double Weight(const CacheRecord& r, const Vec3& x, const Vec3& normal)
{
  const Vec3 d = x - r.Origin;
  const double distance = Norm(d);
  const double agree = Dot(normal, r.Normal);
  if (!(distance < r.Reach) || agree <= kAgree)
  {
    return 0.0;
  }
  // Ward's test: a record whose surface stands above the point's (along their mean normal)
  // sees what the point does not. A fifth of the distance lets a curved surface's
  // neighbours, whose normals differ by up to 20 degrees, read each other.
  if (Dot(d, normal + r.Normal) * 0.5 < -0.2 * distance)
  {
    return 0.0;
  }
  const double turned = std::sqrt(std::max(0.0, 1.0 - agree) / (1.0 - kAgree));
  return 1.0 - std::max(distance / r.Reach, turned);
}
} // namespace

void StratifiedRays::Reset(int side, int solutions)
{
  Side = side;
  Solutions = solutions;
  const size_t cells = static_cast<size_t>(side) * side;
  U.assign(cells, 0.0);
  CosPhi.assign(cells, 1.0);
  SinPhi.assign(cells, 0.0);
  Distance.assign(cells, std::numeric_limits<double>::infinity());
  Values.assign(cells * solutions, Vec3());
}

void IrradianceGradients(const StratifiedRays& rays, Vec3* translation, Vec3* rotation)
{
  const int n = rays.Side, S = rays.Solutions;
  std::fill(translation, translation + 3 * S, Vec3());
  std::fill(rotation, rotation + 3 * S, Vec3());
  const size_t cells = static_cast<size_t>(n) * n;
  auto at = [n](int i, int k) { return static_cast<size_t>(i) * n + k; };
  auto distance = [&](int i, int k) { return rays.Distance[at(i, k)]; };
  // Each cell's value enters the gradients once, by a vector (summed by parts from the
  // boundaries' differences): the solutions' loop then does the least per cell.
  thread_local std::vector<Vec3> move, turn;
  move.assign(cells, Vec3());
  turn.resize(cells);
  thread_local std::vector<double> radius;
  radius.resize(n + 1);
  for (int i = 0; i <= n; ++i)
  {
    radius[i] = std::sqrt(static_cast<double>(i) / n);
  }
  // The values are radiosities, the irradiance their mean: a radiance is value / pi.
  for (int k = 0; k < n; ++k)
  {
    const double centre = 2 * M_PI * (k + 0.5) / n, edge = 2 * M_PI * k / n;
    const Vec3 along = rays.T * std::cos(centre) + rays.B * std::sin(centre);
    const Vec3 across = rays.T * -std::sin(edge) + rays.B * std::cos(edge);
    const int before = (k + n - 1) % n;
    for (int i = 0; i < n; ++i)
    {
      const double low = radius[i], high = radius[i + 1];
      // The boundary with the stratum nearer the normal, moving as the point goes along it.
      const double rTheta = i > 0 ? std::min(distance(i, k), distance(i - 1, k)) : 0.0;
      const double wTheta = i > 0 && std::isfinite(rTheta) ? 2.0 / n * low * (1 - low * low) / rTheta : 0.0;
      if (wTheta > 0)
      {
        move[at(i, k)] += along * wTheta;
        move[at(i - 1, k)] += along * -wTheta;
      }
      // The boundary with the stratum before in phi, moving as the point goes across it.
      const double rPhi = std::min(distance(i, k), distance(i, before));
      const double wPhi = std::isfinite(rPhi) ? (high - low) / rPhi / M_PI : 0.0;
      if (wPhi > 0)
      {
        move[at(i, k)] += across * wPhi;
        move[at(i, before)] += across * -wPhi;
      }
    }
  }
  for (size_t cell = 0; cell < cells; ++cell)
  {
    const double u = std::min(rays.U[cell], 1 - 1e-6);
    turn[cell] = (rays.T * -rays.SinPhi[cell] + rays.B * rays.CosPhi[cell]) * (std::sqrt(u / (1 - u)) / cells);
  }
  for (size_t cell = 0; cell < cells; ++cell)
  {
    const Vec3* values = &rays.Values[cell * S];
    for (int m = 0; m < S; ++m)
    {
      const Vec3& v = values[m];
      translation[3 * m] += move[cell] * v.x;
      translation[3 * m + 1] += move[cell] * v.y;
      translation[3 * m + 2] += move[cell] * v.z;
      rotation[3 * m] += turn[cell] * v.x;
      rotation[3 * m + 1] += turn[cell] * v.y;
      rotation[3 * m + 2] += turn[cell] * v.z;
    }
  }
}

double RecordReach(double accuracy, double inverseDistanceSum, int rays, double nearest, double largest)
{
  if (rays <= 0 || !(accuracy > 0))
  {
    return 0.0;
  }
  const double harmonic = inverseDistanceSum > 0 ? rays / inverseDistanceSum : std::numeric_limits<double>::infinity();
  return std::min({ accuracy * harmonic, nearest, largest });
}

IrradianceCache::IrradianceCache(std::vector<CacheRecord> records)
{
  for (const CacheRecord& r : records)
  {
    if (r.Reach > 0)
    {
      Items.push_back(r);
    }
  }
  if (!Items.empty())
  {
    Nodes.reserve(2 * Items.size());
    Build(0, static_cast<int>(Items.size()));
  }
}

int IrradianceCache::Build(int first, int count)
{
  const int at = static_cast<int>(Nodes.size());
  Nodes.emplace_back();
  Vec3 low{ 1e300, 1e300, 1e300 }, high{ -1e300, -1e300, -1e300 };
  for (int i = first; i < first + count; ++i)
  {
    const Vec3& o = Items[i].Origin;
    const double r = Items[i].Reach;
    low = { std::min(low.x, o.x - r), std::min(low.y, o.y - r), std::min(low.z, o.z - r) };
    high = { std::max(high.x, o.x + r), std::max(high.y, o.y + r), std::max(high.z, o.z + r) };
  }
  Nodes[at].Low = low;
  Nodes[at].High = high;
  if (count <= 4)
  {
    Nodes[at].First = first;
    Nodes[at].Count = count;
    return at;
  }
  const Vec3 size = high - low;
  const int axis = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
  // Ties by point index: the tree, and so the order a point's weights are found and summed
  // in, depends on the records alone (which PlaceRecords makes the same on any thread count).
  std::nth_element(Items.begin() + first, Items.begin() + first + count / 2, Items.begin() + first + count,
    [axis](const CacheRecord& a, const CacheRecord& b) {
      const double ka = Coordinate(a.Origin, axis), kb = Coordinate(b.Origin, axis);
      return ka < kb || (ka == kb && a.Point < b.Point);
    });
  const int left = Build(first, count / 2);
  const int right = Build(first + count / 2, count - count / 2);
  Nodes[at].Left = left;
  Nodes[at].Right = right;
  return at;
}

double IrradianceCache::Weights(const Vec3& x, const Vec3& normal, std::vector<std::pair<int, double>>& out) const
{
  out.clear();
  double sum = 0;
  if (Nodes.empty())
  {
    return sum;
  }
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0)
  {
    const Node& n = Nodes[stack[--top]];
    if (x.x < n.Low.x || x.y < n.Low.y || x.z < n.Low.z || x.x > n.High.x || x.y > n.High.y || x.z > n.High.z)
    {
      continue;
    }
    if (n.Left < 0)
    {
      for (int i = n.First; i < n.First + n.Count; ++i)
      {
        const double w = Weight(Items[i], x, normal);
        if (w > 0)
        {
          out.emplace_back(i, w);
          sum += w;
        }
      }
      continue;
    }
    stack[top++] = n.Right;
    stack[top++] = n.Left;
  }
  return sum;
}
} // namespace radiosity

namespace radiosity
{
std::vector<CacheRecord> PlaceRecords(const std::vector<Vec3>& origins, const std::vector<Vec3>& normals,
  const std::function<std::vector<CacheRecord>(const std::vector<int>&)>& gather,
  const std::function<void(int, const std::function<void(int, int)>&)>& inParallel)
{
  const int points = static_cast<int>(origins.size());
  std::vector<CacheRecord> records;
  std::vector<char> gathered(points, 0);
  for (int stride : { 256, 64, 16, 4, 1 })
  {
    const IrradianceCache cache(records);
    std::vector<char> uncovered(points, 0);
    inParallel(points, [&](int begin, int end) {
      std::vector<std::pair<int, double>> weights;
      for (int q = begin; q < end; ++q)
      {
        uncovered[q] = q % stride == 0 && !gathered[q] && cache.Weights(origins[q], normals[q], weights) < kCovered;
      }
    });
    std::vector<int> level;
    for (int q = 0; q < points; ++q)
    {
      if (uncovered[q])
      {
        level.push_back(q);
        gathered[q] = 1;
      }
    }
    if (level.empty())
    {
      continue;
    }
    std::vector<CacheRecord> found = gather(level);
    const bool stopped = found.size() < level.size();
    records.insert(records.end(), found.begin(), found.end());
    if (stopped)
    {
      break;
    }
  }
  return records;
}
} // namespace radiosity
