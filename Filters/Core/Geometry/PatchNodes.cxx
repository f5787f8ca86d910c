#include "Geometry/PatchNodes.h"

#include <cmath>
#include <utility>

namespace radiosity
{


size_t FanCoordinates(const Vec3& x, const Vec3& normal, const std::vector<Vec3>& loop, const Vec3& centre,
  double* weights)
{
  const size_t n = loop.size();
  size_t best = 0;
  double bestMin = -1e300, a = 0, b = 0, c = 0;
  for (size_t i = 0; i < n; ++i)
  {
    // Barycentric coordinates in the fan triangle (centre, v_i, v_i+1), from signed areas.
    const Vec3& p = loop[i];
    const Vec3& q = loop[(i + 1) % n];
    const double total = Dot(Cross(p - centre, q - centre), normal);
    if (total <= 0)
    {
      continue;
    }
    const double wc = Dot(Cross(p - x, q - x), normal) / total;
    const double wp = Dot(Cross(q - x, centre - x), normal) / total;
    const double wq = 1 - wc - wp;
    const double least = std::min(wc, std::min(wp, wq));
    if (least > bestMin)
    {
      bestMin = least;
      best = i;
      a = wc;
      b = wp;
      c = wq;
    }
  }
  for (size_t j = 0; j <= n; ++j)
  {
    weights[j] = 0;
  }
  weights[best] = b;
  weights[(best + 1) % n] = c;
  weights[n] = a;
  return best;
}

namespace
{
/// The fan triangles an element belongs to, with its share of each: the one holding its
/// centroid, or both sides of a fan edge the centroid lies on (where the choice between
/// them would follow round-off, and a rotated scene would be split differently).
std::vector<std::pair<size_t, double>> FanShares(size_t fan, const double* w, size_t corners)
{
  const double tiny = 1e-9;
  const bool onFirst = std::fabs(w[(fan + 1) % corners]) < tiny;  // on the edge to corner fan
  const bool onSecond = std::fabs(w[fan]) < tiny;                  // on the edge to corner fan + 1
  if (onFirst && onSecond)
  {
    std::vector<std::pair<size_t, double>> all;
    for (size_t i = 0; i < corners; ++i)
    {
      all.push_back({ i, 1.0 / corners });
    }
    return all;
  }
  if (onFirst)
  {
    return { { fan, 0.5 }, { (fan + corners - 1) % corners, 0.5 } };
  }
  if (onSecond)
  {
    return { { fan, 0.5 }, { (fan + 1) % corners, 0.5 } };
  }
  return { { fan, 1.0 } };
}
} // namespace

PatchNodes::PatchNodes(const SceneGeometry& g, const std::vector<std::vector<Vec3>>& loops, const std::vector<Vec3>& centres)
{
  WeightBegin.assign(g.Normal.size(), 0);
  for (size_t p = 0; p < g.PatchElements.size(); ++p)
  {
    AddNodes(static_cast<int>(p), g, loops[p], centres[p]);
  }
}

void PatchNodes::AddNodes(int patch, const SceneGeometry& g, std::vector<Vec3> loop, const Vec3& centre)
{
  const std::vector<int>& elements = g.PatchElements[patch];
  const Vec3 normal = elements.empty() ? Vec3() : g.Normal[elements[0]];
  // Mean value coordinates need the point inside a simple loop seen from the front; where
  // that is not sure (no loop, or the loop winds backwards), one node at the centre.
  double winding = 0;
  for (size_t i = 0; i < loop.size(); ++i)
  {
    winding += Dot(Cross(loop[i] - centre, loop[(i + 1) % loop.size()] - centre), normal);
  }
  if (loop.size() < 3 || winding <= 0)
  {
    loop.clear();
  }
  loop.push_back(centre); // the last node: with it, concave variation is not cut off
  const int first = static_cast<int>(Position.size());
  Position.insert(Position.end(), loop.begin(), loop.end());
  NodeBegin.push_back(static_cast<int>(Position.size()));
  Area.resize(Position.size(), 0.0);
  const std::vector<Vec3> corners(loop.begin(), loop.end() - 1);
  for (size_t i = 0; i < corners.size(); ++i)
  {
    const Vec3& a = corners[i];
    const Vec3& b = corners[(i + 1) % corners.size()];
    FanCentroids.push_back((centre + a + b) * (1.0 / 3.0));
    FanAreas.push_back(0.5 * Dot(Cross(a - centre, b - centre), normal));
  }
  // Fan triangles count only their open part (elements not sheltered), like the nodes.
  const size_t firstFan = FanAreas.size() - corners.size();
  std::vector<double> fanTotal(corners.size(), 0.0), fanOpen(corners.size(), 0.0);
  for (int e : elements)
  {
    WeightBegin[e] = WeightData.size();
    WeightData.resize(WeightData.size() + loop.size());
    double* w = WeightData.data() + WeightBegin[e];
    if (corners.empty())
    {
      w[0] = g.Sheltered[e] ? 0 : 1;
    }
    else
    {
      const size_t fan = FanCoordinates(g.Centroid[e], normal, corners, centre, w);
      for (const auto& [shared, part] : FanShares(fan, w, corners.size()))
      {
        fanTotal[shared] += part * g.Area[e];
        fanOpen[shared] += g.Sheltered[e] ? 0.0 : part * g.Area[e];
      }
      if (g.Sheltered[e])
      {
        std::fill(w, w + loop.size(), 0.0); // what reaches the patch as a whole lands on its open part
      }
    }
    for (size_t j = 0; j < loop.size(); ++j)
    {
      Area[first + j] += w[j] * g.Area[e];
    }
  }
  for (size_t i = 0; i < corners.size(); ++i)
  {
    FanAreas[firstFan + i] *= fanTotal[i] > 0 ? fanOpen[i] / fanTotal[i] : 1.0;
  }
}

} // namespace radiosity
