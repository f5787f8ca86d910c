#include "Solve/ClusterLinks.h"
#include "Geometry/FormFactor.h"
#include "Geometry/Polygon.h"
#include "Base/SampleStream.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace radiosity
{

struct ClusterLinkBuilder::Found
{
  std::vector<int> Receiver, Source, LeafReceiver, LeafSource;
  std::vector<float> Coupling, LeafFactor;
  std::vector<unsigned char> Mixed;
  long long Rays = 0;
  std::vector<Vec3> Loop, Scratch; ///< NearFactor's buffers, reused over the task's pairs
};

namespace
{
/// A pair of nodes farther apart than this many of the sum of their radii that none of
/// kHiddenRays rays between points facing each other connects is passed over whole (the
/// rooms behind a wall) instead of being split down to where its links would be made.
constexpr double kHiddenRadii = 2.0;
constexpr int kHiddenRays = 16;
/// Times the shadow rays for a partly visible pair of elements that exchange much.
constexpr int kPartialSamples = 4;
/// Draws beyond a pair's rays, times its rays (and at least kNodePoints), to find points
/// that face each other.
constexpr int kExtraDraws = 4;
/// The factor from which a link gets all its shadow rays (RaysFor); below, fewer.
constexpr double kFullRaysFactor = 1e-4;

} // namespace

void ClusterLinkBuilder::SortByReceiver(
  std::vector<Found>& found, ClusterLinkSet& links, std::vector<size_t>& far) const
{
  // A counting sort over every task's links, in task order: each task's lists are freed
  // once placed, so the links are held at most twice.
  std::vector<size_t>& near = links.NearStart;
  far.assign(Tree.Nodes().size() + 1, 0);
  near.assign(G.Normal.size() + 1, 0);
  for (const Found& f : found)
  {
    for (int r : f.Receiver)
    {
      ++far[r + 1];
    }
    for (int r : f.LeafReceiver)
    {
      ++near[r + 1];
    }
    links.Rays += f.Rays;
  }
  std::partial_sum(far.begin(), far.end(), far.begin());
  std::partial_sum(near.begin(), near.end(), near.begin());
  links.Source.resize(far.back());
  links.Coupling.resize(far.back());
  links.Mixed.resize(far.back());
  links.LeafSource.resize(near.back());
  links.LeafFactor.resize(near.back());
  std::vector<size_t> farAt(far.begin(), far.end() - 1), nearAt(near.begin(), near.end() - 1);
  for (Found& f : found)
  {
    for (size_t i = 0; i < f.Receiver.size(); ++i)
    {
      const size_t at = farAt[f.Receiver[i]]++;
      links.Source[at] = f.Source[i];
      links.Coupling[at] = f.Coupling[i];
      links.Mixed[at] = f.Mixed[i];
    }
    for (size_t i = 0; i < f.LeafReceiver.size(); ++i)
    {
      const size_t at = nearAt[f.LeafReceiver[i]]++;
      links.LeafSource[at] = f.LeafSource[i];
      links.LeafFactor[at] = f.LeafFactor[i];
    }
    f = Found();
  }
}

void ClusterLinkBuilder::SortBySource(
  const WorkerPool& pool, const std::vector<size_t>& farStart, ClusterLinkSet& links)
{
  // Neighbouring receivers gather from neighbouring sources: in one block sorted by source,
  // a source's sums are read once for all its receivers there.
  for (size_t r = 0; r + 1 < farStart.size(); ++r)
  {
    if (farStart[r + 1] > farStart[r])
    {
      links.FarReceivers.push_back(static_cast<int>(r));
    }
  }
  const int blocks = static_cast<int>((links.FarReceivers.size() + ClusterLinkSet::kBlock - 1) / ClusterLinkSet::kBlock);
  links.FarBlockStart.assign(blocks + 1, links.Source.size());
  links.Receiver.resize(links.Source.size());
  for (int b = 0; b < blocks; ++b)
  {
    links.FarBlockStart[b] = farStart[links.FarReceivers[static_cast<size_t>(b) * ClusterLinkSet::kBlock]];
  }
  pool.For(blocks, 1, [&](int begin, int end) {
    std::vector<std::pair<int, int>> order; // (source, place in the block's links before)
    std::vector<float> coupling;
    std::vector<unsigned char> mixed, receiver;
    for (int b = begin; b < end; ++b)
    {
      const size_t first = links.FarBlockStart[b], count = links.FarBlockStart[b + 1] - first;
      receiver.clear();
      const size_t r0 = static_cast<size_t>(b) * ClusterLinkSet::kBlock;
      for (size_t r = r0; r < std::min(links.FarReceivers.size(), r0 + ClusterLinkSet::kBlock); ++r)
      {
        const int node = links.FarReceivers[r];
        receiver.insert(receiver.end(), farStart[node + 1] - farStart[node], static_cast<unsigned char>(r - r0));
      }
      order.resize(count);
      for (size_t i = 0; i < count; ++i)
      {
        order[i] = { links.Source[first + i], static_cast<int>(i) };
      }
      std::sort(order.begin(), order.end()); // ties by place: each receiver's order stays
      coupling.assign(links.Coupling.begin() + first, links.Coupling.begin() + first + count);
      mixed.assign(links.Mixed.begin() + first, links.Mixed.begin() + first + count);
      for (size_t i = 0; i < count; ++i)
      {
        const int from = order[i].second;
        links.Source[first + i] = order[i].first;
        links.Coupling[first + i] = coupling[from];
        links.Mixed[first + i] = mixed[from];
        links.Receiver[first + i] = receiver[from];
      }
    }
  });
  pool.For(static_cast<int>(links.NearStart.size()) - 1, 256, [&](int begin, int end) {
    std::vector<std::pair<int, float>> order;
    for (int r = begin; r < end; ++r)
    {
      const size_t first = links.NearStart[r], count = links.NearStart[r + 1] - first;
      order.resize(count);
      for (size_t i = 0; i < count; ++i)
      {
        order[i] = { links.LeafSource[first + i], links.LeafFactor[first + i] };
      }
      std::sort(order.begin(), order.end());
      for (size_t i = 0; i < count; ++i)
      {
        links.LeafSource[first + i] = order[i].first;
        links.LeafFactor[first + i] = order[i].second;
      }
    }
  });
}

ClusterLinkBuilder::ClusterLinkBuilder(const SceneMesh& mesh, const SceneGeometry& g, const ElementTree& tree,
  const Visibility& rays, const ShooterFormFactors& culling, const ClusterLinkOptions& options)
  : Mesh(mesh)
  , G(g)
  , Tree(tree)
  , Rays(rays)
  , Culling(culling)
  , Options(options)
  , AreaBefore(tree.Elements().size() + 1, 0.0)
  , Epsilon(g.RayLift)
{
  for (size_t i = 0; i < tree.Elements().size(); ++i)
  {
    AreaBefore[i + 1] = AreaBefore[i] + g.Area[tree.Elements()[i]];
  }
  PackSampleData();
}

void ClusterLinkBuilder::PackSampleData()
{
  const std::vector<int>& order = Tree.Elements();
  SampleAt.resize(order.size() + 1, 0);
  for (size_t i = 0; i < order.size(); ++i)
  {
    SampleAt[i + 1] = SampleAt[i] + 7 + 4 * Mesh.PolygonSize(order[i]);
  }
  SampleData.resize(SampleAt.back());
  for (size_t i = 0; i < order.size(); ++i)
  {
    const int e = order[i];
    const int* ids = Mesh.Polygon(e);
    const int count = Mesh.PolygonSize(e);
    const Vec3& c = G.Centroid[e];
    double* r = SampleData.data() + SampleAt[i];
    const double head[6] = { c.x, c.y, c.z, G.Normal[e].x, G.Normal[e].y, G.Normal[e].z };
    std::copy(head, head + 6, r);
    r[6] = 0;
    for (int k = 0; k < count; ++k)
    {
      const Vec3& p = Mesh.Points[ids[k]];
      const double fan = Norm(Cross(p - c, Mesh.Points[ids[(k + 1) % count]] - c));
      const double corner[4] = { fan, p.x, p.y, p.z };
      std::copy(corner, corner + 4, r + 7 + 4 * k);
      r[6] += fan;
    }
  }
}

void ClusterLinkBuilder::DrawNodePoints(const WorkerPool& pool)
{
  const std::vector<ElementTree::Node>& nodes = Tree.Nodes();
  if (!NodePoints.empty() || Options.Samples <= 0 || Culling.BlockingPlanes() == 0)
  {
    return; // drawn already, or no link needs rays (NeedsRays)
  }
  NodePoints.resize(nodes.size() * kNodePoints * 6);
  pool.For(static_cast<int>(nodes.size()), 256, [&](int begin, int end) {
    for (int node = begin; node < end; ++node)
    {
      SampleStream random(static_cast<std::uint64_t>(node), 0, 0xC3u);
      float* out = NodePoints.data() + static_cast<size_t>(node) * kNodePoints * 6;
      for (int j = 0; j < kNodePoints; ++j, out += 6)
      {
        Vec3 normal;
        const Vec3 offset = SamplePoint(node, (j + random.Next()) / kNodePoints, random, normal) - nodes[node].Centre;
        const double values[6] = { offset.x, offset.y, offset.z, normal.x, normal.y, normal.z };
        std::copy(values, values + 6, out);
      }
    }
  });
}

bool ClusterLinkBuilder::NotInFront(int a, int b) const
{
  const ElementTree::Node& A = Tree.Nodes()[a];
  const ElementTree::Node& B = Tree.Nodes()[b];
  if (!A.Flat)
  {
    return BehindBall(A.Centre, A.Radius, A.Cone, B.Centre, B.Radius);
  }
  const bool parallel = B.Flat && std::abs(Dot(A.Cone.Axis, B.Cone.Axis)) > 1 - 1e-9;
  const double highest = Dot(A.Cone.Axis, B.Centre) + (parallel ? 0.0 : B.Radius);
  return highest <= A.PlaneOffset + Tree.Tolerance();
}

bool ClusterLinkBuilder::FacesCentre(int a, int b) const
{
  const ElementTree::Node& A = Tree.Nodes()[a];
  const ElementTree::Node& B = Tree.Nodes()[b];
  if (!A.Flat)
  {
    return FacesBall(A.Centre, A.Radius, A.Cone, B.Centre, 0.0);
  }
  return Dot(A.Cone.Axis, B.Centre) > A.PlaneOffset + Tree.Tolerance();
}

ClusterLinkBuilder::Pair ClusterLinkBuilder::Classify(int a, int b) const
{
  if (NotInFront(a, b) || NotInFront(b, a))
  {
    return Pair::Cull; // one of them faces away from all of the other: nothing passes
  }
  const ElementTree::Node& A = Tree.Nodes()[a];
  const ElementTree::Node& B = Tree.Nodes()[b];
  const double d = Norm(A.Centre - B.Centre);
  const double reach = A.Radius + B.Radius;
  if (d > Options.Separation * reach)
  {
    const bool facesB = FacesCentre(a, b), facesA = FacesCentre(b, a);
    if (facesA && facesB)
    {
      return Pair::Far;
    }
    // A flat node that does not face the other's centre is cut by its plane: split that.
    if ((facesB || !A.Flat) && (facesA || !B.Flat) && d > Options.MixedSeparation * reach)
    {
      return Pair::Far;
    }
  }
  return Tree.IsLeaf(a) && Tree.IsLeaf(b) ? Pair::Near : Pair::Split;
}

ClusterLinkBuilder::Children ClusterLinkBuilder::Split(int a, int b) const
{
  const ElementTree::Node& A = Tree.Nodes()[a];
  const ElementTree::Node& B = Tree.Nodes()[b];
  Children c;
  if (a == b)
  {
    c.Pairs[c.Count++] = { A.Left, A.Left };
    c.Pairs[c.Count++] = { A.Left, A.Right };
    c.Pairs[c.Count++] = { A.Right, A.Right };
  }
  else if (!Tree.IsLeaf(a) && (Tree.IsLeaf(b) || A.Radius >= B.Radius))
  {
    c.Pairs[c.Count++] = { A.Left, b };
    c.Pairs[c.Count++] = { A.Right, b };
  }
  else
  {
    c.Pairs[c.Count++] = { a, B.Left };
    c.Pairs[c.Count++] = { a, B.Right };
  }
  return c;
}

void ClusterLinkBuilder::RefineChildren(int a, int b, Found& found, bool seen) const
{
  const Children c = Split(a, b);
  for (int i = 0; i < c.Count; ++i)
  {
    Refine(c.Pairs[i].A, c.Pairs[i].B, found, seen);
  }
}

void ClusterLinkBuilder::Refine(int a, int b, Found& found, bool seen) const
{
  Pair kind = a == b ? (Tree.IsLeaf(a) ? Pair::Cull : Pair::Split) : Classify(a, b);
  if (kind == Pair::Far)
  {
    AddFar(a, b, found);
  }
  else if (kind == Pair::Near)
  {
    AddNear(a, b, found);
  }
  else if (kind == Pair::Split)
  {
    const Sight sight = seen ? Sight::Seen : Hidden(a, b, found.Rays);
    if (sight != Sight::Hidden)
    {
      RefineChildren(a, b, found, sight == Sight::Seen);
    }
  }
}

void ClusterLinkBuilder::AddFar(int a, int b, Found& found) const
{
  const ElementTree::Node& A = Tree.Nodes()[a];
  const ElementTree::Node& B = Tree.Nodes()[b];
  const Vec3 between = A.Centre - B.Centre;
  const double d2 = Dot(between, between);
  const Vec3 u = between * (1.0 / std::sqrt(d2)); // from b towards a
  const bool mixedA = !FacesCentre(a, b), mixedB = !FacesCentre(b, a);
  const double projectedB = Tree.ProjectedArea(b, u, !mixedB);
  const double projectedA = Tree.ProjectedArea(a, u * -1.0, !mixedA);
  if (projectedA <= 0 || projectedB <= 0)
  {
    return;
  }
  // The point-to-disc correction (pi d^2 + area) keeps a near cluster from sending more
  // than a disc of its projected area could.
  const double fromA = projectedA * projectedB / (A.Area * (Pi * d2 + projectedB));
  const double fromB = projectedA * projectedB / (B.Area * (Pi * d2 + projectedA));
  const double visible = NeedsRays(a, b) ? Visible(a, b, found.Rays, RaysFor(std::max(fromA, fromB))) : 1.0;
  if (visible <= 0)
  {
    return;
  }
  if (visible < 1 && !(Tree.IsLeaf(a) && Tree.IsLeaf(b)) && std::max(fromA, fromB) > Options.PartialFactor)
  {
    RefineChildren(a, b, found, true); // a shadow's edge crosses them: link their parts instead
    return;
  }
  // One coupling both ways keeps reciprocity (A_a F_ab = A_b F_ba), so a uniformly bright
  // closed scene stays uniform.
  const double shared = visible / (Pi * d2 + 0.5 * (projectedA + projectedB));
  if (Tree.IsLeaf(a) && Tree.IsLeaf(b) && !mixedA && !mixedB)
  {
    // Two elements facing each other: the same transport as one number each way, which a
    // bounce applies at a third of a node link's cost.
    const double exchange = shared * projectedA * projectedB;
    AddElementPair(Tree.ElementOf(a), Tree.ElementOf(b), exchange / A.Area, exchange / B.Area, found);
    return;
  }
  const int ends[2][2] = { { a, b }, { b, a } };
  const double coupling[2] = { shared, shared };
  for (int k = 0; k < 2; ++k)
  {
    found.Receiver.push_back(ends[k][0]);
    found.Source.push_back(ends[k][1]);
    found.Coupling.push_back(static_cast<float>(coupling[k]));
    const bool source = k == 0 ? mixedB : mixedA, receiver = k == 0 ? mixedA : mixedB;
    found.Mixed.push_back(static_cast<unsigned char>((source ? 1 : 0) | (receiver ? 2 : 0)));
  }
}

void ClusterLinkBuilder::AddNear(int a, int b, Found& found) const
{
  const int ea = Tree.ElementOf(a), eb = Tree.ElementOf(b);
  // The point rule at either end estimates the same A_a F_ab = A_b F_ba: their mean, made
  // reciprocal, errs less than either (measured against progressive refinement).
  const double exchange = 0.5 * (NearFactor(ea, eb, found) * G.Area[ea] + NearFactor(eb, ea, found) * G.Area[eb]);
  const double fromA = exchange / G.Area[ea], fromB = exchange / G.Area[eb];
  if (exchange <= 0)
  {
    return;
  }
  double visible = NeedsRays(a, b) ? Visible(a, b, found.Rays, RaysFor(std::max(fromA, fromB))) : 1.0;
  if (visible > 0 && visible < 1 && std::max(fromA, fromB) > Options.PartialFactor &&
    Options.Samples <= std::numeric_limits<int>::max() / kPartialSamples)
  {
    // A shadow's edge crosses two elements that exchange much: a few rays misjudge it by
    // a share of that much, so it is judged again, by kPartialSamples times the rays.
    visible = Visible(a, b, found.Rays, kPartialSamples * Options.Samples);
  }
  AddElementPair(ea, eb, fromA * visible, fromB * visible, found);
}

void ClusterLinkBuilder::AddElementPair(int ea, int eb, double fromA, double fromB, Found& found)
{
  const int ends[2][2] = { { ea, eb }, { eb, ea } };
  const double factor[2] = { fromA, fromB };
  for (int k = 0; k < 2; ++k)
  {
    if (factor[k] > 0)
    {
      found.LeafReceiver.push_back(ends[k][0]);
      found.LeafSource.push_back(ends[k][1]);
      found.LeafFactor.push_back(static_cast<float>(factor[k]));
    }
  }
}

double ClusterLinkBuilder::NearFactor(int from, int to, Found& found) const
{
  std::vector<Vec3>& loop = found.Loop;
  std::vector<Vec3>& scratch = found.Scratch;
  loop.clear();
  for (int i = 0; i < Mesh.PolygonSize(to); ++i)
  {
    loop.push_back(Mesh.Points[Mesh.Polygon(to)[i]]);
  }
  const Vec3& n = G.Normal[from];
  const auto value = [&](const Vec3& x) {
    // Only the front of `to` sends; Lambert's formula alone would count its back too.
    return Dot(G.Normal[to], x - G.Centroid[to]) > Tree.Tolerance()
      ? PointToPolygonFormFactor(x, n, loop.data(), static_cast<int>(loop.size()), scratch)
      : 0.0;
  };
  const double reach = Tree.ElementRadius(from) + Tree.ElementRadius(to);
  if (Norm(G.Centroid[from] - G.Centroid[to]) > 2 * reach)
  {
    return value(G.Centroid[from]);
  }
  const double mean = FanAverage(Mesh, G, from, value); // adjacent: the centroid alone misjudges
  return std::isfinite(mean) ? mean : 0.0;
}

int ClusterLinkBuilder::RaysFor(double factor) const
{
  // For a given number of rays, the error of a receiver's sum over its links is least
  // with each link's rays in proportion to its factor; past kFullRaysFactor a link gets
  // them all.
  const double share = std::min(1.0, factor / kFullRaysFactor);
  return std::max(1, static_cast<int>(std::ceil(Options.Samples * share)));
}

bool ClusterLinkBuilder::NeedsRays(int a, int b) const
{
  if (Options.Samples <= 0 || Culling.BlockingPlanes() == 0)
  {
    return false;
  }
  if (Tree.IsLeaf(a) && Tree.IsLeaf(b))
  {
    const int pa = G.ElementPatch[Tree.ElementOf(a)], pb = G.ElementPatch[Tree.ElementOf(b)];
    return Culling.MayBeBlockedBetweenPatches(pa, pb);
  }
  return true;
}

Vec3 ClusterLinkBuilder::SamplePoint(int node, double u, SampleStream& random, Vec3& normal) const
{
  const ElementTree::Node& n = Tree.Nodes()[node];
  int i = n.First;
  if (n.Count > 1)
  {
    const double target = AreaBefore[n.First] + u * n.Area;
    i = static_cast<int>(
      std::upper_bound(AreaBefore.begin() + n.First, AreaBefore.begin() + n.First + n.Count, target) -
      AreaBefore.begin()) - 1;
    i = std::max(n.First, std::min(n.First + n.Count - 1, i));
  }
  const double* r = SampleData.data() + SampleAt[i];
  const int count = static_cast<int>((SampleAt[i + 1] - SampleAt[i] - 7) / 4);
  const Vec3 c{ r[0], r[1], r[2] };
  normal = Vec3{ r[3], r[4], r[5] };
  // A point uniform over the element's fan triangles around its centroid.
  double pick = random.Next() * r[6];
  int k = 0;
  for (; k < count - 1; ++k)
  {
    pick -= r[7 + 4 * k];
    if (pick < 0)
    {
      break;
    }
  }
  const double* p = r + 8 + 4 * k;
  const double* q = r + 8 + 4 * ((k + 1) % count);
  const double s = random.Next(), t = random.Next();
  return TrianglePoint(c, Vec3{ p[0], p[1], p[2] }, Vec3{ q[0], q[1], q[2] }, s, t) + normal * Epsilon;
}

ClusterLinkBuilder::Sight ClusterLinkBuilder::Hidden(int a, int b, long long& rays) const
{
  const ElementTree::Node& A = Tree.Nodes()[a];
  const ElementTree::Node& B = Tree.Nodes()[b];
  if (a == b || !NeedsRays(a, b) || Norm(A.Centre - B.Centre) <= kHiddenRadii * (A.Radius + B.Radius))
  {
    return Sight::Unknown; // near: the nodes' own surfaces would hide too much of a pair partly in view
  }
  SampleStream random(static_cast<std::uint64_t>(a), static_cast<std::uint64_t>(b), 0xC2u);
  int valid = 0;
  for (int r = 0; r < kHiddenRays; ++r)
  {
    Vec3 na, nb;
    const Vec3 pa = NodePoint(a, Stratum(r, kHiddenRays, random), na);
    const Vec3 pb = NodePoint(b, Stratum(0, 1, random), nb);
    if (Dot(na, pb - pa) <= 0 || Dot(nb, pa - pb) <= 0)
    {
      continue;
    }
    ++valid;
    ++rays;
    if (!Rays.Occluded(pa, pb))
    {
      return Sight::Seen; // the first ray through settles it, for the pair's parts too
    }
  }
  // No two points facing each other: too little passes between them to test again below.
  return valid > 0 ? Sight::Hidden : Sight::Seen;
}

double ClusterLinkBuilder::Visible(int a, int b, long long& rays, int samples) const
{
  SampleStream random(static_cast<std::uint64_t>(a), static_cast<std::uint64_t>(b), 0xC1u);
  int valid = 0, open = 0;
  // Both ends stratified over their node's points, stratum r of one joined to stratum
  // r + shift of the other: each part of either node sends one ray. Past kNodePoints rays
  // the strata are single points, so the far ends are drawn from all of them instead.
  const bool paired = samples <= kNodePoints;
  const int shift = static_cast<int>(random.Next() * samples);
  // Nodes that face each other only in part (a cluster's faces turned every way) waste
  // draws on points that do not. Short of `samples` points that face each other, more
  // are drawn, at random; where none of them does either, the two exchange next to
  // nothing, and passing them as fully visible was how light leaked through what stands
  // between them.
  const long long draws = samples + std::max(static_cast<long long>(kExtraDraws) * samples, 1LL * kNodePoints);
  for (long long r = 0; r < samples || (valid < samples && r < draws); ++r)
  {
    const bool stratified = r < samples;
    Vec3 na, nb;
    const int ra = static_cast<int>(r);
    const Vec3 pa = NodePoint(a, stratified ? Stratum(ra, samples, random) : Stratum(0, 1, random), na);
    const Vec3 pb = NodePoint(b,
      stratified && paired ? Stratum((ra + shift) % samples, samples, random) : Stratum(0, 1, random), nb);
    if (Dot(na, pb - pa) <= 0 || Dot(nb, pa - pb) <= 0)
    {
      continue; // these two points do not exchange light: no ray speaks for the pair
    }
    ++valid;
    ++rays;
    open += Rays.Occluded(pa, pb) ? 0 : 1;
  }
  return valid > 0 ? static_cast<double>(open) / valid : 0.0;
}

std::vector<ClusterLinkBuilder::Task> ClusterLinkBuilder::Frontier(int wanted) const
{
  std::vector<Task> list;
  if (!Tree.Nodes().empty())
  {
    list.push_back({ 0, 0 });
  }
  bool split = true;
  while (split && static_cast<int>(list.size()) < wanted)
  {
    split = false;
    std::vector<Task> next;
    for (const Task& t : list)
    {
      const Pair kind = t.A == t.B ? (Tree.IsLeaf(t.A) ? Pair::Cull : Pair::Split) : Classify(t.A, t.B);
      if (kind == Pair::Split)
      {
        const Children c = Split(t.A, t.B);
        next.insert(next.end(), c.Pairs, c.Pairs + c.Count);
        split = true;
      }
      else if (kind != Pair::Cull)
      {
        next.push_back(t);
      }
    }
    list.swap(next);
  }
  return list;
}

ClusterLinkSet ClusterLinkBuilder::Build(
  const WorkerPool& pool, int rank, int ranks, const std::function<bool(double, double)>& keepGoing)
{
  DrawNodePoints(pool);
  const std::vector<Task> tasks = Frontier(4096);
  std::vector<Found> found(tasks.size());
  ClusterLinkSet links;
  const int batch = std::max(1, static_cast<int>(tasks.size()) / 50);
  double held = 0; // far links count 13 bytes here, near ones 12
  for (int begin = 0; begin < static_cast<int>(tasks.size()); begin += batch)
  {
    for (int i = std::max(0, begin - batch); i < begin; ++i)
    {
      // Capacity, not size: a list grown by doubling holds up to twice what it has found.
      held += kFoundBytes * found[i].Receiver.capacity() + 12.0 * found[i].LeafReceiver.capacity();
    }
    if (keepGoing && !keepGoing(static_cast<double>(begin) / tasks.size(), held))
    {
      links.Complete = false;
      break;
    }
    const int end = std::min(static_cast<int>(tasks.size()), begin + batch);
    pool.For(end - begin, 1, [&](int first, int last) {
      for (int i = begin + first; i < begin + last; ++i)
      {
        if (i % ranks == rank)
        {
          Refine(tasks[i].A, tasks[i].B, found[i], false);
        }
      }
    });
  }
  std::vector<size_t> farStart;
  SortByReceiver(found, links, farStart);
  SortBySource(pool, farStart, links);
  return links;
}

} // namespace radiosity
