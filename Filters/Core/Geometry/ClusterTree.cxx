#include "Geometry/ClusterTree.h"
#include "Geometry/FormFactor.h"
#include "Geometry/Polygon.h"

#include <algorithm>
#include <cmath>

namespace radiosity
{

namespace
{
constexpr int kLeafSize = 4;
} // namespace

bool FacesBall(const Vec3& centre, double radius, const NormalCone& cone, const Vec3& c, double r)
{
  const Vec3 d = c - centre;
  const double along = Dot(cone.Axis, d); // length x cos(phi)
  if (cone.Spread >= 0.5 * Pi || along <= r + radius)
  {
    return false; // also where the axis is zero (normals cancel)
  }
  // Every normal is within Spread of the axis, so its angle to d is at most phi + Spread:
  // length x cos(phi + Spread) bounds n . d.
  const double across = std::sqrt(std::max(0.0, Dot(d, d) - along * along)); // length x sin(phi)
  return along * cone.CosSpread - across * cone.SinSpread > r + radius;
}

bool BehindBall(const Vec3& centre, double radius, const NormalCone& cone, const Vec3& c, double r)
{
  const Vec3 d = c - centre;
  const double along = Dot(cone.Axis, d); // length x cos(phi)
  if (cone.Spread >= 0.5 * Pi || along >= -(r + radius))
  {
    return false; // the bound below is at least along: it cannot be behind (or no axis)
  }
  // The normal nearest d is at phi - Spread from it: length x cos(phi - Spread) bounds n . d
  // from above (phi > Spread here, as along < 0).
  const double across = std::sqrt(std::max(0.0, Dot(d, d) - along * along));
  return along * cone.CosSpread + across * cone.SinSpread < -(r + radius);
}

NormalCone ConeOf(const SceneGeometry& g, const std::vector<int>& elements)
{
  Vec3 sum;
  for (int e : elements)
  {
    sum += g.Normal[e] * g.Area[e];
  }
  const Vec3 axis = Normalized(sum);
  if (Norm(axis) == 0)
  {
    return NormalCone(axis, Pi);
  }
  double spread = 0;
  for (int e : elements)
  {
    spread = std::max(spread, std::acos(std::max(-1.0, std::min(1.0, Dot(axis, g.Normal[e])))));
  }
  return NormalCone(axis, spread);
}

Vec3 PolygonFactorVector(const Vec3& x, const Vec3* loop, int count)
{
  Vec3 sum, centre;
  for (int i = 0; i < count; ++i)
  {
    const Vec3 a = loop[i] - x, b = loop[(i + 1) % count] - x;
    const Vec3 c = Cross(a, b);
    const double cn = Norm(c);
    centre += a;
    if (cn > 1e-300)
    {
      sum += c * (std::atan2(cn, Dot(a, b)) / cn);
    }
  }
  sum = sum * (1.0 / (2.0 * Pi));
  return Dot(sum, centre) < 0 ? sum * -1.0 : sum;
}

ClusterTree::ClusterTree(
  const SceneMesh& mesh, const SceneGeometry& g, const std::vector<Vec3>& loops, const std::vector<int>& elements)
  : Mesh(mesh)
  , G(g)
  , Loops(loops)
  , Order(elements)
{
  Nodes.reserve(2 * elements.size() / kLeafSize + 2);
  Build(0, static_cast<int>(elements.size()));
}

int ClusterTree::Build(int first, int count)
{
  const int index = static_cast<int>(Nodes.size());
  Nodes.emplace_back();
  Nodes[index].First = first;
  Nodes[index].Count = count;
  Summarise(Nodes[index]);
  if (count <= kLeafSize)
  {
    return index;
  }
  // Median split of the centroids along their longest extent.
  Vec3 lo = G.Centroid[Order[first]], hi = lo;
  for (int i = first; i < first + count; ++i)
  {
    const Vec3& c = G.Centroid[Order[i]];
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], c[k]);
      hi[k] = std::max(hi[k], c[k]);
    }
  }
  const Vec3 extent = hi - lo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  const auto begin = Order.begin() + first;
  const int half = count / 2;
  std::nth_element(begin, begin + half, begin + count, [&](int a, int b) {
    return G.Centroid[a][axis] < G.Centroid[b][axis] || (G.Centroid[a][axis] == G.Centroid[b][axis] && a < b);
  });
  const int left = Build(first, half);
  const int right = Build(first + half, count - half);
  Nodes[index].Left = left;
  Nodes[index].Right = right;
  return index;
}

void ClusterTree::Summarise(Node& node) const
{
  double area = 0;
  std::vector<int> members(Order.begin() + node.First, Order.begin() + node.First + node.Count);
  for (int e : members)
  {
    node.Centre += G.Centroid[e] * G.Area[e];
    node.AreaVector += G.Normal[e] * G.Area[e];
    area += G.Area[e];
  }
  node.Centre = area > 0 ? node.Centre * (1.0 / area) : G.Centroid[members.front()];
  for (int e : members)
  {
    for (int v = 0; v < Mesh.PolygonSize(e); ++v)
    {
      node.Radius = std::max(node.Radius, Norm(Mesh.Points[Mesh.Polygon(e)[v]] - node.Centre));
    }
  }
  node.Cone = ConeOf(G, members);
  for (int e : members)
  {
    const Vec3 offset = G.Centroid[e] - node.Centre;
    const double along = G.Area[e] * Dot(G.Normal[e], offset);
    node.Moment += along;
    node.OffsetMoment += offset * along;
    for (int row = 0; row < 3; ++row)
    {
      node.Spread[row] += G.Normal[e] * (G.Area[e] * offset[row]);
    }
  }
}

