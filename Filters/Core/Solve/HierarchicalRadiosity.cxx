#include "Solve/HierarchicalRadiosity.h"
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
  /// Face clusters taken whole: F(element -> shooter) = normal . vector for each element.
  std::vector<int> Clusters;
  std::vector<float> ClusterVectors; ///< three per cluster link
  std::vector<int> Groups;   ///< receiver patch of each element group
  std::vector<int> GroupEnd; ///< end of each group in Elements
  std::vector<int> Elements;
  std::vector<float> ElementFactors;
  /// Sum of factor x receiver area: the power received per unit of shot radiosity.
  double ReceivingArea = 0;
  bool Built = false;

  double Bytes() const
  {
    return static_cast<double>(Patches.size() * 4 + NodeFactors.size() + Clusters.size() * 4 + Groups.size() * 2 +
             Elements.size() * 2) * 4;
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
/// The same for a face cluster taken whole: it has one value (a vector) at its centre, no
/// corners to interpolate between, so it must be farther for the value to hold across it.
constexpr double kClusterNearRadii = 3.0;
/// Rays per sample for one visibility shared by a far receiver's element links: they stand
/// for all of its elements' rays, so they are more.
constexpr int kSharedRays = 4;

class LinkBuilder
{
public:
  /// `owned`: the receiver patches this process links to; `ranks`: the processes solving
  /// together, which share the element factors of every shooter's near patches.
  LinkBuilder(const SceneGeometry& g, ShooterFormFactors& factors, const PatchNodes& nodes, const WorkerPool& pool,
    int samples, double threshold, const std::vector<char>& owned, Collective& ranks)
    : G(g)
    , Factors(factors)
    , Nodes(nodes)
    , Pool(pool)
    , Samples(samples)
    , Threshold(threshold)
    , Patches(static_cast<int>(g.patchElements.size()))
    , Kind(Patches)
    , NodeFactor(nodes.Count())
    , ClusterVector(Patches)
    , SharedVisibility(Patches, -1.0)
    , Owned(owned)
    , Ranks(ranks)
    , OpenAreaVector(Patches)
  {
    for (size_t e = 0; e < g.normal.size(); ++e)
    {
      if (!g.sheltered[e])
      {
        OpenAreaVector[g.elementPatch[e]] += g.normal[e] * g.area[e];
      }
    }
  }

  /// `shotFraction`: the largest fraction of a solution's emitted power this shot carries.
  ShooterLinks Build(int shooter, double shotFraction, SolverStatistics& stats)
  {
    Classify(shooter, shotFraction, stats);
    ShooterLinks links;
    links.Built = true;
    for (int q = 0; q < Patches; ++q)
    {
      if (Kind[q] == LinkKind::Patch)
      {
        AddPatchLink(q, links);
      }
      else if (Kind[q] == LinkKind::Cluster)
      {
        AddClusterLink(q, links);
      }
      else if (Kind[q] == LinkKind::Elements)
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

private:
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
    links.MeanFactors.push_back(covered / G.patchOpenArea[q]); // unshot spreads over the open area
    links.ReceivingArea += covered;
  }

  void AddClusterLink(int q, ShooterLinks& links) const
  {
    const Vec3& v = ClusterVector[q];
    links.Clusters.push_back(q);
    for (int k = 0; k < 3; ++k)
    {
      links.ClusterVectors.push_back(static_cast<float>(v[k]));
    }
    links.ReceivingArea += Receiving(q, v);
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
    links.ReceivingArea *= scale;
  }

  /// Decides per receiver patch: no link, one patch link, or element links.
  void Classify(int shooter, double shotFraction, SolverStatistics& stats)
  {
    std::atomic<long long> rays{ 0 };
    Pool.For(Patches, 16, [&](int begin, int end) {
      thread_local std::vector<Vec3> scratch;
      long long chunkRays = 0;
      for (int q = begin; q < end; ++q)
      {
        SharedVisibility[q] = -1;
        Kind[q] = q == shooter || !Owned[q] ? LinkKind::None : Decide(shooter, q, shotFraction, scratch, chunkRays);
      }
      rays += chunkRays;
    });
    stats.RayCount += rays;
    stats.FormFactorCount += std::count(Owned.begin(), Owned.end(), 1);
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
    if (covered <= 0 || G.patchOpenArea[q] <= 0)
    {
      return LinkKind::None;
    }
    // Power fraction reaching q: F(s -> q) = F(q -> s) A_q / A_s.
    if (shotFraction * covered / G.patchArea[s] >= Threshold)
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

  /// Decide where one of the two is a face cluster (not flat): whole when far enough and the
  /// receiver faces all of the shooter (so that its cosines stay positive),
  /// through node factors to a flat receiver, through a factor vector to a cluster.
  LinkKind DecideForCluster(int s, int q, std::vector<Vec3>& scratch, long long& rays)
  {
    const Vec3 &cs = Factors.Centre(s), &cq = Factors.Centre(q);
    const double rs = Factors.Radius(s), rq = Factors.Radius(q);
    if (BehindBall(cs, rs, Factors.Cone(s), cq, rq) || BehindBall(cq, rq, Factors.Cone(q), cs, rs))
    {
      return LinkKind::None;
    }
    const double near = Factors.Planar(q) ? kNearRadii : kClusterNearRadii;
    // The receiver's elements must all face the whole shooter (so n . v is each one's
    // factor); the shooter's may turn away in part, which its tree accounts for at the
    // receiver's centre and which changes slowly across a receiver this far away.
    if (Norm(cq - cs) < near * (rs + rq) || G.patchOpenArea[q] <= 0)
    {
      return LinkKind::Elements;
    }
    if (!FacesBall(cq, rq, Factors.Cone(q), cs, rs))
    {
      // Far, but some of the receiver's elements turn from part of the shooter: each gets
      // its own factor, all one visibility (rays per element would not see more this far).
      SharedVisibility[q] = Visible(s, q, rays, kSharedRays);
      return SharedVisibility[q] > 0 ? LinkKind::Elements : LinkKind::None;
    }
    double received = 0;
    if (Factors.Planar(q))
    {
      received = NodeFactors(s, q, scratch);
    }
    else
    {
      ClusterVector[q] = Factors.FactorVector(s, cq);
      received = Receiving(q, ClusterVector[q]);
    }
    if (!(received > 0))
    {
      return LinkKind::None;
    }
    const double visible = Visible(s, q, rays);
    for (int j = Nodes.Begin(q); j < Nodes.End(q); ++j)
    {
      NodeFactor[j] *= visible;
    }
    ClusterVector[q] = ClusterVector[q] * visible;
    return visible <= 0 ? LinkKind::None : Factors.Planar(q) ? LinkKind::Patch : LinkKind::Cluster;
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

  /// Power a cluster's open elements receive per unit shot radiosity through vector v.
  double Receiving(int q, const Vec3& v) const { return Dot(OpenAreaVector[q], v); }

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
    const double tolerance = 1e-9 * G.sceneDiagonal;
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
    std::vector<int> elements;
    ElementVisibility.clear();
    for (int q : links.Groups)
    {
      elements.insert(elements.end(), G.patchElements[q].begin(), G.patchElements[q].end());
      ElementVisibility.insert(ElementVisibility.end(), G.patchElements[q].size(), SharedVisibility[q]);
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
    for (int q : links.Groups)
    {
      for (size_t j = 0; j < G.patchElements[q].size(); ++j, ++k)
      {
        const float f = static_cast<float>(Scratch[k]);
        if (f > 0)
        {
          links.Elements.push_back(elements[k]);
          links.ElementFactors.push_back(f);
          links.ReceivingArea += static_cast<double>(f) * G.area[elements[k]];
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
  const WorkerPool& Pool;
  const int Samples;
  const double Threshold;
  const int Patches;
  std::vector<LinkKind> Kind;
  std::vector<double> NodeFactor, Scratch;
  std::vector<Vec3> ClusterVector; ///< per receiver cluster, this shooter's factor vector
  /// Per receiver patch, one visibility for all its element links (-1: rays per element),
  /// and the same per element of the list being computed.
  std::vector<double> SharedVisibility, ElementVisibility;
  const std::vector<char>& Owned;
  Collective& Ranks;
  std::vector<Vec3> OpenAreaVector; ///< per patch, the sum of area x normal of its open elements
};

std::vector<Vec3> MeanReflectance(const SceneMesh& mesh, const SceneGeometry& g)
{
  std::vector<Vec3> mean(g.patchElements.size());
  for (size_t p = 0; p < mean.size(); ++p)
  {
    for (int e : g.patchElements[p])
    {
      mean[p] += mesh.reflectance[e] * (g.area[e] / g.patchArea[p]);
    }
  }
  return mean;
}

/// Sends the current shot along a shooter's links; returns the power received.
template <typename Channel>
double DistributeAlongLinks(ShootingState<Channel>& state, const WorkerPool& pool, const ShooterLinks& links,
  const std::vector<Vec3>& meanReflectance)
{
  const int patchLinks = static_cast<int>(links.Patches.size());
  const int wholeLinks = patchLinks + static_cast<int>(links.Clusters.size());
  const int items = wholeLinks + static_cast<int>(links.Groups.size());
  // Every item touches one receiver patch only, so the items run in parallel safely.
  pool.For(items, 8, [&](int begin, int end) {
    for (int i = begin; i < end; ++i)
    {
      if (i < patchLinks)
      {
        const int q = links.Patches[i];
        state.GatherPatch(q, links.NodeFactors.data() + links.NodeFactorBegin[i], links.MeanFactors[i], meanReflectance[q]);
        continue;
      }
      if (i < wholeLinks)
      {
        const float* v = links.ClusterVectors.data() + 3 * (i - patchLinks);
        state.GatherCluster(links.Clusters[i - patchLinks], Vec3{ v[0], v[1], v[2] });
        continue;
      }
      const int group = i - wholeLinks;
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
  state.EnablePatchGathering(nodes);
  state.EnableClusterGathering();
  const int samples = options.Visibility == EffectMode::Off ? 0 : options.Samples;
  const double refine = options.RefinementThreshold > 0 ? options.RefinementThreshold : 2.0; // 2: never
  LinkBuilder builder(g, estimator, nodes, pool, samples, refine, state.OwnedPatchFlags(), state.Ranks());
  const std::vector<Vec3> meanReflectance = MeanReflectance(mesh, g);
  std::vector<ShooterLinks> links(state.Patches);
  std::vector<double> factors;
  while (state.Continue())
  {
    const int shooter = state.PickShooter();
    const bool emitting = options.DirectToElements && state.Emitting(shooter);
    state.TakeShot(shooter);
    if (emitting)
    {
      // Direct light: every element, per-element shadow rays, nothing kept.
      ShootToElements(state, pool, estimator, shooter, FormFactorMethod::Analytic, samples, stats, factors);
      continue;
    }
    if (!links[shooter].Built)
    {
      links[shooter] = builder.Build(shooter, state.ShotFraction(shooter), stats);
    }
    state.EndShot(shooter, DistributeAlongLinks(state, pool, links[shooter], meanReflectance));
  }
  state.Finish(estimator);
}
} // namespace

void SolveHierarchical(const SceneMesh& mesh, const SceneGeometry& geometry, const Visibility& rays,
  const std::vector<Vec3>& emission, int solutions, bool grey, const SolverOptions& options,
  SolverClock::time_point start, Solution& out)
{
  out.Statistics.Method = SolverMethod::Hierarchical;
  WithChannel(grey, [&](auto channel) {
    Shoot<decltype(channel)>(mesh, geometry, rays, emission, solutions, options, start, out);
  });
}

} // namespace radiosity
