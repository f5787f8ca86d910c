#include "Solve/MethodCost.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace radiosity
{

namespace
{
double Quantile(std::vector<double> values, double q)
{
  const size_t at = std::min(values.size() - 1, static_cast<size_t>(q * values.size()));
  std::nth_element(values.begin(), values.begin() + at, values.end());
  return values[at];
}

/// The centroids hashed into cubes of side `cell`.
class CentroidGrid
{
public:
  CentroidGrid(const std::vector<Vec3>& centroids, const std::vector<int>& elements, double cell)
    : Cell(cell)
  {
    for (int e : elements)
    {
      Cells[Key(Index(centroids[e]))].push_back(e);
    }
  }

  struct Triple
  {
    int64_t x, y, z;
  };

  Triple Index(const Vec3& p) const
  {
    return { static_cast<int64_t>(std::floor(p.x / Cell)), static_cast<int64_t>(std::floor(p.y / Cell)),
      static_cast<int64_t>(std::floor(p.z / Cell)) };
  }

  const std::vector<int>* Find(const Triple& t) const
  {
    auto it = Cells.find(Key(t));
    return it == Cells.end() ? nullptr : &it->second;
  }

private:
  static uint64_t Key(const Triple& t)
  {
    const uint64_t mask = (1u << 21) - 1;
    return (static_cast<uint64_t>(t.x) & mask) | ((static_cast<uint64_t>(t.y) & mask) << 21) |
      ((static_cast<uint64_t>(t.z) & mask) << 42);
  }

  double Cell;
  std::unordered_map<uint64_t, std::vector<int>> Cells;
};

/// Whether element b rises in front of element a's plane (its centroid, or its radius
/// where it is tilted): the element tree's test for leaves, on centroids and radii.
bool InFront(const SceneGeometry& g, const std::vector<double>& radius, int a, int b)
{
  const double lift = Dot(g.Centroid[b] - g.Centroid[a], g.Normal[a]);
  const bool parallel = std::abs(Dot(g.Normal[a], g.Normal[b])) > 1 - 1e-9;
  return lift + (parallel ? 0.0 : radius[b]) > 1e-9 * (radius[a] + radius[b]);
}

/// The elements near element a that face it and that it faces, in the cubes within `span`;
/// `scanned` counts the candidates looked at.
int NearAround(const SceneGeometry& g, const std::vector<double>& radius, const CentroidGrid& grid, int a,
  int64_t span, double separation, long long& scanned)
{
  int pairs = 0;
  const CentroidGrid::Triple at = grid.Index(g.Centroid[a]);
  for (int64_t x = at.x - span; x <= at.x + span; ++x)
    for (int64_t y = at.y - span; y <= at.y + span; ++y)
      for (int64_t z = at.z - span; z <= at.z + span; ++z)
      {
        const std::vector<int>* cube = grid.Find({ x, y, z });
        scanned += cube ? static_cast<long long>(cube->size()) : 0;
        for (size_t i = 0; cube && i < cube->size(); ++i)
        {
          const int b = (*cube)[i];
          const bool near = b != a && Norm(g.Centroid[b] - g.Centroid[a]) <= separation * (radius[a] + radius[b]);
          pairs += near && InFront(g, radius, a, b) && InFront(g, radius, b, a) ? 1 : 0;
        }
      }
  return pairs;
}
/// The elements the clustered method links (ElementTree's leaves: open, of some area).
std::vector<int> LinkedElements(const SceneGeometry& g)
{
  std::vector<int> linked;
  for (size_t e = 0; e < g.Centroid.size(); ++e)
  {
    if (!g.Enclosed[e] && g.Area[e] > 0)
    {
      linked.push_back(static_cast<int>(e));
    }
  }
  return linked;
}

/// Up to `count` of `linked`, spread over the scene, in a fixed order: the smallest by a
/// multiplicative hash of the index (elements come patch by patch, and every k-th of them
/// would keep landing on the same corners).
std::vector<int> SpreadSample(const std::vector<int>& linked, size_t count)
{
  std::vector<std::pair<uint32_t, int>> keyed(linked.size());
  std::transform(linked.begin(), linked.end(), keyed.begin(),
    [](int e) { return std::make_pair(static_cast<uint32_t>(static_cast<uint32_t>(e) * 2654435761u), e); });
  count = std::min(count, keyed.size());
  std::nth_element(keyed.begin(), keyed.begin() + (count - 1), keyed.end());
  std::sort(keyed.begin(), keyed.begin() + count);
  std::vector<int> sample(count);
  std::transform(keyed.begin(), keyed.begin() + count, sample.begin(), [](const std::pair<uint32_t, int>& k) { return k.second; });
  return sample;
}
} // namespace

double EstimateNearPairs(const SceneMesh& mesh, const SceneGeometry& g, double separation)
{
  const std::vector<int> linked = LinkedElements(g);
  if (linked.size() < 2)
  {
    return 0;
  }
  std::vector<double> radius(g.Centroid.size());
  for (size_t e = 0; e < radius.size(); ++e)
  {
    radius[e] = ElementRadius(mesh, g, static_cast<int>(e));
  }
  std::vector<double> linkedRadius(linked.size());
  std::transform(linked.begin(), linked.end(), linkedRadius.begin(), [&](int e) { return radius[e]; });
  const double typical = Quantile(linkedRadius, 0.5);
  const double large = std::max(Quantile(linkedRadius, 0.99), typical);
  const double cell = 2 * separation * typical;
  if (!(cell > 0) || !std::isfinite(cell))
  {
    return 0;
  }
  const CentroidGrid grid(g.Centroid, linked, cell);
  // Around an element far larger than the rest only nearby cubes are searched, and a dense
  // knot of tiny elements stops the count early (the samples are spread, so those taken
  // stand for all): an estimate, bounded in time.
  const int64_t widest = 6;
  const long long mostScanned = 50000000;
  double pairs = 0;
  long long scanned = 0;
  size_t sampled = 0;
  const std::vector<int> sample = SpreadSample(linked, 4000);
  for (; sampled < sample.size() && scanned < mostScanned; ++sampled)
  {
    const int a = sample[sampled];
    const int64_t span = std::min(widest, static_cast<int64_t>(std::ceil(separation * (radius[a] + large) / cell)));
    pairs += NearAround(g, radius, grid, a, span, separation, scanned);
  }
  return pairs * static_cast<double>(linked.size()) / static_cast<double>(sampled);
}

/// Fitted on 15 solves of the paper scene, the Cornell box, the furnished room and the
/// sphere room (1.7k to 78k elements, 115 to 4,834 patches, each at the suggested sizes and
/// 2x and 4x finer; 2026-12-03, docs/benchmarks.md): the links cost about 100 ns per
/// element-patch pair, less where a patch holds many elements (a far patch takes them as a
/// whole). Where the two methods cross (about 1,200 patches of 16 elements) both cost about
/// the same, so a wrong pick there costs little.
double HierarchicalSeconds(double elements, double patches)
{
  const double perPatch = elements / std::max(1.0, patches);
  return 100e-9 * elements * patches * std::pow(16.0 / std::max(16.0, perPatch), 0.3);
}

/// Fitted on five clustered solves, 62k to 149k elements with 9 to 1,300 estimated near
/// pairs per element (the FZK-Haus, the 2CylinderEngine in a room, the sphere and furnished
/// rooms; the solves and the fit's errors are in docs/benchmarks.md): the near pairs, not
/// the elements alone, set the time. Above 100k elements the node sums no longer stay in
/// the caches, which the last factor allows for.
double ClusteredSeconds(double elements, double nearPairs)
{
  const double caches = std::pow(std::max(1.0, elements / 1e5), 0.25);
  return (80e-6 * elements + 0.45e-6 * nearPairs) * caches;
}

} // namespace radiosity
