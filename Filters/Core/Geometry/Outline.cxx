#include "Geometry/Outline.h"

#include <algorithm>
#include <map>
#include <utility>

namespace radiosity
{

namespace
{
/// Directed edges by point id, with how many times each is left uncancelled.
using EdgeCounts = std::map<std::pair<int, int>, int>;

/// Adds `count` copies of the directed edge, first cancelling as many of its reverse.
void AddEdge(EdgeCounts& edges, int from, int to, int count)
{
  auto reverse = edges.find({ to, from });
  for (; count > 0 && reverse != edges.end() && reverse->second > 0; --count)
  {
    --reverse->second;
  }
  if (reverse != edges.end() && reverse->second == 0)
  {
    edges.erase(reverse);
  }
  if (count > 0)
  {
    edges[{ from, to }] += count;
  }
}

EdgeCounts SplitAtJunctions(const SceneMesh& mesh, const EdgeCounts& edges)
{
  // An element cut beside an uncut one (the mesher's contact cuts, or polygons meshed apart
  // on one patch) leaves an edge whose reverse runs in two parts through a point on it (a
  // T-junction): nothing cancels, and the outline would not close. Split what is left at
  // the points that lie on it, then cancel again. Only the few edges left are searched.
  std::vector<int> ends;
  for (const auto& edge : edges)
  {
    ends.push_back(edge.first.first);
    ends.push_back(edge.first.second);
  }
  std::sort(ends.begin(), ends.end());
  ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
  EdgeCounts split;
  std::vector<std::pair<double, int>> inside;
  for (const auto& edge : edges)
  {
    const Vec3& a = mesh.Points[edge.first.first];
    const Vec3 ab = mesh.Points[edge.first.second] - a;
    const double length2 = Dot(ab, ab);
    inside.clear();
    for (int w : ends)
    {
      const Vec3 aw = mesh.Points[w] - a;
      const double t = length2 > 0 ? Dot(aw, ab) / length2 : 0.0;
      if (t > 1e-9 && t < 1 - 1e-9 && Norm(Cross(ab, aw)) <= 1e-9 * length2)
      {
        inside.push_back({ t, w });
      }
    }
    std::sort(inside.begin(), inside.end());
    int from = edge.first.first;
    for (const auto& stop : inside)
    {
      AddEdge(split, from, stop.second, edge.second);
      from = stop.second;
    }
    AddEdge(split, from, edge.first.second, edge.second);
  }
  return split;
}

/// Boundary edges (by point id, with multiplicity) as segments, straight runs joined.
std::vector<Vec3> MergeCollinear(const SceneMesh& mesh, const EdgeCounts& edges)
{
  // Elements put points along the patch border; without merging, the outline (and the
  // cost of every form factor to the patch) would grow with the number of elements.
  std::map<int, std::vector<int>> next, previous;
  for (const auto& edge : edges)
  {
    if (edge.second == 1)
    {
      next[edge.first.first].push_back(edge.first.second);
      previous[edge.first.second].push_back(edge.first.first);
    }
  }
  auto passThrough = [&](int b) {
    const auto in = previous.find(b), out = next.find(b);
    if (in == previous.end() || out == next.end() || in->second.size() != 1 || out->second.size() != 1)
    {
      return false;
    }
    const Vec3& a = mesh.Points[in->second[0]];
    const Vec3& c = mesh.Points[out->second[0]];
    const Vec3 ab = mesh.Points[b] - a, bc = c - mesh.Points[b];
    return Dot(ab, bc) > 0 && Norm(Cross(ab, bc)) <= 1e-9 * Norm(ab) * Norm(bc);
  };
  std::vector<Vec3> outline;
  for (const auto& edge : edges)
  {
    const int start = edge.first.first;
    if (edge.second != 1)
    {
      for (int c = 0; c < edge.second; ++c)
      {
        outline.push_back(mesh.Points[start]);
        outline.push_back(mesh.Points[edge.first.second]);
      }
      continue;
    }
    if (passThrough(start))
    {
      continue; // inside a straight run that another edge starts
    }
    int end = edge.first.second;
    for (size_t guard = 0; passThrough(end) && guard < edges.size(); ++guard)
    {
      end = next[end][0];
    }
    outline.push_back(mesh.Points[start]);
    outline.push_back(mesh.Points[end]);
  }
  return outline;
}
} // namespace

std::vector<Vec3> PolygonSetOutline(const SceneMesh& mesh, const std::vector<int>& polygons)
{
  // An edge and its reverse are interior and cancel.
  EdgeCounts edges;
  for (int e : polygons)
  {
    const int* ids = mesh.Polygon(e);
    const int count = mesh.PolygonSize(e);
    for (int v = 0; v < count; ++v)
    {
      AddEdge(edges, ids[v], ids[(v + 1) % count], 1);
    }
  }
  return MergeCollinear(mesh, SplitAtJunctions(mesh, edges));
}

} // namespace radiosity
