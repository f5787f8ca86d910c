// A bounding-ball tree over every element that can send or receive light: the clusters of
// the clustered method, whose links join groups of elements of any size and orientation
// (volume clusters, Smits, Arvo & Greenberg 1994; Sillion 1995).
#ifndef RadiosityCore_ElementTree_h
#define RadiosityCore_ElementTree_h

#include "Geometry/ClusterTree.h"
#include "Geometry/Scene.h"

#include <vector>

namespace radiosity
{

/// The second-order expansion of max(0, t) in Legendre polynomials: 1/4 + t/2 +
/// (5/32)(3t^2 - 1). Exact in the mean over a sphere of normals; for one plane it errs by at
/// most 1/16 of head-on.
inline double ClampedCosineSeries(double area, double along, double quadratic)
{
  return 0.25 * area + 0.5 * along + (5.0 / 32.0) * (3.0 * quadratic - area);
}

/// u^T M u for a symmetric matrix stored as (xx, xy, xz, yy, yz, zz).
inline double Quadratic(const double* m, const Vec3& u)
{
  return m[0] * u.x * u.x + m[3] * u.y * u.y + m[5] * u.z * u.z + 2 * (m[1] * u.x * u.y + m[2] * u.x * u.z + m[4] * u.y * u.z);
}

class ElementTree
{
public:
  struct Node
  {
    Vec3 Centre;       ///< area-weighted centroid
    double Radius = 0; ///< the ball around Centre holds every corner of the node's elements
    NormalCone Cone;   ///< of their normals
    double Area = 0;
    Vec3 AreaVector; ///< sum of area x unit normal
    /// Sum of area x n n^T (xx, xy, xz, yy, yz, zz): with Area and AreaVector, the clamped
    /// cosine's expansion to second order (ProjectedArea).
    double NormalMoment[6] = { 0, 0, 0, 0, 0, 0 };
    /// All elements lie in the plane Cone.Axis . x = PlaneOffset (to a tolerance of the
    /// scene's size): then a node's front half-space is exact, not a ball's bound.
    bool Flat = false;
    double PlaneOffset = 0;
    int First = 0, Count = 0; ///< range in Elements()
    int Left = -1, Right = -1;
  };

  /// Every element not enclosed (SceneGeometry::Enclosed), one per leaf.
  ElementTree(const SceneMesh& mesh, const SceneGeometry& g);

  /// The root first, each parent before its children.
  const std::vector<Node>& Nodes() const { return All; }
  /// Elements in tree order: node n holds Elements()[First, First + Count).
  const std::vector<int>& Elements() const { return Order; }
  /// The leaf of element e; -1 for an enclosed element.
  int LeafOf(int e) const { return Leaf[e]; }
  bool IsLeaf(int n) const { return All[n].Left < 0; }
  /// Node n's subtree is the nodes [n, SubtreeEnd(n)): each parent precedes its children.
  int SubtreeEnd(int n) const { return n + 2 * All[n].Count - 1; }
  /// The element of leaf n.
  int ElementOf(int n) const { return Order[All[n].First]; }
  /// Largest distance from element e's centroid to one of its corners.
  double ElementRadius(int e) const { return Reach[e]; }
  /// Sum of area x max(0, n . u) over node n's elements: AreaVector . u exactly where
  /// `facing` (every element faces u), else the clamped cosine's series.
  double ProjectedArea(int n, const Vec3& u, bool facing) const
  {
    const Node& node = All[n];
    const double along = Dot(node.AreaVector, u);
    return facing ? along : ClampedCosineSeries(node.Area, along, Quadratic(node.NormalMoment, u));
  }
  /// Distances below this are the same point: planes and coincidences are judged to it.
  double Tolerance() const { return Tol; }

private:
  int Build(int first, int count);
  void Summarise(Node& node) const;
  /// Positions along the line between the node's two elements farthest apart, quantized:
  /// splits at their median make the same tree however the scene is turned or placed.
  std::vector<long long> SplitKeys(int first, int count) const;
  /// A node whose surfaces face apart (both sides of a wall, a box's faces) splits into
  /// the elements facing one way and those facing the other, where each side then faces
  /// within a right angle of its mean: volume clusters mixing both sides of a wall see
  /// each other's rooms and must be linked from farther (fewer links and less error on the
  /// FZK-Haus, docs/benchmarks.md). `mean`: the node's unit
  /// mean normal. Returns false, leaving the order, where it does not split; else `left` is
  /// the first side's size.
  bool SplitByFacing(int first, int count, const Vec3& mean, int& left);
  Vec3 MeanNormal(std::vector<int>::const_iterator begin, std::vector<int>::const_iterator end) const;
  /// The element of [first, first + count) whose normal is least like `direction` (ties by
  /// element, judged to a quantum, so the choice turns with the scene).
  int LeastAlike(int first, int count, const Vec3& direction) const;
  bool Coherent(std::vector<int>::const_iterator begin, std::vector<int>::const_iterator end) const;
  /// Nodes whose normals spread wider than a right angle are split by facing where they
  /// can be; each side must then face within a right angle of its mean. Both are judged a
  /// little past the right angle, so that a node at exactly one (a floor between two facing
  /// walls) is judged alike however the scene is turned.
  static constexpr double kBackToBack = 0.5 * Pi + 1e-6, kFacing = -1e-6;

  const SceneGeometry& G;
  std::vector<int> Order, Leaf;
  std::vector<double> Reach;
  std::vector<Node> All;
  double Quantum = 1, Tol = 0;
};

} // namespace radiosity

#endif
