#include "Solve/HierarchicalRadiosity.h"
#include "Solve/PatchTree.h"
#include "Solve/ShootToElements.h"

#include <algorithm>
#include <atomic>
#include <functional>

namespace radiosity
{

namespace
{
/// One shooter's links: receiver patches taken whole, and receiver patches taken element by
/// element, grouped by patch so that one thread owns each patch's unshot sum.
struct ShooterLinks
{
  std::vector<int> Patches;
  std::vector<int> NodeFactorBegin; ///< where each patch link's node factors start
  std::vector<float> NodeFactors;   ///< F(node -> shooter) at each node of each linked patch
  std::vector<double> MeanFactors;  ///< their integral over the patch per unit of its open area
  /// Face clusters' nodes (ReceiverNodes) taken whole: F(element -> shooter) = normal .
  /// vector for each of their elements; grouped by patch with the element links.
  std::vector<int> Clusters;
  std::vector<float> ClusterVectors; ///< three per cluster link
  std::vector<int> ClusterEnd;       ///< end of each group in Clusters
  /// Patch-tree nodes taken whole (far and in full view): each of their patches receives
  /// F = n_q . v, a face cluster through its root node; three floats per link.
  std::vector<int> Volumes;
  std::vector<float> VolumeVectors;
  std::vector<int> Groups;   ///< receiver patch of each element group
  std::vector<int> GroupEnd; ///< end of each group in Elements
  std::vector<int> Elements;
  std::vector<float> ElementFactors;
  /// Sum of factor x receiver area: the power received per unit of shot radiosity.
  double ReceivingArea = 0;
  bool Built = false;

  double Bytes() const
  {
    return static_cast<double>(Patches.size() * 4 + NodeFactors.size() + Clusters.size() * 4 + Groups.size() * 3 +
             Elements.size() * 2 + Volumes.size() * 4) * 4;
  }
};

enum class LinkKind : char
{
  None,
  Patch,
  Cluster,
  Elements
};

/// Centres closer than this many times the sum of two patches' radii are linked element by
/// element: there the form factor varies too much across the receiver for one value.
constexpr double kNearRadii = 2.0;
/// Within this many of the sum of their radii a cluster pair's links are near: visibility
/// is sampled per node and per element, not once for the pair.
constexpr double kClusterNearRadii = 3.0;
/// A cluster's node is taken whole where the shooter is farther from it than this many of
/// the node's radii (one vector at its centre, no corners to interpolate between: the
/// value must hold across it); nearer, its children are.
constexpr double kNodeNearRadii = 4.0;
/// Rays per sample for one visibility shared by a far receiver's element links: they stand
/// for all of its elements' rays, so they are more.
constexpr int kSharedRays = 4;
/// A node of the patch tree farther from the shooter than this many of the sum of their
/// radii is passed over whole when none of kHiddenNodeRays rays from the shooter to its
/// elements that face it arrives (a room behind a wall); nearer, the shooter's own walls and corners
/// would hide too much of a node that is partly in view.
constexpr double kHiddenNodeRadii = 2.0;
constexpr int kHiddenNodeRays = 16;
/// A patch-tree node in full view and farther than this many of its radii is linked whole:
/// one factor vector at its centre stands for each patch's factor, to within about
/// (1 / 6)^2 = 3 % of each (the error of a point factor across a far receiver).
constexpr double kVolumeNearRadii = 6.0;

class LinkBuilder
{
public:
  /// `owned`: the receiver patches this process links to; `ranks`: the processes solving
  /// together, which share the element factors of every shooter's near patches.
  LinkBuilder(const SceneGeometry& g, ShooterFormFactors& factors, const PatchNodes& nodes,
    const ReceiverNodes& clusters, const PatchTree& tree, const WorkerPool& pool, int samples, double threshold,
    const std::vector<char>& owned, Collective& ranks)
    : G(g)
    , Factors(factors)
    , Nodes(nodes)
    , Tree(tree)
    , ClusterNodes(clusters)
    , Pool(pool)
    , Samples(samples)
    , Threshold(threshold)
    , Patches(static_cast<int>(g.PatchElements.size()))
    , Kind(Patches)
    , NodeFactor(nodes.Count())
    , SharedVisibility(Patches, -1.0)
    , NodeLinks(Patches)
    , NodeElements(Patches)
    , Owned(owned)
    , Ranks(ranks)
    , PatchCovered(Patches, 0.0)
  {
    for (int q = 0; q < Patches; ++q)
    {
      for (int j = Nodes.Begin(q); j < Nodes.End(q); ++j)
      {
        PatchCovered[q] += Nodes.CoveredArea(j);
      }
    }
  }

