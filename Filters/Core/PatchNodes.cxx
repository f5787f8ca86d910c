#include "PatchNodes.h"

#include <cmath>

namespace radiosity
{

namespace
{
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
} // namespace

void MeanValueCoordinates(const Vec3& x, const Vec3& normal, const std::vector<Vec3>& loop, double* weights)
{
  const size_t n = loop.size();
  std::vector<Vec3> d(n);
  std::vector<double> r(n), halfTan(n);
  for (size_t i = 0; i < n; ++i)
  {
    d[i] = loop[i] - x;
    r[i] = Norm(d[i]);
  }
  double scale = 0;
  for (double v : r)
  {
    scale = std::max(scale, v);
  }
  for (size_t i = 0; i < n; ++i)
  {
    if (r[i] <= 1e-12 * scale)
    {
      for (size_t j = 0; j < n; ++j)
      {
        weights[j] = i == j ? 1.0 : 0.0;
      }
      return;
    }
  }
  for (size_t i = 0; i < n; ++i)
  {
    // tan(a/2) = sin a / (1 + cos a), with the angle signed about the normal.
    const Vec3& a = d[i];
    const Vec3& b = d[(i + 1) % n];
    const double sine = Dot(Cross(a, b), normal) / (r[i] * r[(i + 1) % n]);
    const double cosine = Dot(a, b) / (r[i] * r[(i + 1) % n]);
    halfTan[i] = sine / std::max(1 + cosine, 1e-12);
  }
  double sum = 0;
  for (size_t i = 0; i < n; ++i)
  {
    weights[i] = (halfTan[(i + n - 1) % n] + halfTan[i]) / r[i];
    sum += weights[i];
  }
  for (size_t i = 0; i < n; ++i)
  {
    weights[i] = sum != 0 ? weights[i] / sum : 1.0 / n;
  }
}

PatchNodes::PatchNodes(const SceneMesh& mesh, const SceneGeometry& g, const std::vector<std::vector<Vec3>>& outlines,
  const std::vector<Vec3>& centres)
{
  WeightBegin.assign(g.normal.size(), 0);
  for (size_t p = 0; p < g.patchElements.size(); ++p)
  {
    AddNodes(static_cast<int>(p), mesh, g, outlines[p], centres[p]);
  }
}

void PatchNodes::AddNodes(int patch, const SceneMesh& mesh, const SceneGeometry& g, const std::vector<Vec3>& outline,
  const Vec3& centre)
{
  const std::vector<int>& elements = g.patchElements[patch];
  std::vector<Vec3> loop;
  if (elements.size() == 1)
  {
    for (int v = 0; v < mesh.PolygonSize(elements[0]); ++v)
    {
      loop.push_back(mesh.points[mesh.Polygon(elements[0])[v]]);
    }
  }
  else
  {
    loop = ChainLoop(outline);
  }
  const Vec3 normal = elements.empty() ? Vec3() : g.normal[elements[0]];
  // Mean value coordinates need the point inside a simple loop seen from the front; where
  // that is not sure (no loop, or the loop winds backwards), one node at the centre.
  double winding = 0;
  for (size_t i = 0; i < loop.size(); ++i)
  {
    winding += Dot(Cross(loop[i] - centre, loop[(i + 1) % loop.size()] - centre), normal);
  }
  if (loop.size() < 3 || winding <= 0)
  {
    loop.assign(1, centre);
  }
  const int first = static_cast<int>(Position.size());
  Position.insert(Position.end(), loop.begin(), loop.end());
  NodeBegin.push_back(static_cast<int>(Position.size()));
  Area.resize(Position.size(), 0.0);
  for (int e : elements)
  {
    WeightBegin[e] = WeightData.size();
    WeightData.resize(WeightData.size() + loop.size());
    double* w = WeightData.data() + WeightBegin[e];
    if (loop.size() == 1)
    {
      w[0] = 1;
    }
    else
    {
      MeanValueCoordinates(g.centroid[e], normal, loop, w);
    }
    for (size_t j = 0; j < loop.size(); ++j)
    {
      Area[first + j] += w[j] * g.area[e];
    }
  }
}

} // namespace radiosity
