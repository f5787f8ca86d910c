// The links of the clustered method: which groups of elements exchange light directly,
// found once for the scene and for every light (a light-independent oracle), so that the
// transport is computed once and carries all k solutions.
#ifndef RadiosityCore_ClusterLinks_h
#define RadiosityCore_ClusterLinks_h

#include "Solve/ElementTree.h"
#include "Solve/ShooterFormFactors.h"
#include "Base/WorkerPool.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace radiosity
{

/// Directed links, each "receiver gathers from source", grouped by receiver: 10 bytes a far
/// link and 8 a near one (the direction between two nodes is their centres').
struct ClusterLinkSet
{
  /// Far links between tree nodes in full or partial view: the receiver's irradiance vector
  /// gains Coupling x (M_source . u) x (-u), where M is the sum of radiosity x area x normal
  /// over the source's elements and u the unit vector from the source's centre to the
  /// receiver's (FarDirection). They come in blocks of up to kBlock receivers (those with
  /// far links, in tree order: FarReceivers), block b's links at [FarBlockStart[b],
  /// FarBlockStart[b + 1]) in the order of their sources, each naming its receiver by its
  /// place in the block (Receiver): a bounce reads a source's sums once per block, not once
  /// per link (a fifth as often on the FZK-Haus), and each receiver still sums its links in
  /// the order of their sources.
  static constexpr int kBlock = 256;
  std::vector<int> FarReceivers;
  std::vector<size_t> FarBlockStart;
  std::vector<unsigned char> Receiver;
  std::vector<int> Source;
  std::vector<float> Coupling;
  /// Per link: 1 where the source's elements do not all face the receiver (its emission
  /// towards u is taken from the clamped cosine's series), 2 where the receiver's do not
  /// (each element's share likewise), 3 for both.
  std::vector<unsigned char> Mixed;
  /// Links between two elements, element e's at [NearStart[e], NearStart[e + 1]):
  /// irradiance += Factor x the source's radiosity, with Factor = F(receiver -> source) by
  /// Lambert's formula and shadow rays (near), or a far link's coupling between two
  /// elements facing each other. Each receiver's links in the order of their sources.
  std::vector<size_t> NearStart;
  std::vector<int> LeafSource;
  std::vector<float> LeafFactor;
  long long Rays = 0;
  bool Complete = true; ///< false where the build was stopped (abort or time)

  size_t FarCount() const { return Source.size(); }
  size_t NearCount() const { return LeafSource.size(); }
  double Bytes() const
  {
    return 10.0 * FarCount() + 8.0 * NearCount() + sizeof(int) * FarReceivers.size() +
      sizeof(size_t) * (FarBlockStart.size() + NearStart.size());
  }
};

/// The unit vector from `source`'s centre to `receiver`'s, as a far link between the two
/// nodes uses it (in float, as the links once stored it).
inline void FarDirection(const Vec3& receiver, const Vec3& source, float* u)
{
  const Vec3 between = receiver - source;
  const Vec3 unit = between * (1.0 / std::sqrt(Dot(between, between)));
  u[0] = static_cast<float>(unit.x);
  u[1] = static_cast<float>(unit.y);
  u[2] = static_cast<float>(unit.z);
}

/// How fine the links are: a pair of nodes is linked whole when their centres are
/// farther apart than Separation x the sum of their radii and each faces the other's centre.
/// The clustered method sets both from ClusteredSettings::Separation, where the default lives.
struct ClusterLinkOptions
{
  double Separation = 0;
  /// The same for a pair where one side's elements do not all face the other (a corner, a
  /// curved object's rim): farther, as the series errs by up to 1/16 of head-on.
  double MixedSeparation = 0;
  int Samples = 4;     ///< shadow rays per link (0: none)
  /// A partly hidden pair of nodes whose form factor either way exceeds this is split.
  double PartialFactor = 0.01;
};

class ClusterLinkBuilder
{
public:
  ClusterLinkBuilder(const SceneMesh& mesh, const SceneGeometry& g, const ElementTree& tree,
    const Visibility& rays, const ShooterFormFactors& culling, const ClusterLinkOptions& options);

  /// The links of this rank's share of the pairs (every `ranks`-th task); `keepGoing` is
  /// asked between batches of tasks with the fraction of tasks done and the bytes the links
  /// found so far hold, and false stops the build.
  ClusterLinkSet Build(
    const WorkerPool& pool, int rank, int ranks, const std::function<bool(double, double)>& keepGoing);
  /// Bytes a link takes while the build holds it, and once sorted (ClusterLinkSet).
  static constexpr double kFoundBytes = 13.0, kSortedBytes = 10.0;
  /// Bytes the ray ends drawn for `tree`'s nodes take while the build runs (NodePoints).
  static double PointBytes(const ElementTree& tree)
  {
    return static_cast<double>(tree.Nodes().size()) * kNodePoints * 6 * sizeof(float);
  }

private:
  enum class Pair
  {
    Cull,
    Far,
    Near,
    Split
  };
  struct Task
  {
    int A, B;
  };
  struct Children
  {
    Task Pairs[3];
    int Count = 0;
  };
  struct Found; // one task's links
  Pair Classify(int a, int b) const;
  /// Every task's links into `links`, sorted by receiver (far ones: `farStart` says where
  /// each node's are), in the order the tasks found them.
  void SortByReceiver(std::vector<Found>& found, ClusterLinkSet& links, std::vector<size_t>& farStart) const;
  /// The far links into blocks of receivers, each block's in the order of their sources;
  /// each receiver's near links in the order of their sources.
  static void SortBySource(const WorkerPool& pool, const std::vector<size_t>& farStart, ClusterLinkSet& links);
  std::vector<Task> Frontier(int wanted) const;
  /// The pairs a pair splits into: both halves of a node paired with itself, else the
  /// halves of the larger node with the other.
  Children Split(int a, int b) const;
  /// `seen`: a ray joined an ancestor pair, so the pair is not tested for being hidden.
  void RefineChildren(int a, int b, Found& found, bool seen) const;
  void Refine(int a, int b, Found& found, bool seen) const;
  void AddFar(int a, int b, Found& found) const;
  void AddNear(int a, int b, Found& found) const;
  /// Element a gathers fromA x b's radiosity, b fromB x a's (a near link each way).
  static void AddElementPair(int ea, int eb, double fromA, double fromB, Found& found);
  /// True when no point of node b lies in front of node a's elements' planes.
  bool NotInFront(int a, int b) const;
  /// True when node b's centre lies in front of every plane of a's elements: then a
  /// gathers from b as from a point, with a positive cosine at each of its elements.
  bool FacesCentre(int a, int b) const;
  double NearFactor(int from, int to, Found& found) const;
  /// Fraction of `samples` shadow rays between the nodes that arrive (only rays from the
  /// front of one to the front of the other count); 1 without rays.
  double Visible(int a, int b, long long& rays, int samples) const;
  enum class Sight
  {
    Unknown, ///< near, or no rays needed
    Seen,    ///< a ray between facing points arrived (or no two sampled points face)
    Hidden   ///< far apart, and none of the rays between facing points arrived
  };
  Sight Hidden(int a, int b, long long& rays) const;
  /// A point of node `node` (uniform by area, `u` choosing where), just off its front.
  Vec3 SamplePoint(int node, double u, SampleStream& random, Vec3& normal) const;
  /// Point j of node `node`'s kNodePoints (DrawNodePoints), with its element's normal.
  Vec3 NodePoint(int node, int j, Vec3& normal) const
  {
    const float* p = NodePoints.data() + (static_cast<size_t>(node) * kNodePoints + j) * 6;
    const Vec3& c = Tree.Nodes()[node].Centre;
    normal = Vec3{ p[3], p[4], p[5] };
    return Vec3{ c.x + p[0], c.y + p[1], c.z + p[2] };
  }
  /// Index of one of the node points in stratum r of `strata` (all of them where strata
  /// outnumber the points: each point then serves several).
  static int Stratum(int r, int strata, SampleStream& random)
  {
    const long long n = kNodePoints;
    const int low = static_cast<int>(r * n / strata), high = std::max(low + 1, static_cast<int>((r + 1) * n / strata));
    return std::min(high - 1, low + static_cast<int>(random.Next() * (high - low)));
  }
  bool NeedsRays(int a, int b) const;
  int RaysFor(double factor) const;

  const SceneMesh& Mesh;
  const SceneGeometry& G;
  const ElementTree& Tree;
  const Visibility& Rays;
  const ShooterFormFactors& Culling;
  const ClusterLinkOptions Options;
  std::vector<double> AreaBefore; ///< prefix sums of area in tree order
  double Epsilon = 0;
  /// What SamplePoint reads of each element, in tree order and in one place: at
  /// SampleAt[i], the centroid, the normal, the sum of the fan triangles' doubled areas,
  /// then per corner that corner's fan triangle's doubled area and the corner.
  std::vector<double> SampleData;
  std::vector<size_t> SampleAt;
  void PackSampleData();
  /// The ray ends of the shadow rays between nodes: per node, kNodePoints points uniform by
  /// area (stratified, each just off its element's front) as float offsets from the node's
  /// centre, each with its element's normal (384 bytes a node, about 770 an element). Drawn
  /// once, kNodePoints per node, where rays are needed at all, instead of once per ray end
  /// (hundreds of millions on the FZK-Haus, each a cache miss or two into SampleData), and a
  /// node's points lie together.
  static constexpr int kNodePoints = 16;
  std::vector<float> NodePoints;
  void DrawNodePoints(const WorkerPool& pool);
};

} // namespace radiosity

#endif