  /// `shotFraction`: the largest fraction of a solution's emitted power this shot carries.
  ShooterLinks Build(int shooter, double shotFraction, SolverStatistics& stats)
  {
    Classify(shooter, shotFraction, stats);
    ShooterLinks links;
    links.Built = true;
    AddVolumeLinks(links, stats);
    for (int q = 0; q < Patches; ++q)
    {
      if (Kind[q] == LinkKind::Patch)
      {
        AddPatchLink(q, links);
      }
      else if (Kind[q] == LinkKind::Cluster || Kind[q] == LinkKind::Elements)
      {
        links.Groups.push_back(q);
      }
    }
    LinkElements(shooter, links, stats);
    Conserve(shooter, links);
    stats.PatchLinks += static_cast<long long>(links.Patches.size());
    stats.ElementLinks += static_cast<long long>(links.Elements.size());
    stats.LinkBytes += links.Bytes();
    return links;
  }

  /// Delivers the current shot to the owned patches of volume link `link`.
  template <typename Channel>
  void DeliverVolume(ShootingState<Channel>& state, const ShooterLinks& links, int link,
    const std::vector<Vec3>& meanReflectance) const
  {
    const float* f = links.VolumeVectors.data() + 3 * link;
    const Vec3 v{ f[0], f[1], f[2] };
    const PatchTree::Node& node = Tree.Nodes()[links.Volumes[link]];
    for (int i = node.First; i < node.First + node.Count; ++i)
    {
      const int q = Tree.Patches()[i];
      if (!Owned[q] || G.PatchOpenArea[q] <= 0)
      {
        continue;
      }
      if (!Factors.Planar(q))
      {
        state.GatherCluster(ClusterNodes.Root[q], v); // only links facing all of it are made
        continue;
      }
      const double factor = Dot(Factors.Normal(q), v);
      if (factor > 0)
      {
        state.GatherPatchUniform(q, factor, factor * PatchCovered[q] / G.PatchOpenArea[q], meanReflectance[q]);
      }
    }
  }

private:
  void AddVolumeLinks(ShooterLinks& links, SolverStatistics& stats) const
  {
    for (const auto& task : TaskVolumes)
    {
      for (const auto& link : task)
      {
        links.Volumes.push_back(link.first);
        for (int k = 0; k < 3; ++k)
        {
          links.VolumeVectors.push_back(static_cast<float>(link.second[k]));
        }
        links.ReceivingArea += VolumeReceiving(link.first, link.second, true);
      }
    }
    // Every rank makes the same volume links, each for its own patches: count them once.
    stats.VolumeLinks += Ranks.Rank() == 0 ? static_cast<long long>(links.Volumes.size()) : 0;
  }

  /// The power node n receives per unit shot radiosity through factor vector v (its owned
  /// patches only, where `owned`); -1 where a face cluster in it is cut by the shooter's
  /// ball's planes, so that the node cannot be taken whole.
  double VolumeReceiving(int n, const Vec3& v, bool owned, int s = -1) const
  {
    const PatchTree::Node& node = Tree.Nodes()[n];
    double covered = 0;
    for (int i = node.First; i < node.First + node.Count; ++i)
    {
      const int q = Tree.Patches()[i];
      if ((owned && !Owned[q]) || G.PatchOpenArea[q] <= 0)
      {
        continue;
      }
      if (Factors.Planar(q))
      {
        covered += std::max(0.0, Dot(Factors.Normal(q), v)) * PatchCovered[q];
        continue;
      }
      if (s >= 0 && !FacesBall(Factors.Centre(q), Factors.Radius(q), Factors.Cone(q), Factors.Centre(s), Factors.Radius(s)))
      {
        return -1;
      }
      covered += Dot(ClusterNodes.OpenArea[ClusterNodes.Root[q]], v);
    }
    return covered;
  }

  void AddPatchLink(int q, ShooterLinks& links) const
  {
    links.Patches.push_back(q);
    links.NodeFactorBegin.push_back(static_cast<int>(links.NodeFactors.size()));
    double covered = 0;
    for (int j = Nodes.Begin(q); j < Nodes.End(q); ++j)
    {
      const float f = static_cast<float>(NodeFactor[j]);
      links.NodeFactors.push_back(f);
      covered += f * Nodes.CoveredArea(j);
    }
    links.MeanFactors.push_back(covered / G.PatchOpenArea[q]); // unshot spreads over the open area
    links.ReceivingArea += covered;
  }

