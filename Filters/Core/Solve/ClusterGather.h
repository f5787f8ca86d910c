// One gathering pass over the clustered method's links: what every element receives from a
// given radiosity of all elements, for any number of solutions at once.
#ifndef RadiosityCore_ClusterGather_h
#define RadiosityCore_ClusterGather_h

#include "Solve/ClusterLinks.h"
#include "Base/WorkerPool.h"

#include <vector>

namespace radiosity
{

/// Per node and solution the source sums are the sum of x A n (3 values) and, for the
/// series, of x A and x A n n^T (7); the receiver sums the irradiance vector (3) for links
/// whose receiver faces them, and 1, w, w w^T weighted by the arriving flux (10) for the
/// others. The vector parts are kept apart: most links read and write only them.
template <typename Value>
class ClusterGather
{
public:
  static constexpr int kVector = 3, kSourceSeries = 7, kReceiverSeries = 10;

  ClusterGather(const SceneGeometry& g, const ElementTree& tree, const ClusterLinkSet& links, const WorkerPool& pool)
    : G(g)
    , Tree(tree)
    , Links(links)
    , Pool(pool)
    , FarRuns(RunStarts(links.Receiver))
    , NearRuns(RunStarts(links.LeafReceiver))
  {
    if (!tree.Nodes().empty())
    {
      Divide(0, std::max(1, tree.Nodes()[0].Count / (8 * pool.Threads())));
    }
  }

  /// Gathers from sending[e * L + m] along this rank's links; the caller sums the node and
  /// near sums over the ranks (Sums) before Collect where several share the links.
  void Scatter(const std::vector<Value>& sending, int L)
  {
    PullUp(sending, L);
    const size_t nodes = Tree.Nodes().size() * static_cast<size_t>(L);
    ReceivedVector.assign(nodes * kVector, Value());
    ReceivedSeries.assign(nodes * kReceiverSeries, Value());
    Near.assign(sending.size(), Value());
    Pool.For(static_cast<int>(FarRuns.size()) - 1, 64, [&](int begin, int end) {
      for (int i = FarRuns[begin]; i < FarRuns[end]; ++i)
      {
        FarLink(i, L);
      }
    });
    Pool.For(static_cast<int>(NearRuns.size()) - 1, 256, [&](int begin, int end) {
      for (int i = NearRuns[begin]; i < NearRuns[end]; ++i)
      {
        const size_t to = static_cast<size_t>(Links.LeafReceiver[i]) * L, from = static_cast<size_t>(Links.LeafSource[i]) * L;
        for (int m = 0; m < L; ++m)
        {
          Near[to + m] += sending[from + m] * Links.LeafFactor[i];
        }
      }
    });
  }

  /// The sums Scatter left, for a sum over the ranks.
  std::vector<std::vector<Value>*> Sums() { return { &ReceivedVector, &ReceivedSeries, &Near }; }

  /// Pushes the node sums down and evaluates each element's irradiance.
  void Collect(int L, std::vector<Value>& irradiance)
  {
    PushDown(ReceivedVector, kVector * L);
    PushDown(ReceivedSeries, kReceiverSeries * L);
    irradiance.assign(Near.size(), Value());
    Pool.For(static_cast<int>(G.normal.size()), 512, [&](int begin, int end) {
      for (int e = begin; e < end; ++e)
      {
        const int leaf = Tree.LeafOf(e);
        for (int m = 0; m < L && leaf >= 0; ++m)
        {
          const size_t at = static_cast<size_t>(leaf) * L + m;
          irradiance[static_cast<size_t>(e) * L + m] = AtElement(ReceivedVector.data() + at * kVector,
            ReceivedSeries.data() + at * kReceiverSeries, G.normal[e]) + Near[static_cast<size_t>(e) * L + m];
        }
      }
    });
  }

private:
  static std::vector<int> RunStarts(const std::vector<int>& receiver)
  {
    std::vector<int> starts;
    for (int i = 0; i < static_cast<int>(receiver.size()); ++i)
    {
      if (i == 0 || receiver[i] != receiver[i - 1])
      {
        starts.push_back(i);
      }
    }
    starts.push_back(static_cast<int>(receiver.size()));
    return starts;
  }

  /// The nodes near the root (one thread) and the subtrees under them (in parallel).
  void Divide(int n, int limit)
  {
    if (Tree.IsLeaf(n) || Tree.Nodes()[n].Count <= limit)
    {
      Subtrees.push_back(n);
      return;
    }
    Top.push_back(n);
    Divide(Tree.Nodes()[n].Left, limit);
    Divide(Tree.Nodes()[n].Right, limit);
  }

