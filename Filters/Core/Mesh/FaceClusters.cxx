#include "Mesh/FaceClusters.h"
#include "Geometry/Polygon.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <utility>

namespace radiosity
{

namespace
{
struct PatchSummary
{
  Vec3 Centre, Normal;
  double Area = 0, Radius = 0;
  int Key = 0;
};

std::vector<PatchSummary> Summarise(const MeshedPolygons& mesh, const std::vector<int>& surfaceKey)
{
  std::vector<PatchSummary> patches(mesh.Patches);
  const int n = static_cast<int>(mesh.Offsets.size()) - 1;
  std::vector<Vec3> loop;
  for (int e = 0; e < n; ++e)
  {
    loop.assign(mesh.Offsets[e + 1] - mesh.Offsets[e], Vec3());
    for (int v = mesh.Offsets[e]; v < mesh.Offsets[e + 1]; ++v)
    {
      loop[v - mesh.Offsets[e]] = mesh.Points[mesh.Connectivity[v]];
    }
    const Vec3 newell = NewellVector(loop.data(), static_cast<int>(loop.size()));
    const double area = 0.5 * Norm(newell);
    PatchSummary& p = patches[mesh.PatchId[e]];
    p.Centre += PolygonCentroid(loop.data(), static_cast<int>(loop.size())) * area;
    p.Normal += newell * 0.5;
    p.Area += area;
    p.Key = surfaceKey[mesh.SourcePolygon[e]];
  }
  for (PatchSummary& p : patches)
  {
    p.Centre = p.Area > 0 ? p.Centre * (1.0 / p.Area) : p.Centre;
    p.Normal = Normalized(p.Normal);
  }
  for (int e = 0; e < n; ++e)
  {
    PatchSummary& p = patches[mesh.PatchId[e]];
    for (int v = mesh.Offsets[e]; v < mesh.Offsets[e + 1]; ++v)
    {
      p.Radius = std::max(p.Radius, Norm(mesh.Points[mesh.Connectivity[v]] - p.Centre));
    }
  }
  return patches;
}

/// The patches next to each patch: those whose input polygons share an edge with its own,
/// by the position of the input's points, within `tolerance` (a small patch holds whole
/// input polygons; corners that overlap cuts made, and the mesher's own points along split
/// edges, are computed from float input, so they may sit its noise off the corners they
/// meet, where the input's are copies of each other).
std::vector<std::vector<int>> Neighbours(const MeshedPolygons& mesh, const PolygonArrays& input, double tolerance)
{
  const std::vector<int> welded = WeldedPointIds(input.Points, tolerance);
  // By the mesher's polygon, not the input's: a warped input polygon is several triangles.
  std::vector<int> cellPatch(input.Offsets.size() - 1, -1);
  for (size_t e = 0; e < mesh.MeshedPolygon.size(); ++e)
  {
    cellPatch[mesh.MeshedPolygon[e]] = mesh.PatchId[e];
  }
  std::vector<std::pair<std::uint64_t, int>> edges;
  for (size_t c = 0; c < cellPatch.size(); ++c)
  {
    const int begin = input.Offsets[c], count = input.Offsets[c + 1] - begin;
    for (int v = 0; v < count && cellPatch[c] >= 0; ++v)
    {
      const std::uint64_t a = welded[input.Connectivity[begin + v]];
      const std::uint64_t b = welded[input.Connectivity[begin + (v + 1) % count]];
      edges.push_back({ std::min(a, b) << 32 | std::max(a, b), cellPatch[c] });
    }
  }
  std::sort(edges.begin(), edges.end());
  std::vector<std::vector<int>> next(mesh.Patches);
  for (size_t i = 0; i < edges.size();)
  {
    size_t j = i;
    while (j < edges.size() && edges[j].first == edges[i].first)
    {
      ++j;
    }
    for (size_t a = i; a < j; ++a)
    {
      for (size_t b = a + 1; b < j; ++b)
      {
        if (edges[a].second != edges[b].second)
        {
          next[edges[a].second].push_back(edges[b].second);
          next[edges[b].second].push_back(edges[a].second);
        }
      }
    }
    i = j;
  }
  for (std::vector<int>& list : next)
  {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return next;
}
/// How far a face cluster reaches from its first patch's centre, in PatchSize. A curved
/// cluster shoots one value from surfaces turned up to ClusterAngle apart, so it is kept
/// smaller than a flat patch: 0.3 (0.6 PatchSize across) came closer to Mitsuba 3 than 0.5
/// on the sphere rooms of `bench polygons` in the same time, and 0.2 gained no more
/// (docs/benchmarks.md, "Curved models").
constexpr double kClusterReach = 0.3;
} // namespace

int ClusterFaces(MeshedPolygons& mesh, const PolygonArrays& input, const std::vector<int>& surfaceKey, double patchSize,
  double coneDegrees, double weld)
{
  if (!(coneDegrees > 0) || !(patchSize > 0) || mesh.Patches < 2)
  {
    return 0;
  }
  const std::vector<PatchSummary> patches = Summarise(mesh, surfaceKey);
  const std::vector<std::vector<int>> next =
    Neighbours(mesh, input, std::max({ Span(input.Points) * 1e-9, weld, 1e-300 }));
  // Models come in whole sizes, so limits are met exactly; slack above float noise (VTK's
  // float points 1 km away: 1e-5 of a 5 m patch) keeps it from deciding which side they fall.
  const double slack = 1 + 1e-4;
  const double cosCone = std::cos(coneDegrees * Pi / 180.0) - 1e-4, reach = kClusterReach * patchSize * slack;
  auto small = [&](int p) { return patches[p].Radius <= 0.5 * reach && patches[p].Area > 0; };
  std::vector<int> cluster(mesh.Patches, -1);
  std::deque<int> frontier;
  for (int seed = 0; seed < mesh.Patches; ++seed)
  {
    if (cluster[seed] >= 0)
    {
      continue;
    }
    cluster[seed] = seed;
    if (!small(seed))
    {
      continue;
    }
    const PatchSummary& s = patches[seed];
    frontier.assign(1, seed);
    while (!frontier.empty())
    {
      const int p = frontier.front();
      frontier.pop_front();
      for (int q : next[p])
      {
        const PatchSummary& c = patches[q];
        if (cluster[q] < 0 && small(q) && c.Key == s.Key && Dot(c.Normal, s.Normal) >= cosCone &&
          Norm(c.Centre - s.Centre) + c.Radius <= reach)
        {
          cluster[q] = seed;
          frontier.push_back(q);
        }
      }
    }
  }
  std::vector<int> compact(mesh.Patches, -1);
  int count = 0;
  for (int p = 0; p < mesh.Patches; ++p)
  {
    if (compact[cluster[p]] < 0)
    {
      compact[cluster[p]] = count++;
    }
  }
  for (int& id : mesh.PatchId)
  {
    id = compact[cluster[id]];
  }
  const int merged = mesh.Patches - count;
  mesh.Patches = count;
  return merged;
}

} // namespace radiosity
