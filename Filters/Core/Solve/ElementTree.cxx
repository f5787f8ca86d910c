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
  int half = count / 2;
  const NormalCone cone = All[index].Cone; // Summarise's: its axis is the unit mean normal
  if (cone.Spread <= kBackToBack || !SplitByFacing(first, count, cone.Axis, half))
  {
    const std::vector<long long> key = SplitKeys(first, count);
    SplitAtMedian(Order, first, count, key);
  }
  const int left = Build(first, half);
  const int right = Build(first + half, count - half);
  All[index].Left = left;
  All[index].Right = right;
  return index;
}

bool ElementTree::SplitByFacing(int first, int count, const Vec3& mean, int& left)
{
  // Two seeds in normal space, as SplitKeys takes two in space: the normal least like the
  // (unit, so scale-free) mean, then the one least like it; each element joins the seed it
  // faces more.
  const Vec3 a = G.Normal[LeastAlike(first, count, mean)];
  const Vec3 b = G.Normal[LeastAlike(first, count, a)];
  const auto nearerA = [&](int e) { return std::llround((Dot(G.Normal[e], a) - Dot(G.Normal[e], b)) * 1e9) > 0; };
  std::vector<int> sides(Order.begin() + first, Order.begin() + first + count);
  const auto middle = std::stable_partition(sides.begin(), sides.end(), nearerA);
  if (middle == sides.begin() || middle == sides.end() || !Coherent(sides.begin(), middle) ||
    !Coherent(middle, sides.end()))
  {
    return false;
  }
  std::copy(sides.begin(), sides.end(), Order.begin() + first);
  left = static_cast<int>(middle - sides.begin());
  return true;
}

Vec3 ElementTree::MeanNormal(std::vector<int>::const_iterator begin, std::vector<int>::const_iterator end) const
{
  Vec3 sum;
  for (auto e = begin; e != end; ++e)
  {
    sum += G.Normal[*e] * G.Area[*e];
  }
  return sum;
}

int ElementTree::LeastAlike(int first, int count, const Vec3& direction) const
{
  int best = Order[first];
  long long lowest = 0;
  for (int i = first; i < first + count; ++i)
  {
    const long long d = std::llround(Dot(G.Normal[Order[i]], direction) * 1e9);
    if (i == first || d < lowest || (d == lowest && Order[i] < best))
    {
      lowest = d;
      best = Order[i];
    }
  }
  return best;
}

bool ElementTree::Coherent(std::vector<int>::const_iterator begin, std::vector<int>::const_iterator end) const
{
  const Vec3 sum = MeanNormal(begin, end);
  const Vec3 axis = Normalized(sum);
  return Norm(sum) > 0 && std::all_of(begin, end, [&](int e) { return Dot(axis, G.Normal[e]) > kFacing; });
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