  /// The node links of group q (a cluster receiver), after the groups before it.
  void AddClusterLinks(int q, ShooterLinks& links) const
  {
    for (const auto& link : NodeLinks[q])
    {
      links.Clusters.push_back(link.first);
      for (int k = 0; k < 3; ++k)
      {
        links.ClusterVectors.push_back(static_cast<float>(link.second[k]));
      }
      links.ReceivingArea += Dot(ClusterNodes.OpenArea[link.first], link.second);
    }
    links.ClusterEnd.push_back(static_cast<int>(links.Clusters.size()));
  }

  /// Scales every link of the shooter so that it delivers no more than it shoots, and
  /// exactly that when it sees a closed scene (ShooterFormFactors::ConservationScale), over
  /// the links of every process.
  void Conserve(int shooter, ShooterLinks& links) const
  {
    double receiving = links.ReceivingArea;
    Ranks.Sum(&receiving, 1);
    const double scale = Factors.ConservationScale(shooter, receiving);
    if (scale == 1.0)
    {
      return;
    }
    for (float& f : links.NodeFactors)
    {
      f = static_cast<float>(f * scale);
    }
    for (double& f : links.MeanFactors)
    {
      f *= scale;
    }
    for (float& f : links.ElementFactors)
    {
      f = static_cast<float>(f * scale);
    }
    for (float& f : links.ClusterVectors)
    {
      f = static_cast<float>(f * scale);
    }
    for (float& f : links.VolumeVectors)
    {
      f = static_cast<float>(f * scale);
    }
    links.ReceivingArea *= scale;
  }

  /// Decides per receiver patch: no link, one patch link, or element links.
  void Classify(int shooter, double shotFraction, SolverStatistics& stats)
  {
    std::fill(Kind.begin(), Kind.end(), LinkKind::None);
    std::fill(SharedVisibility.begin(), SharedVisibility.end(), -1.0);
    std::atomic<long long> rays{ 0 };
    const std::vector<int>& tasks = Tree.Frontier();
    TaskVolumes.assign(tasks.size(), {});
    Pool.For(static_cast<int>(tasks.size()), 1, [&](int begin, int end) {
      thread_local std::vector<Vec3> scratch;
      long long chunkRays = 0;
      for (int t = begin; t < end; ++t)
      {
        Visit(shooter, tasks[t], shotFraction, scratch, chunkRays, TaskVolumes[t]);
      }
      rays += chunkRays;
    });
    stats.RayCount += rays;
    stats.FormFactorCount += std::count(Owned.begin(), Owned.end(), 1);
  }

  /// Decides for the patches of patch-tree node n: passes over all of them where the node
  /// lies behind the shooter, faces away from it, or is far and out of its sight; links it
  /// whole where it is far enough and in full view; else asks its children, or each patch.
  void Visit(int s, int n, double shotFraction, std::vector<Vec3>& scratch, long long& rays,
    std::vector<std::pair<int, Vec3>>& volumes)
  {
    const PatchTree::Node& node = Tree.Nodes()[n];
    const Vec3& cs = Factors.Centre(s);
    const double rs = Factors.Radius(s);
    if (BehindBall(cs, rs, Factors.Cone(s), node.Centre, node.Radius) ||
      BehindBall(node.Centre, node.Radius, node.Cone, cs, rs))
    {
      return;
    }
    const double distance = Norm(node.Centre - cs);
    if (node.Count > 1 && distance > kHiddenNodeRadii * (node.Radius + rs))
    {
      const double seen = InView(s, n, rays);
      if (seen == 0)
      {
        return;
      }
      if (seen == 1 && distance - rs >= kVolumeNearRadii * node.Radius && TakeWhole(s, n, shotFraction, volumes))
      {
        return;
      }
    }
    if (node.Left >= 0)
    {
      Visit(s, node.Left, shotFraction, scratch, rays, volumes);
      Visit(s, node.Right, shotFraction, scratch, rays, volumes);
      return;
    }
    for (int i = node.First; i < node.First + node.Count; ++i)
    {
      const int q = Tree.Patches()[i];
      Kind[q] = q == s || !Owned[q] ? LinkKind::None : Decide(s, q, shotFraction, scratch, rays);
    }
  }

