// One gathering pass over the clustered method's links: what every element receives from a
// given radiosity of all elements, for any number of solutions at once.
#ifndef RadiosityCore_ClusterGather_h
#define RadiosityCore_ClusterGather_h

#include "Solve/ClusterLinks.h"
#include "Base/ProcessGroup.h"
#include "Base/WorkerPool.h"

#include <vector>

// GCC on x86-64 Linux makes the copies and picks one at load time (an ifunc); elsewhere
// (other processors, Clang, which refuses it on templates) there is one portable loop.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__linux__)
#define RADIOSITY_AVX2_CLONE __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define RADIOSITY_AVX2_CLONE
#endif

namespace radiosity
{

/// The values of every solution and color channel of one element or node side by side
/// ("lanes"): a link does the same arithmetic on each lane, which the compiler vectorizes.
/// Per node and lane the source sums are the sum of x A n (3 values) and, for the series, of
/// x A and x A n n^T (7), kept in float: a bounce reads them once per link, so their size
/// is its speed. The receiver sums (float too: they are cleared, pushed down and read on
/// every bounce) are the irradiance vector (3) for links whose receiver faces them, and 1,
/// w, w w^T weighted by the arriving flux (10) for the others.
template <typename Value>
class ClusterGather
{
public:
  static constexpr int kVector = 3, kSourceSeries = 7, kReceiverSeries = 10;
  static constexpr int kChannels = sizeof(Value) / sizeof(double);

  /// What the sums of one tree node take for `lanes` lanes (sent and received, the centre).
  static double BytesPerNode(double lanes)
  {
    return (2 * kVector + kSourceSeries + kReceiverSeries) * lanes * sizeof(float) + sizeof(Vec3);
  }

  ClusterGather(const SceneGeometry& g, const ElementTree& tree, const ClusterLinkSet& links, const WorkerPool& pool)
    : G(g)
    , Tree(tree)
    , Links(links)
    , Pool(pool)
    , NearReceivers(WithLinks(links.NearStart))
    , Centres(tree.Nodes().size())
  {
    for (size_t n = 0; n < Centres.size(); ++n)
    {
      Centres[n] = tree.Nodes()[n].Centre; // a bounce reads one per link: kept together
    }
    if (!tree.Nodes().empty())
    {
      Divide(0, std::max(1, tree.Nodes()[0].Count / (8 * pool.Threads())));
    }
  }

  /// Gathers from sending[e * L + m] along this rank's links; the caller sums the node and
  /// near sums over the ranks (Sums) before Collect where several share the links.
  void Scatter(const std::vector<Value>& sending, int L)
  {
    W = L * kChannels;
    const double* x = reinterpret_cast<const double*>(sending.data());
    PullUp(x);
    const size_t nodes = Tree.Nodes().size();
    ReceivedVector.assign(nodes * kVector * W, 0.0f);
    ReceivedSeries.assign(nodes * kReceiverSeries * W, 0.0f);
    Near.assign(G.Normal.size() * W, 0.0);
    Pool.For(static_cast<int>(Links.FarBlockStart.size()) - 1, 1, [&](int begin, int end) {
      std::vector<float> flux(W);
      for (int block = begin; block < end; ++block)
      {
        FarBlock(block, flux.data());
      }
    });
    Pool.For(static_cast<int>(NearReceivers.size()), 256, [&](int begin, int end) {
      for (int run = begin; run < end; ++run)
      {
        NearRun(NearReceivers[run], x);
      }
    });
  }

  /// Sums what Scatter left over the ranks (each gathered along its own share of the links).
  void SumOverRanks(Collective& group)
  {
    if (!group.Distributed())
    {
      return;
    }
    for (std::vector<float>* sums : { &ReceivedVector, &ReceivedSeries })
    {
      std::vector<double> values(sums->begin(), sums->end());
      group.Sum(values);
      std::copy(values.begin(), values.end(), sums->begin());
    }
    group.Sum(Near);
  }

