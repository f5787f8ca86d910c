#include "Solve/ElementTree.h"
#include "Solve/MedianSplit.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace radiosity
{

ElementTree::ElementTree(const SceneMesh& mesh, const SceneGeometry& g)
  : G(g)
  , Leaf(g.Normal.size(), -1)
  , Reach(g.Normal.size(), 0.0)
{
  for (int e = 0; e < static_cast<int>(g.Normal.size()); ++e)
  {
    Reach[e] = radiosity::ElementRadius(mesh, g, e);
    if (!g.Enclosed[e] && g.Area[e] > 0)
    {
      Order.push_back(e);
    }
  }
  // Scale measured without axes, so that the quanta turn with the scene.
  Vec3 mean;
  for (int e : Order)
  {
    mean += g.Centroid[e] * (1.0 / Order.size());
  }
  double size = 0;
  for (int e : Order)
  {
    size = std::max(size, Norm(g.Centroid[e] - mean));
  }
  Quantum = 1e-7 * std::max(size, 1e-300);
  Tol = 1e-6 * std::max(size, 1e-300);
  All.reserve(2 * Order.size());
  if (!Order.empty())
  {
    Build(0, static_cast<int>(Order.size()));
  }
  for (int n = 0; n < static_cast<int>(All.size()); ++n)
  {
    if (All[n].Left < 0)
    {
      Leaf[Order[All[n].First]] = n;
    }
  }
}

int ElementTree::Build(int first, int count)
{
  const int index = static_cast<int>(All.size());
  All.emplace_back();
  All[index].First = first;
  All[index].Count = count;
  Summarise(All[index]);
  if (count == 1)
  {
    return index;
  }
  const int half = count / 2;
  const std::vector<long long> key = SplitKeys(first, count);
  SplitAtMedian(Order, first, count, key);
  const int left = Build(first, half);
  const int right = Build(first + half, count - half);
  All[index].Left = left;
  All[index].Right = right;
  return index;
}

std::vector<long long> ElementTree::SplitKeys(int first, int count) const
{
  Vec3 mean;
  for (int i = first; i < first + count; ++i)
  {
    mean += G.Centroid[Order[i]] * (1.0 / count);
  }
  const auto farthest = [&](const Vec3& from) {
    int best = Order[first];
    long long far = -1;
    for (int i = first; i < first + count; ++i)
    {
      const long long d = std::llround(Norm(G.Centroid[Order[i]] - from) / Quantum);
      if (d > far || (d == far && Order[i] < best))
      {
        far = d;
        best = Order[i];
      }
    }
    return best;
  };
  const Vec3 a = G.Centroid[farthest(mean)];
  const Vec3 axis = Normalized(G.Centroid[farthest(a)] - a);
  std::vector<long long> key(count);
  for (int i = 0; i < count; ++i)
  {
    key[i] = std::llround(Dot(G.Centroid[Order[first + i]] - a, axis) / Quantum);
  }
  return key;
}

void ElementTree::Summarise(Node& node) const
{
  Vec3 centre;
  for (int i = node.First; i < node.First + node.Count; ++i)
  {
    const int e = Order[i];
    centre += G.Centroid[e] * G.Area[e];
    node.Area += G.Area[e];
    node.AreaVector += G.Normal[e] * G.Area[e];
    const Vec3& n = G.Normal[e];
    const double m[6] = { n.x * n.x, n.x * n.y, n.x * n.z, n.y * n.y, n.y * n.z, n.z * n.z };
    for (int k = 0; k < 6; ++k)
    {
      node.NormalMoment[k] += G.Area[e] * m[k];
    }
  }
  node.Centre = centre * (1.0 / node.Area);
  const Vec3 axis = Normalized(node.AreaVector);
  double spread = 0, lowest = 1e300, highest = -1e300;
  for (int i = node.First; i < node.First + node.Count; ++i)
  {
    const int e = Order[i];
    node.Radius = std::max(node.Radius, Norm(G.Centroid[e] - node.Centre) + Reach[e]);
    spread = std::max(spread, std::acos(std::max(-1.0, std::min(1.0, Dot(axis, G.Normal[e])))));
    lowest = std::min(lowest, Dot(axis, G.Centroid[e]));
    highest = std::max(highest, Dot(axis, G.Centroid[e]));
  }
  node.Cone = Norm(axis) == 0 || spread >= Pi ? NormalCone(axis, Pi) : NormalCone(axis, spread);
  node.Flat = Norm(axis) > 0 && spread < 1e-6 && highest - lowest <= Tol;
  node.PlaneOffset = 0.5 * (lowest + highest);
}

} // namespace radiosity