  /// Links node n whole unless the transfer is strong enough to want patch resolution
  /// (the refinement threshold) or a face cluster in it is not wholly in front of the
  /// shooter; false when it must be refined.
  bool TakeWhole(int s, int n, double shotFraction, std::vector<std::pair<int, Vec3>>& volumes) const
  {
    const Vec3 v = Factors.FactorVector(s, Tree.Nodes()[n].Centre);
    const double covered = VolumeReceiving(n, v, false, s);
    if (covered < 0 || shotFraction * covered / G.PatchArea[s] >= Threshold)
    {
      return false;
    }
    if (covered > 0)
    {
      volumes.push_back({ n, v });
    }
    return true;
  }

  /// Whether node n's elements that face the shooter are in its full view (1), out of it
  /// (0, also where none faces it) or partly (in between), by kHiddenNodeRays rays.
  double InView(int s, int n, long long& rays) const
  {
    const PatchTree::Node& node = Tree.Nodes()[n];
    if (node.ElementCount == 0)
    {
      return -1.0; // no elements to aim at: neither hidden nor seen
    }
    if (Samples <= 0 || Factors.BlockingPlanes() == 0)
    {
      return 1.0; // no shadows, or nothing that could cast one
    }
    const std::uint64_t seed = (std::uint64_t{ 1 } << 40) + static_cast<std::uint64_t>(n);
    long long cast = 0;
    const double seen = Factors.VisibleFractionOfFacing(
      s, Tree.Targets().data() + node.ElementFirst, node.ElementCount, kHiddenNodeRays, seed, cast);
    rays += Ranks.Rank() == 0 ? cast : 0; // every rank casts the same rays: count them once
    return seen;
  }

  LinkKind Decide(int s, int q, double shotFraction, std::vector<Vec3>& scratch, long long& rays)
  {
    if (!Factors.Planar(s) || !Factors.Planar(q))
    {
      return DecideForCluster(s, q, scratch, rays);
    }
    const Vec3 d = Factors.Centre(q) - Factors.Centre(s);
    const double ahead = Dot(Factors.Normal(s), d), facing = -Dot(Factors.Normal(q), d);
    const double rs = Factors.Radius(s), rq = Factors.Radius(q);
    if (ahead + rq <= 0 || facing + rs <= 0)
    {
      return LinkKind::None; // one wholly behind the other's plane: nothing passes
    }
    if (Norm(d) < kNearRadii * (rs + rq) || Straddles(q, s) || Straddles(s, q))
    {
      return LinkKind::Elements; // near, or partly behind a plane: resolve per element
    }
    const double covered = NodeFactors(s, q, scratch);
    if (covered <= 0 || G.PatchOpenArea[q] <= 0)
    {
      return LinkKind::None;
    }
    // Power fraction reaching q: F(s -> q) = F(q -> s) A_q / A_s.
    if (shotFraction * covered / G.PatchArea[s] >= Threshold)
    {
      return LinkKind::Elements; // strong transfer: worth element resolution
    }
    const double visible = Visible(s, q, rays);
    for (int j = Nodes.Begin(q); j < Nodes.End(q); ++j)
    {
      NodeFactor[j] *= visible;
    }
    return visible > 0 ? LinkKind::Patch : LinkKind::None;
  }

  /// Decide where one of the two is a face cluster (not flat). A flat receiver is linked
  /// whole, through node factors from the cluster's tree, where it is far and faces all of
  /// the shooter; a cluster receiver links node by node (LinkNode).
  LinkKind DecideForCluster(int s, int q, std::vector<Vec3>& scratch, long long& rays)
  {
    const Vec3 &cs = Factors.Centre(s), &cq = Factors.Centre(q);
    const double rs = Factors.Radius(s), rq = Factors.Radius(q);
    if (BehindBall(cs, rs, Factors.Cone(s), cq, rq) || BehindBall(cq, rq, Factors.Cone(q), cs, rs) ||
      G.PatchOpenArea[q] <= 0)
    {
      return LinkKind::None;
    }
    const bool near = Norm(cq - cs) < (Factors.Planar(q) ? kNearRadii : kClusterNearRadii) * (rs + rq);
    if (!Factors.Planar(q))
    {
      NodeLinks[q].clear();
      NodeElements[q].clear();
      double shared = -2; // not cast yet
      LinkNode(s, q, ClusterNodes.Root[q], near, shared, rays);
      return NodeLinks[q].empty() && NodeElements[q].empty() ? LinkKind::None : LinkKind::Cluster;
    }
    if (near)
    {
      return LinkKind::Elements;
    }
    if (!FacesBall(cq, rq, Factors.Cone(q), cs, rs))
    {
      // Far, but the receiver's plane cuts part of the shooter: each element gets its own
      // factor, all one visibility (rays per element would not see more this far).
      SharedVisibility[q] = Visible(s, q, rays, kSharedRays);
      return SharedVisibility[q] > 0 ? LinkKind::Elements : LinkKind::None;
    }
    if (!(NodeFactors(s, q, scratch) > 0))
    {
      return LinkKind::None;
    }
    const double visible = Visible(s, q, rays);
    for (int j = Nodes.Begin(q); j < Nodes.End(q); ++j)
    {
      NodeFactor[j] *= visible;
    }
    return visible > 0 ? LinkKind::Patch : LinkKind::None;
  }

