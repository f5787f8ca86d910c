// Linear interpolation over a patch from values at its corners, so that energy a patch
// receives as a whole still varies smoothly across its elements.
#ifndef RadiosityCore_PatchNodes_h
#define RadiosityCore_PatchNodes_h

#include "Geometry/Scene.h"

#include <vector>

namespace radiosity
{

/// Each patch gets nodes: the corners of its outline (straight runs merged) and its centre,
/// or the centre alone where the outline is not one simple loop. Values interpolate
/// linearly over the fan of triangles (centre, corner, next corner): exact for linear
/// functions, and the centre keeps a value that peaks or dips inside the patch (a cosine
/// that vanishes along one edge) from being lost between corners.
class PatchNodes
{
public:
  /// `loops[p]`: the patch's outline as one loop of corners (empty where it has none).
  PatchNodes(const SceneGeometry& geometry, const std::vector<std::vector<Vec3>>& loops, const std::vector<Vec3>& centres);

  int Count() const { return static_cast<int>(Position.size()); }
  int Begin(int patch) const { return NodeBegin[patch]; }
  int End(int patch) const { return NodeBegin[patch + 1]; }
  const Vec3& Node(int node) const { return Position[node]; }
  /// Sum over the patch's elements of weight x area: what a unit value at the node covers.
  /// Sheltered elements (SceneGeometry::Sheltered) have weight 0: what reaches a patch as a
  /// whole lands on its open part.
  double CoveredArea(int node) const { return Area[node]; }
  /// The fan triangles (centre, corner i, corner i+1) of a patch with corners: node
  /// Begin(patch) + i is corner i, and fan triangle FanBegin(patch) + i follows it.
  int FanBegin(int patch) const { return NodeBegin[patch] - patch; }
  int FanEnd(int patch) const { return NodeBegin[patch + 1] - patch - 1; }
  const Vec3& FanCentroid(int fan) const { return FanCentroids[fan]; }
  double FanArea(int fan) const { return FanAreas[fan]; }
  /// The element's weights, one per node of its patch, in node order.
  const double* Weights(int element) const { return WeightData.data() + WeightBegin[element]; }

private:
  void AddNodes(int patch, const SceneGeometry& g, std::vector<Vec3> loop, const Vec3& centre);
  std::vector<Vec3> Position;
  std::vector<int> NodeBegin{ 0 };
  std::vector<double> Area, WeightData;
  std::vector<size_t> WeightBegin;
  std::vector<Vec3> FanCentroids;
  std::vector<double> FanAreas;
};

/// Weights of x (corners..., centre) in the fan triangle of `loop` around `centre` that
/// contains it (or comes nearest), in the plane with unit `normal`; returns that triangle.
size_t FanCoordinates(const Vec3& x, const Vec3& normal, const std::vector<Vec3>& loop, const Vec3& centre,
  double* weights);

} // namespace radiosity

#endif
