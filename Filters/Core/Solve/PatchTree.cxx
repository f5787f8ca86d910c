#include "Solve/PatchTree.h"
#include "Solve/MedianSplit.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace radiosity
{

PatchTree::PatchTree(const SceneGeometry& g, const ShooterFormFactors& factors, int leafPatches, int tasks)
  : G(g)
  , Factors(factors)
  , Order(g.PatchElements.size())
{
  std::iota(Order.begin(), Order.end(), 0);
  // The quantum follows the scene's size measured without axes (a box's diagonal would
  // change under a rotation).
  Vec3 mean;
  for (int p : Order)
  {
    mean += factors.Centre(p) * (1.0 / Order.size());
  }
  double size = 0;
  for (int p : Order)
  {
    size = std::max(size, Norm(factors.Centre(p) - mean));
  }
  Quantum = 1e-7 * std::max(size, 1e-300);
  if (!Order.empty())
  {
    Build(0, static_cast<int>(Order.size()), std::max(1, leafPatches));
  }
  // Element ranges follow the patch order: a prefix sum over it.
  std::vector<int> start(Order.size() + 1, 0);
  for (size_t i = 0; i < Order.size(); ++i)
  {
    for (int e : g.PatchElements[Order[i]])
    {
      if (!g.Sheltered[e])
      {
        Open.push_back(e);
      }
    }
    start[i + 1] = static_cast<int>(Open.size());
  }
  for (Node& node : All)
  {
    node.ElementFirst = start[node.First];
    node.ElementCount = start[node.First + node.Count] - node.ElementFirst;
  }
  FindFrontier(tasks);
}

int PatchTree::Build(int first, int count, int leafPatches)
{
  const int index = static_cast<int>(All.size());
  All.emplace_back();
  All[index].First = first;
  All[index].Count = count;
  Summarise(All[index]);
  if (count <= leafPatches)
  {
    return index;
  }
  const int half = count / 2;
  const std::vector<long long> key = SplitKeys(first, count);
  SplitAtMedian(Order, first, count, key);
  const int left = Build(first, half, leafPatches);
  const int right = Build(first + half, count - half, leafPatches);
  All[index].Left = left;
  All[index].Right = right;
  return index;
}

std::vector<long long> PatchTree::SplitKeys(int first, int count) const
{
  Vec3 mean;
  for (int i = first; i < first + count; ++i)
  {
    mean += Factors.Centre(Order[i]) * (1.0 / count);
  }
  const auto farthest = [&](const Vec3& from) {
    int best = Order[first];
    long long far = -1;
    for (int i = first; i < first + count; ++i)
    {
      const long long d = std::llround(Norm(Factors.Centre(Order[i]) - from) / Quantum);
      if (d > far || (d == far && Order[i] < best))
      {
        far = d;
        best = Order[i];
      }
    }
    return best;
  };
  const Vec3 a = Factors.Centre(farthest(mean));
  const Vec3 b = Factors.Centre(farthest(a));
  const Vec3 axis = Normalized(b - a);
  std::vector<long long> key(count);
  for (int i = 0; i < count; ++i)
  {
    key[i] = std::llround(Dot(Factors.Centre(Order[first + i]) - a, axis) / Quantum);
  }
  return key;
}

void PatchTree::Summarise(Node& node) const
{
  // The ball around the area-weighted mean of the patch centres, not a box's centre: the
  // same ball however the scene is turned.
  Vec3 centre, axis;
  double area = 0;
  for (int i = node.First; i < node.First + node.Count; ++i)
  {
    const int p = Order[i];
    centre += Factors.Centre(p) * G.PatchArea[p];
    area += G.PatchArea[p];
    axis += Factors.Cone(p).Axis * G.PatchArea[p];
  }
  node.Centre = area > 0 ? centre * (1.0 / area) : Factors.Centre(Order[node.First]);
  axis = Normalized(axis);
  double spread = 0;
  for (int i = node.First; i < node.First + node.Count; ++i)
  {
    const int p = Order[i];
    node.Radius = std::max(node.Radius, Norm(Factors.Centre(p) - node.Centre) + Factors.Radius(p));
    const double between = std::acos(std::max(-1.0, std::min(1.0, Dot(axis, Factors.Cone(p).Axis))));
    spread = std::max(spread, between + Factors.Cone(p).Spread);
  }
  node.Cone = Norm(axis) == 0 || spread >= Pi ? NormalCone(axis, Pi) : NormalCone(axis, spread);
}

void PatchTree::FindFrontier(int tasks)
{
  if (All.empty())
  {
    return;
  }
  Tasks = { 0 };
  bool split = true;
  while (split && static_cast<int>(Tasks.size()) < tasks)
  {
    split = false;
    std::vector<int> next;
    for (int n : Tasks)
    {
      if (All[n].Left >= 0)
      {
        next.push_back(All[n].Left);
        next.push_back(All[n].Right);
        split = true;
      }
      else
      {
        next.push_back(n);
      }
    }
    Tasks.swap(next);
  }
}

} // namespace radiosity