  /// Links node n of cluster q: whole (a factor vector at its centre) where the shooter is
  /// far from it and in front of all its elements, else through its children, and at a
  /// leaf element by element. Visibility: per node and element for a near pair, else one
  /// for the pair (`shared`, cast once).
  void LinkNode(int s, int q, int n, bool near, double& shared, long long& rays)
  {
    const ReceiverNodes& c = ClusterNodes;
    const Vec3& cs = Factors.Centre(s);
    const double rs = Factors.Radius(s);
    if (BehindBall(cs, rs, Factors.Cone(s), c.Centre[n], c.Radius[n]) ||
      BehindBall(c.Centre[n], c.Radius[n], c.Cone[n], cs, rs))
    {
      return;
    }
    Vec3 v;
    if (WholeNodeVector(s, c.Centre[n], c.Radius[n], c.Cone[n], v))
    {
      const double visible = Dot(c.OpenArea[n], v) > 0 ? (near ? NodeVisible(s, q, n, rays) : Shared(s, q, shared, rays)) : 0;
      if (visible > 0)
      {
        NodeLinks[q].push_back({ n, v * visible });
      }
      return;
    }
    if (c.Left[n] >= 0)
    {
      LinkNode(s, q, c.Left[n], near, shared, rays);
      LinkNode(s, q, c.Right[n], near, shared, rays);
      return;
    }
    const double mode = near ? -1.0 : Shared(s, q, shared, rays);
    for (int i = c.ElementBegin[n]; i < c.ElementEnd[n] && mode != 0; ++i)
    {
      NodeElements[q].push_back({ c.Elements[i], mode });
    }
  }

  /// The factor vector from shooter s to a receiver node where one holds for all of it: the
  /// shooter (each part of it, where it is a cluster) far from the node and in front of
  /// all its elements.
  bool WholeNodeVector(int s, const Vec3& c, double r, const NormalCone& cone, Vec3& v) const
  {
    if (const ClusterTree* tree = Factors.Tree(s))
    {
      return tree->FactorVectorFor(c, r, cone, kNodeNearRadii, v);
    }
    const Vec3& cs = Factors.Centre(s);
    const double rs = Factors.Radius(s);
    if (Norm(c - cs) - rs < kNodeNearRadii * r || !FacesBall(c, r, cone, cs, rs))
    {
      return false;
    }
    v = Factors.FactorVector(s, c);
    return true;
  }

  double Shared(int s, int q, double& shared, long long& rays) const
  {
    if (shared < -1)
    {
      shared = Visible(s, q, rays, kSharedRays);
    }
    return shared;
  }

  /// The unblocked fraction of rays from the shooter to node n's elements.
  double NodeVisible(int s, int q, int n, long long& rays) const
  {
    if (Samples <= 0 || !Factors.MayBeBlockedBetweenPatches(q, s))
    {
      return 1.0;
    }
    const ReceiverNodes& c = ClusterNodes;
    rays += Samples;
    return static_cast<double>(Factors.VisibleRaysToElements(s, c.Elements.data() + c.ElementBegin[n],
             c.ElementEnd[n] - c.ElementBegin[n], Samples, static_cast<std::uint64_t>(n))) / Samples;
  }

  /// The unblocked fraction of the rays between two patches (1 where none can be blocked),
  /// `perSample` rays for each of Samples.
  double Visible(int s, int q, long long& rays, int perSample = 1) const
  {
    if (Samples <= 0 || !Factors.MayBeBlockedBetweenPatches(q, s))
    {
      return 1.0;
    }
    const int samples = Samples * perSample;
    rays += samples;
    return static_cast<double>(Factors.VisibleRaysBetweenPatches(q, s, samples)) / samples;
  }