double ClusterTree::FarField(const Node& node, const Vec3& x, Vec3& d)
{
  // The weights w_e = A_e n_e . (x - c_e) and their centroid, from the node's moments.
  const Vec3 r = x - node.Centre;
  const double weight = Dot(node.AreaVector, r) - node.Moment;
  if (!(weight > 0))
  {
    d = Vec3();
    return 0;
  }
  const Vec3 shift = Vec3{ Dot(node.Spread[0], r), Dot(node.Spread[1], r), Dot(node.Spread[2], r) } - node.OffsetMoment;
  d = node.Centre + shift * (1.0 / weight) - x;
  const double distance2 = Dot(d, d);
  return weight / (Pi * distance2 * distance2);
}

double ClusterTree::PointFactor(const Vec3& x, const Vec3& normal, std::vector<Vec3>& scratch) const
{
  return NodeFactor(0, x, normal, scratch);
}

double ClusterTree::NodeFactor(int index, const Vec3& x, const Vec3& normal, std::vector<Vec3>& scratch) const
{
  const Node& node = Nodes[index];
  const Vec3 d = node.Centre - x;
  const double toPlane = Dot(normal, d);
  if (toPlane <= -node.Radius || BehindBall(node.Centre, node.Radius, node.Cone, x, 0.0))
  {
    return 0; // behind the receiver, or facing away from it: nothing arrives
  }
  const double distance = Norm(d);
  if (node.Left >= 0 && distance > kFarRadii * node.Radius && toPlane > node.Radius &&
    FacesBall(node.Centre, node.Radius, node.Cone, x, 0.0))
  {
    // Far, wholly in front, facing x: cos at x times the projected area, over pi r^2.
    Vec3 towards;
    const double w = FarField(node, x, towards);
    return Dot(normal, towards) * w;
  }
  if (node.Left >= 0)
  {
    return NodeFactor(node.Left, x, normal, scratch) + NodeFactor(node.Right, x, normal, scratch);
  }
  double f = 0;
  for (int i = node.First; i < node.First + node.Count; ++i)
  {
    const int e = Order[i];
    if (Dot(G.Normal[e], x - G.Centroid[e]) > 0)
    {
      f += PointToPolygonFormFactor(x, normal, Loops.data() + Mesh.Offsets[e], Mesh.PolygonSize(e), scratch);
    }
  }
  return f;
}

Vec3 ClusterTree::FactorVector(const Vec3& x) const
{
  Vec3 sum;
  NodeVector(0, x, sum);
  return sum;
}

bool ClusterTree::FactorVectorFor(const Vec3& c, double r, const NormalCone& cone, double clearance, Vec3& v) const
{
  v = Vec3();
  return NodeVectorFor(0, c, r, cone, clearance, v);
}

bool ClusterTree::NodeVectorFor(
  int index, const Vec3& c, double r, const NormalCone& cone, double clearance, Vec3& sum) const
{
  const Node& node = Nodes[index];
  if (BehindBall(node.Centre, node.Radius, node.Cone, c, r) || BehindBall(c, r, cone, node.Centre, node.Radius))
  {
    return true; // faces away from the whole receiver, or behind all its planes: nothing
  }
  if (FacesBall(c, r, cone, node.Centre, node.Radius) && Norm(node.Centre - c) - node.Radius >= clearance * r)
  {
    NodeVector(index, c, sum);
    return true;
  }
  if (node.Left >= 0)
  {
    return NodeVectorFor(node.Left, c, r, cone, clearance, sum) && NodeVectorFor(node.Right, c, r, cone, clearance, sum);
  }
  if (cone.Spread > kFlatReceiver || Norm(node.Centre - c) - node.Radius < clearance * r)
  {
    return false;
  }
  // A leaf cut by a nearly flat receiver's planes: each polygon clipped to the front of the
  // receiver's mean plane, which stands for all of them.
  std::vector<Vec3> clipped;
  for (int i = node.First; i < node.First + node.Count; ++i)
  {
    const int e = Order[i];
    if (Dot(G.Normal[e], c - G.Centroid[e]) <= 0)
    {
      continue;
    }
    ClipToHalfSpace(Loops.data() + Mesh.Offsets[e], Mesh.PolygonSize(e), c, cone.Axis, clipped);
    if (clipped.size() >= 3)
    {
      sum += PolygonFactorVector(c, clipped.data(), static_cast<int>(clipped.size()));
    }
  }
  return true;
}

void ClusterTree::NodeVector(int index, const Vec3& x, Vec3& sum) const
{
  const Node& node = Nodes[index];
  if (BehindBall(node.Centre, node.Radius, node.Cone, x, 0.0))
  {
    return;
  }
  const Vec3 d = node.Centre - x;
  const double distance = Norm(d);
  if (node.Left >= 0 && distance > kFarRadii * node.Radius && FacesBall(node.Centre, node.Radius, node.Cone, x, 0.0))
  {
    Vec3 towards;
    const double w = FarField(node, x, towards);
    sum += towards * w;
    return;
  }
  if (node.Left >= 0)
  {
    NodeVector(node.Left, x, sum);
    NodeVector(node.Right, x, sum);
    return;
  }
  for (int i = node.First; i < node.First + node.Count; ++i)
  {
    const int e = Order[i];
    if (Dot(G.Normal[e], x - G.Centroid[e]) > 0)
    {
      sum += PolygonFactorVector(x, Loops.data() + Mesh.Offsets[e], Mesh.PolygonSize(e));
    }
  }
}

} // namespace radiosity