  void FarLink(int i, int L)
  {
    const float* d = Links.Direction.data() + 3 * i;
    const Vec3 u{ d[0], d[1], d[2] };
    const bool mixedSource = (Links.Mixed[i] & 1) != 0, mixedReceiver = (Links.Mixed[i] & 2) != 0;
    const double w[6] = { u.x * u.x, u.x * u.y, u.x * u.z, u.y * u.y, u.y * u.z, u.z * u.z };
    const double c = Links.Coupling[i];
    const size_t source = static_cast<size_t>(Links.Source[i]) * L, receiver = static_cast<size_t>(Links.Receiver[i]) * L;
    for (int m = 0; m < L; ++m)
    {
      const Value* s = SentVector.data() + (source + m) * kVector;
      const Value along = s[0] * u.x + s[1] * u.y + s[2] * u.z;
      Value flux = along * c;
      if (mixedSource)
      {
        const Value* q = SentSeries.data() + (source + m) * kSourceSeries; // x A, then x A n n^T
        const Value quadratic = q[1] * w[0] + q[4] * w[3] + q[6] * w[5] + (q[2] * w[1] + q[3] * w[2] + q[5] * w[4]) * 2.0;
        flux = (q[0] * 0.25 + along * 0.5 + (quadratic * 3.0 - q[0]) * (5.0 / 32.0)) * c;
      }
      if (!mixedReceiver)
      {
        Value* r = ReceivedVector.data() + (receiver + m) * kVector;
        r[0] += flux * -u.x; // towards the source: n . (-u) > 0 at each receiving element
        r[1] += flux * -u.y;
        r[2] += flux * -u.z;
        continue;
      }
      Value* r = ReceivedSeries.data() + (receiver + m) * kReceiverSeries;
      r[0] += flux;
      r[1] += flux * -u.x;
      r[2] += flux * -u.y;
      r[3] += flux * -u.z;
      for (int k = 0; k < 6; ++k)
      {
        r[4 + k] += flux * w[k];
      }
    }
  }

  /// What an element of normal n receives from its node's sums.
  static Value AtElement(const Value* v, const Value* r, const Vec3& n)
  {
    const Value along = r[1] * n.x + r[2] * n.y + r[3] * n.z;
    const Value quadratic = r[4] * (n.x * n.x) + r[7] * (n.y * n.y) + r[9] * (n.z * n.z) +
      (r[5] * (n.x * n.y) + r[6] * (n.x * n.z) + r[8] * (n.y * n.z)) * 2.0;
    return v[0] * n.x + v[1] * n.y + v[2] * n.z + r[0] * 0.25 + along * 0.5 + (quadratic * 3.0 - r[0]) * (5.0 / 32.0);
  }

  void PullUp(const std::vector<Value>& sending, int L)
  {
    const std::vector<ElementTree::Node>& nodes = Tree.Nodes();
    const size_t vector = static_cast<size_t>(kVector) * L, series = static_cast<size_t>(kSourceSeries) * L;
    SentVector.assign(nodes.size() * vector, Value());
    SentSeries.assign(nodes.size() * series, Value());
    const auto node = [&](int n) {
      Value* toVector = SentVector.data() + n * vector;
      Value* toSeries = SentSeries.data() + n * series;
      if (Tree.IsLeaf(n))
      {
        const int e = Tree.ElementOf(n);
        const Vec3& v = G.normal[e];
        const double a = G.area[e];
        const double moments[kSourceSeries] = { a, a * v.x * v.x, a * v.x * v.y, a * v.x * v.z, a * v.y * v.y,
          a * v.y * v.z, a * v.z * v.z };
        for (int m = 0; m < L; ++m)
        {
          const Value x = sending[static_cast<size_t>(e) * L + m];
          for (int k = 0; k < kVector; ++k)
          {
            toVector[m * kVector + k] = x * (a * v[k]);
          }
          for (int k = 0; k < kSourceSeries; ++k)
          {
            toSeries[m * kSourceSeries + k] = x * moments[k];
          }
        }
        return;
      }
      Add(SentVector.data() + nodes[n].Left * vector, SentVector.data() + nodes[n].Right * vector, toVector, vector);
      Add(SentSeries.data() + nodes[n].Left * series, SentSeries.data() + nodes[n].Right * series, toSeries, series);
    };
    Pool.For(static_cast<int>(Subtrees.size()), 1, [&](int begin, int end) {
      for (int s = begin; s < end; ++s)
      {
        for (int n = Tree.SubtreeEnd(Subtrees[s]) - 1; n >= Subtrees[s]; --n)
        {
          node(n);
        }
      }
    });
    for (auto it = Top.rbegin(); it != Top.rend(); ++it)
    {
      node(*it);
    }
  }

  static void Add(const Value* a, const Value* b, Value* to, size_t count)
  {
    for (size_t j = 0; j < count; ++j)
    {
      to[j] = a[j] + b[j];
    }
  }

  /// Adds each node's sums (`width` values) to its children's, root first.
  void PushDown(std::vector<Value>& sums, size_t width)
  {
    const std::vector<ElementTree::Node>& nodes = Tree.Nodes();
    const auto node = [&](int n) {
      if (Tree.IsLeaf(n))
      {
        return;
      }
      const Value* from = sums.data() + n * width;
      Value* left = sums.data() + nodes[n].Left * width;
      Value* right = sums.data() + nodes[n].Right * width;
      for (size_t j = 0; j < width; ++j)
      {
        left[j] += from[j];
        right[j] += from[j];
      }
    };
    for (int n : Top)
    {
      node(n);
    }
    Pool.For(static_cast<int>(Subtrees.size()), 1, [&](int begin, int end) {
      for (int s = begin; s < end; ++s)
      {
        for (int n = Subtrees[s]; n < Tree.SubtreeEnd(Subtrees[s]); ++n)
        {
          node(n);
        }
      }
    });
  }

  const SceneGeometry& G;
  const ElementTree& Tree;
  const ClusterLinkSet& Links;
  const WorkerPool& Pool;
  const std::vector<int> FarRuns, NearRuns;
  std::vector<int> Top, Subtrees;
  std::vector<Value> SentVector, SentSeries, ReceivedVector, ReceivedSeries, Near;
};

} // namespace radiosity

#endif