  /// F(node -> s) at q's nodes, scaled so that their interpolant integrates over q like a
  /// rule exact for quadratics: 3/4 of the fan triangles' centroid rule plus 1/4 of their
  /// vertex rule (the interpolant's own integral). The vertex rule alone overestimates a
  /// convex factor and underestimates a concave one, and the shooters linked per element
  /// cannot make up for it: a closed box lost 0.1 % of every shot. Returns the integral.
  double NodeFactors(int s, int q, std::vector<Vec3>& scratch)
  {
    const Vec3& normal = Factors.Normal(q);
    double vertexRule = 0;
    for (int j = Nodes.Begin(q); j < Nodes.End(q); ++j)
    {
      NodeFactor[j] = Factors.PointFactor(s, Nodes.Node(j), normal, scratch);
      vertexRule += NodeFactor[j] * Nodes.CoveredArea(j);
    }
    if (Nodes.FanEnd(q) <= Nodes.FanBegin(q) || vertexRule <= 0)
    {
      return vertexRule;
    }
    double centroidRule = 0;
    for (int t = Nodes.FanBegin(q); t < Nodes.FanEnd(q); ++t)
    {
      centroidRule += Factors.PointFactor(s, Nodes.FanCentroid(t), normal, scratch) * Nodes.FanArea(t);
    }
    const double integral = 0.75 * centroidRule + 0.25 * vertexRule;
    for (int j = Nodes.Begin(q); j < Nodes.End(q); ++j)
    {
      NodeFactor[j] *= integral / vertexRule;
    }
    return integral;
  }

  /// True when part of patch `a` lies behind the plane of patch `b` (where the form factor
  /// is cut off inside `a`, which one value per node cannot represent).
  bool Straddles(int a, int b) const
  {
    const double tolerance = 1e-9 * G.SceneDiagonal;
    if (Nodes.End(a) - Nodes.Begin(a) < 3)
    {
      return Dot(Factors.Normal(b), Factors.Centre(a) - Factors.Centre(b)) - Factors.Radius(a) <= 0;
    }
    for (int j = Nodes.Begin(a); j < Nodes.End(a); ++j)
    {
      if (Dot(Factors.Normal(b), Nodes.Node(j) - Factors.Centre(b)) < -tolerance)
      {
        return true;
      }
    }
    return false;
  }

  /// Element factors for every element group, kept in patch order. Several ranks share
  /// the work of all their groups element by element: a shooter's near patches are few, so
  /// whole patches would leave one rank waiting for another at every link-building shot.
  void LinkElements(int shooter, ShooterLinks& links, SolverStatistics& stats)
  {
    std::vector<int> elements, groupSize;
    ElementVisibility.clear();
    for (int q : links.Groups)
    {
      AddClusterLinks(q, links);
      if (Kind[q] == LinkKind::Cluster)
      {
        for (const auto& e : NodeElements[q])
        {
          elements.push_back(e.first);
          ElementVisibility.push_back(e.second);
        }
        groupSize.push_back(static_cast<int>(NodeElements[q].size()));
        continue;
      }
      elements.insert(elements.end(), G.PatchElements[q].begin(), G.PatchElements[q].end());
      ElementVisibility.insert(ElementVisibility.end(), G.PatchElements[q].size(), SharedVisibility[q]);
      groupSize.push_back(static_cast<int>(G.PatchElements[q].size()));
    }
    if (Ranks.Distributed())
    {
      ShareFactors(shooter, elements, stats);
    }
    else
    {
      Scratch.assign(elements.size(), 0.0);
      ComputeFactors(shooter, elements, 0, 1, stats);
    }
    stats.FormFactorCount += static_cast<long long>(elements.size());
    size_t k = 0;
    for (size_t group = 0; group < links.Groups.size(); ++group)
    {
      for (int j = 0; j < groupSize[group]; ++j, ++k)
      {
        const float f = static_cast<float>(Scratch[k]);
        if (f > 0)
        {
          links.Elements.push_back(elements[k]);
          links.ElementFactors.push_back(f);
          links.ReceivingArea += static_cast<double>(f) * G.Area[elements[k]];
        }
      }
      links.GroupEnd.push_back(static_cast<int>(links.Elements.size()));
    }
  }

