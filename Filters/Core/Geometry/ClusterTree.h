// Form factors to a cluster of many small polygons (a tessellated curved surface) at a cost
// that grows with the log of its polygons: a bounding-sphere tree whose far nodes act as
// one oriented area (Barnes & Hut's far field, applied to Lambert emitters).
#ifndef RadiosityCore_ClusterTree_h
#define RadiosityCore_ClusterTree_h

#include "Geometry/Scene.h"

#include <cmath>
#include <vector>

namespace radiosity
{

/// The spread of a set of unit normals: the cone around `Axis` that holds them all.
struct NormalCone
{
  Vec3 Axis;         ///< unit; zero where the normals cancel
  double Spread = 0; ///< half-angle in radians (Pi: no cone)
  double CosSpread = 1, SinSpread = 0; ///< of Spread: the ball tests run without trigonometry

  NormalCone() = default;
  NormalCone(const Vec3& axis, double spread)
    : Axis(axis)
    , Spread(spread)
    , CosSpread(std::cos(spread))
    , SinSpread(std::sin(spread))
  {
  }
};

/// True when every point of the ball (centre `c`, radius `r`) lies strictly in front of
/// the plane of every polygon of a set in the ball (`centre`, `radius`) with normals in
/// `cone`: then the set's front faces all of it, and cosines at both ends stay positive.
bool FacesBall(const Vec3& centre, double radius, const NormalCone& cone, const Vec3& c, double r);
/// True when every point of the ball lies strictly behind every such plane.
bool BehindBall(const Vec3& centre, double radius, const NormalCone& cone, const Vec3& c, double r);

class ClusterTree
{
public:
  /// A tree over `elements` (polygons of `mesh`), leaves of a few polygons; `loops` holds
  /// the mesh's points laid out like its connectivity (kept by reference).
  ClusterTree(
    const SceneMesh& mesh, const SceneGeometry& g, const std::vector<Vec3>& loops, const std::vector<int>& elements);

  /// Unoccluded F(dA at x with unit `normal` -> the polygons); only their fronts emit.
  double PointFactor(const Vec3& x, const Vec3& normal, std::vector<Vec3>& scratch) const;
  /// The vector V with F(dA at x with normal n -> the polygons) = n . V for every n whose
  /// front half-space holds all of them (the irradiance vector of a unit radiosity / pi).
  Vec3 FactorVector(const Vec3& x) const;

  const NormalCone& Cone() const { return Nodes.front().Cone; }

  /// FactorVector at the centre `c` of a receiver (a ball of radius `r` whose polygons'
  /// normals lie in `cone`) such that n . v is each receiving polygon's factor and holds
  /// across the ball: the polygons behind all the receiver's planes are left out, those cut
  /// by them clipped by the receiver's mean plane where it is nearly flat, and it fails
  /// (returns false) where a receiver of wider normals cuts a leaf or a part nearer than
  /// `clearance` x r contributes.
  bool FactorVectorFor(const Vec3& c, double r, const NormalCone& cone, double clearance, Vec3& v) const;

  /// A node is far from x beyond this many of its radii: the error of the far field falls
  /// as the square of radius / distance (under 1 % for one node at 6 radii, less summed).
  static constexpr double kFarRadii = 6.0;
  /// A receiver whose normals spread less than this (radians, 10 degrees) is clipped by its
  /// mean plane alone, where one of its planes cuts a leaf (FactorVectorFor).
  static constexpr double kFlatReceiver = 10.0 * 3.14159265358979323846 / 180.0;

  struct Node
  {
    Vec3 Centre;     ///< area-weighted centroid
    Vec3 AreaVector; ///< sum of area x unit normal
    /// Sum of area x normal . (centroid - Centre): with it the projected area towards x,
    /// sum A n . (x - c_e), is exact, not only to first order (a curved cap's rim turns
    /// away from a point above it: 4 % too much at ten radii without it).
    double Moment = 0;
    /// Sums of area x offset x normal (a matrix, by rows) and of area x normal . offset x
    /// offset, offsets from Centre: with them the far field is taken at the centroid of
    /// what each polygon sends towards x, not at the node's centre, which a cap seen edge-on
    /// weights unevenly (3.8 % low at five radii without).
    Vec3 Spread[3];
    Vec3 OffsetMoment;
    NormalCone Cone;
    double Radius = 0;
    int First = 0, Count = 0; ///< range in Order
    int Left = -1, Right = -1;
  };
  /// The nodes, the root first, children after their parent; each holds Order's range.
  const std::vector<Node>& AllNodes() const { return Nodes; }
  /// The elements in tree order.
  const std::vector<int>& Elements() const { return Order; }

private:
  int Build(int first, int count);
  void Summarise(Node& node) const;
  /// The far field of a node at x: returns sum A n . (x - c) / (pi |d|^4), with `d` from x
  /// to the centroid of those weights, so that F = normal . d times it.
  static double FarField(const Node& node, const Vec3& x, Vec3& d);
  double NodeFactor(int node, const Vec3& x, const Vec3& normal, std::vector<Vec3>& scratch) const;
  void NodeVector(int node, const Vec3& x, Vec3& sum) const;
  bool NodeVectorFor(int node, const Vec3& c, double r, const NormalCone& cone, double clearance, Vec3& sum) const;

  const SceneMesh& Mesh;
  const SceneGeometry& G;
  const std::vector<Vec3>& Loops;
  std::vector<int> Order;
  std::vector<Node> Nodes;
};

/// The cone of the normals of `elements`.
NormalCone ConeOf(const SceneGeometry& g, const std::vector<int>& elements);

/// The irradiance-vector form of Lambert's formula for one planar polygon: V with
/// F(dA at x with normal n -> polygon) = n . V wherever the polygon is wholly in front of
/// the receiver's plane. Oriented towards the polygon.
Vec3 PolygonFactorVector(const Vec3& x, const Vec3* loop, int count);

} // namespace radiosity

#endif