  /// Pushes the node sums down and evaluates each element's irradiance.
  void Collect(int L, std::vector<Value>& irradiance)
  {
    W = L * kChannels;
    PushDown(ReceivedVector, static_cast<size_t>(kVector) * W);
    PushDown(ReceivedSeries, static_cast<size_t>(kReceiverSeries) * W);
    irradiance.assign(G.Normal.size() * L, Value());
    double* out = reinterpret_cast<double*>(irradiance.data());
    Pool.For(static_cast<int>(G.Normal.size()), 512, [&](int begin, int end) {
      for (int e = begin; e < end; ++e)
      {
        const int leaf = Tree.LeafOf(e);
        if (leaf >= 0)
        {
          AtElement(leaf, e, out + static_cast<size_t>(e) * W);
        }
      }
    });
  }

private:
  /// The receivers that have links.
  static std::vector<int> WithLinks(const std::vector<size_t>& start)
  {
    std::vector<int> receivers;
    for (size_t r = 0; r + 1 < start.size(); ++r)
    {
      if (start[r + 1] > start[r])
      {
        receivers.push_back(static_cast<int>(r));
      }
    }
    return receivers;
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

  /// One block's far links, summed into their receivers' rows (which stay in cache while
  /// the block runs). Float arithmetic, as the sums are float; a bounce spends most of its
  /// time here, so a copy for AVX2 and FMA is made beside the portable one and picked when
  /// the program loads (about a quarter faster a bounce on the FZK-Haus).
  RADIOSITY_AVX2_CLONE void FarBlock(int block, float* flux)
  {
    const int* receivers = Links.FarReceivers.data() + static_cast<size_t>(block) * ClusterLinkSet::kBlock;
    for (size_t i = Links.FarBlockStart[block]; i < Links.FarBlockStart[block + 1]; ++i)
    {
      Prefetch(i + kAhead);
      const int receiver = receivers[Links.Receiver[i]];
      float u[3];
      FarDirection(Centres[receiver], Centres[Links.Source[i]], u);
      Flux(i, u, flux);
      if ((Links.Mixed[i] & 2) == 0)
      {
        float* vector = ReceivedVector.data() + static_cast<size_t>(receiver) * kVector * W;
        for (int k = 0; k < kVector; ++k)
        {
          for (int j = 0; j < W; ++j)
          {
            vector[k * W + j] -= flux[j] * u[k]; // towards the source: n . (-u) > 0 at each receiving element
          }
        }
        continue;
      }
      float* series = ReceivedSeries.data() + static_cast<size_t>(receiver) * kReceiverSeries * W;
      const float w[kReceiverSeries] = { 1, -u[0], -u[1], -u[2], u[0] * u[0], u[0] * u[1], u[0] * u[2], u[1] * u[1],
        u[1] * u[2], u[2] * u[2] };
      for (int k = 0; k < kReceiverSeries; ++k)
      {
        for (int j = 0; j < W; ++j)
        {
          series[k * W + j] += flux[j] * w[k];
        }
      }
    }
  }

  /// The sources are scattered over memory: a bounce waits on their sums unless they are
  /// asked for a few links ahead.
  static constexpr int kAhead = 6;
  void Prefetch(size_t i) const
  {
    if (i >= Links.Source.size())
    {
      return;
    }
    const size_t source = static_cast<size_t>(Links.Source[i]);
    __builtin_prefetch(Centres.data() + source);
    const char* vector = reinterpret_cast<const char*>(SentVector.data() + source * kVector * W);
    for (size_t at = 0; at < kVector * W * sizeof(float); at += 64)
    {
      __builtin_prefetch(vector + at);
    }
    if ((Links.Mixed[i] & 1) != 0)
    {
      const char* series = reinterpret_cast<const char*>(SentSeries.data() + source * kSourceSeries * W);
      for (size_t at = 0; at < kSourceSeries * W * sizeof(float); at += 64)
      {
        __builtin_prefetch(series + at);
      }
    }
  }

  /// What link i carries towards its receiver per lane: Coupling x the source's emission
  /// along u (its area vector's projection, or the clamped cosine's series where mixed).
  void Flux(size_t i, const float* u, float* flux) const
  {
    const float c = Links.Coupling[i];
    const float* s = SentVector.data() + static_cast<size_t>(Links.Source[i]) * kVector * W;
    for (int j = 0; j < W; ++j)
    {
      flux[j] = (s[j] * u[0] + s[W + j] * u[1] + s[2 * W + j] * u[2]) * c;
    }
    if ((Links.Mixed[i] & 1) == 0)
    {
      return;
    }
    const float* q = SentSeries.data() + static_cast<size_t>(Links.Source[i]) * kSourceSeries * W; // x A, then x A n n^T
    const float w[6] = { u[0] * u[0], 2 * u[0] * u[1], 2 * u[0] * u[2], u[1] * u[1], 2 * u[1] * u[2], u[2] * u[2] };
    for (int j = 0; j < W; ++j)
    {
      float quadratic = 0;
      for (int k = 0; k < 6; ++k)
      {
        quadratic += q[(1 + k) * W + j] * w[k];
      }
      const float area = q[j];
      flux[j] = area * 0.25f * c + flux[j] * 0.5f + (quadratic * 3.0f - area) * (5.0f / 32.0f) * c;
    }
  }

  /// One receiving element's near links.
  void NearRun(int receiver, const double* sending)
  {
    double* to = Near.data() + static_cast<size_t>(receiver) * W;
    for (size_t i = Links.NearStart[receiver]; i < Links.NearStart[receiver + 1]; ++i)
    {
      const double* from = sending + static_cast<size_t>(Links.LeafSource[i]) * W;
      const double f = Links.LeafFactor[i];
      for (int j = 0; j < W; ++j)
      {
        to[j] += from[j] * f;
      }
    }
  }

  /// What element e of normal n receives from its leaf's sums, per lane.
  void AtElement(int leaf, int e, double* out) const
  {
    const Vec3& n = G.Normal[e];
    const float* v = ReceivedVector.data() + static_cast<size_t>(leaf) * kVector * W;
    const float* r = ReceivedSeries.data() + static_cast<size_t>(leaf) * kReceiverSeries * W;
    const double* near = Near.data() + static_cast<size_t>(e) * W;
    const double w[6] = { n.x * n.x, 2 * n.x * n.y, 2 * n.x * n.z, n.y * n.y, 2 * n.y * n.z, n.z * n.z };
    for (int j = 0; j < W; ++j)
    {
      const double along = r[W + j] * n.x + r[2 * W + j] * n.y + r[3 * W + j] * n.z;
      double quadratic = 0;
      for (int k = 0; k < 6; ++k)
      {
        quadratic += r[(4 + k) * W + j] * w[k];
      }
      out[j] = v[j] * n.x + v[W + j] * n.y + v[2 * W + j] * n.z + r[j] * 0.25 + along * 0.5 +
        (quadratic * 3.0 - r[j]) * (5.0 / 32.0) + near[j];
    }
  }

  void PullUpLeaf(int n, const double* sending)
  {
    const int e = Tree.ElementOf(n);
    const Vec3& v = G.Normal[e];
    const double a = G.Area[e];
    const double vector[kVector] = { a * v.x, a * v.y, a * v.z };
    const double moments[kSourceSeries] = { a, a * v.x * v.x, a * v.x * v.y, a * v.x * v.z, a * v.y * v.y, a * v.y * v.z,
      a * v.z * v.z };
    const double* x = sending + static_cast<size_t>(e) * W;
    float* toVector = SentVector.data() + static_cast<size_t>(n) * kVector * W;
    float* toSeries = SentSeries.data() + static_cast<size_t>(n) * kSourceSeries * W;
    for (int k = 0; k < kVector; ++k)
    {
      for (int j = 0; j < W; ++j)
      {
        toVector[k * W + j] = static_cast<float>(x[j] * vector[k]);
      }
    }
    for (int k = 0; k < kSourceSeries; ++k)
    {
      for (int j = 0; j < W; ++j)
      {
        toSeries[k * W + j] = static_cast<float>(x[j] * moments[k]);
      }
    }
  }

  void PullUp(const double* sending)
  {
    const std::vector<ElementTree::Node>& nodes = Tree.Nodes();
    const size_t vector = static_cast<size_t>(kVector) * W, series = static_cast<size_t>(kSourceSeries) * W;
    SentVector.assign(nodes.size() * vector, 0.0f);
    SentSeries.assign(nodes.size() * series, 0.0f);
    const auto node = [&](int n) {
      if (Tree.IsLeaf(n))
      {
        PullUpLeaf(n, sending);
        return;
      }
      Add(SentVector.data() + nodes[n].Left * vector, SentVector.data() + nodes[n].Right * vector,
        SentVector.data() + n * vector, vector);
      Add(SentSeries.data() + nodes[n].Left * series, SentSeries.data() + nodes[n].Right * series,
        SentSeries.data() + n * series, series);
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

  static void Add(const float* a, const float* b, float* to, size_t count)
  {
    for (size_t j = 0; j < count; ++j)
    {
      to[j] = a[j] + b[j];
    }
  }

  /// Adds each node's sums (`width` values) to its children's, root first.
  void PushDown(std::vector<float>& sums, size_t width)
  {
    const std::vector<ElementTree::Node>& nodes = Tree.Nodes();
    const auto node = [&](int n) {
      if (Tree.IsLeaf(n))
      {
        return;
      }
      const float* from = sums.data() + n * width;
      float* left = sums.data() + nodes[n].Left * width;
      float* right = sums.data() + nodes[n].Right * width;
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
  const std::vector<int> NearReceivers;
  std::vector<Vec3> Centres; ///< each node's, as the far links' directions come from them
  std::vector<int> Top, Subtrees;
  int W = 1; ///< lanes: solutions x channels
  std::vector<float> SentVector, SentSeries;
  std::vector<float> ReceivedVector, ReceivedSeries;
  std::vector<double> Near;
};

} // namespace radiosity

#endif