  /// Scratch[k] = F(elements[k] -> shooter) for every k = first + i * step, in parallel.
  void ComputeFactors(int shooter, const std::vector<int>& elements, int first, int step, SolverStatistics& stats)
  {
    const int count = static_cast<int>(elements.size()) > first
      ? (static_cast<int>(elements.size()) - first + step - 1) / step
      : 0;
    std::atomic<long long> rays{ 0 };
    Pool.For(count, 16, [&](int begin, int end) {
      thread_local std::vector<Vec3> scratch;
      ShooterFormFactors::RayCounts counts;
      for (int i = begin; i < end; ++i)
      {
        const size_t k = static_cast<size_t>(first) + static_cast<size_t>(i) * step;
        const double shared = ElementVisibility[k];
        Scratch[k] = shared < 0 ? Factors.ElementFactor(shooter, elements[k], Samples, scratch, counts)
                                : Factors.ReceiverFactor(shooter, elements[k], scratch) * shared;
      }
      rays += counts.Rays;
      Factors.Count(counts, Samples);
    });
    stats.RayCount += rays;
  }

  /// The ranks' element lists joined in rank order; each rank computes every Ranks-th
  /// factor of the whole list, and a sum gives every rank all of them. Scratch ends with
  /// this rank's own elements' factors, in their order.
  void ShareFactors(int shooter, const std::vector<int>& mine, SolverStatistics& stats)
  {
    std::vector<double> counts(Ranks.Ranks(), 0.0);
    counts[Ranks.Rank()] = static_cast<double>(mine.size());
    Ranks.Sum(counts);
    size_t before = 0, total = 0;
    for (int r = 0; r < Ranks.Ranks(); ++r)
    {
      before += r < Ranks.Rank() ? static_cast<size_t>(counts[r]) : 0;
      total += static_cast<size_t>(counts[r]);
    }
    // Ids and shared visibilities (-1: per element) in one sum, the visibility shifted by 2
    // so that the zeros of the other ranks' parts add nothing.
    std::vector<double> ids(2 * total, 0.0);
    std::copy(mine.begin(), mine.end(), ids.begin() + static_cast<std::ptrdiff_t>(before));
    for (size_t k = 0; k < mine.size(); ++k)
    {
      ids[total + before + k] = ElementVisibility[k] + 2;
    }
    Ranks.Sum(ids);
    const std::vector<int> all(ids.begin(), ids.begin() + static_cast<std::ptrdiff_t>(total));
    ElementVisibility.assign(ids.begin() + static_cast<std::ptrdiff_t>(total), ids.end());
    for (double& v : ElementVisibility)
    {
      v -= 2;
    }
    Scratch.assign(total, 0.0);
    ComputeFactors(shooter, all, Ranks.Rank(), Ranks.Ranks(), stats);
    Ranks.Sum(Scratch); // each factor computed by one rank, zero elsewhere: the sum is exact
    Scratch.erase(Scratch.begin(), Scratch.begin() + static_cast<std::ptrdiff_t>(before));
    Scratch.resize(mine.size());
  }

  const SceneGeometry& G;
  ShooterFormFactors& Factors;
  const PatchNodes& Nodes;
  const PatchTree& Tree;
  const WorkerPool& Pool;
  const int Samples;
  const double Threshold;
  const int Patches;
  std::vector<LinkKind> Kind;
  std::vector<double> NodeFactor, Scratch;
  const ReceiverNodes& ClusterNodes;
  /// Per receiver cluster: its node links (node, factor vector) and the elements linked one
  /// by one (element, shared visibility or -1), made in Classify.
  std::vector<std::vector<std::pair<int, Vec3>>> NodeLinks;
  std::vector<std::vector<std::pair<int, double>>> NodeElements;
  /// Per receiver patch, one visibility for all its element links (-1: rays per element),
  /// and the same per element of the list being computed.
  std::vector<double> SharedVisibility, ElementVisibility;
  const std::vector<char>& Owned;
  Collective& Ranks;
  /// Per patch, the area its nodes cover (a uniform factor's integral per unit factor).
  std::vector<double> PatchCovered;
  /// The volume links found by each task of the walk, joined in task order.
  std::vector<std::vector<std::pair<int, Vec3>>> TaskVolumes;
};

std::vector<Vec3> MeanReflectance(const SceneMesh& mesh, const SceneGeometry& g)
{
  std::vector<Vec3> mean(g.PatchElements.size());
  for (size_t p = 0; p < mean.size(); ++p)
  {
    for (int e : g.PatchElements[p])
    {
      mean[p] += mesh.Reflectance[e] * (g.Area[e] / g.PatchArea[p]);
    }
  }
  return mean;
}

/// Sends the current shot along a shooter's links; returns the power received.
template <typename Channel>
double DistributeAlongLinks(ShootingState<Channel>& state, const WorkerPool& pool, const LinkBuilder& builder,
  const ShooterLinks& links, const std::vector<Vec3>& meanReflectance)
{
  const int patchLinks = static_cast<int>(links.Patches.size());
  const int volumes = static_cast<int>(links.Volumes.size());
  const int items = volumes + patchLinks + static_cast<int>(links.Groups.size());
  // Every item touches its own receiver patches (a volume link those of its node, which no
  // other link of the shooter reaches), so the items run in parallel safely.
  pool.For(items, 8, [&](int begin, int end) {
    for (int item = begin; item < end; ++item)
    {
      if (item < volumes)
      {
        builder.DeliverVolume(state, links, item, meanReflectance);
        continue;
      }
      const int i = item - volumes;
      if (i < patchLinks)
      {
        const int q = links.Patches[i];
        state.GatherPatch(q, links.NodeFactors.data() + links.NodeFactorBegin[i], links.MeanFactors[i], meanReflectance[q]);
        continue;
      }
      const int group = i - patchLinks;
      for (int c = group == 0 ? 0 : links.ClusterEnd[group - 1]; c < links.ClusterEnd[group]; ++c)
      {
        const float* v = links.ClusterVectors.data() + 3 * c;
        state.GatherCluster(links.Clusters[c], Vec3{ v[0], v[1], v[2] });
      }
      const int first = group == 0 ? 0 : links.GroupEnd[group - 1];
      for (int j = first; j < links.GroupEnd[group]; ++j)
      {
        state.Gather(links.Elements[j], links.ElementFactors[j]);
        state.Deposit(links.Elements[j], links.ElementFactors[j]);
      }
    }
  });
  return state.ShotTotal() * links.ReceivingArea;
}

template <typename Channel>
void Shoot(const SceneMesh& mesh, const SceneGeometry& g, const Visibility& rays,
  const std::vector<Vec3>& emission, int L, const SolverOptions& options, SolverClock::time_point start,
  Solution& out)
{
  ShootingState<Channel> state(mesh, g, emission, L, options, start, out);
  SolverStatistics& stats = out.Statistics;
  WorkerPool pool(options.Threads);
  ShooterFormFactors estimator(mesh, g, rays, pool, options.Visibility == EffectMode::Auto);
  estimator.SetReceivers(&state.OwnedPatchFlags());
  const PatchNodes nodes(g, estimator.PatchLoops(), estimator.Centres());
  const ReceiverNodes clusters(g, estimator);
  const PatchTree tree(g, estimator);
  state.EnablePatchGathering(nodes);
  state.EnableClusterGathering(clusters);
  const int samples = options.Visibility == EffectMode::Off ? 0 : options.FormFactorSamples;
  const double refine = options.Hierarchical.RefinementThreshold > 0 ? options.Hierarchical.RefinementThreshold : 2.0; // 2: never
  LinkBuilder builder(g, estimator, nodes, clusters, tree, pool, samples, refine, state.OwnedPatchFlags(), state.Ranks());
  const std::vector<Vec3> meanReflectance = MeanReflectance(mesh, g);
  std::vector<ShooterLinks> links(state.Patches);
  std::vector<double> factors;
  while (state.Continue())
  {
    const int shooter = state.PickShooter();
    const bool emitting = options.Hierarchical.DirectToElements && state.Emitting(shooter);
    state.TakeShot(shooter);
    if (emitting)
    {
      // Direct light: every element, per-element shadow rays, nothing kept.
      const StepTimer timer(stats, "direct light");
      ShootToElements(state, pool, estimator, shooter, FormFactorMethod::Analytic, samples, stats, factors);
      continue;
    }
    if (!links[shooter].Built)
    {
      const StepTimer timer(stats, "links");
      links[shooter] = builder.Build(shooter, state.ShotFraction(shooter), stats);
    }
    const StepTimer timer(stats, "shots");
    state.EndShot(shooter, DistributeAlongLinks(state, pool, builder, links[shooter], meanReflectance));
  }
  state.Finish(estimator);
}
} // namespace

void SolveHierarchical(const SceneMesh& mesh, const SceneGeometry& geometry, const Visibility& rays,
  const std::vector<Vec3>& emission, int solutions, bool grey, const SolverOptions& options,
  SolverClock::time_point start, Solution& out)
{
  out.Statistics.SolverMethod = SolverMethod::Hierarchical;
  WithChannel(grey, [&](auto channel) {
    Shoot<decltype(channel)>(mesh, geometry, rays, emission, solutions, options, start, out);
  });
}

} // namespace radiosity
