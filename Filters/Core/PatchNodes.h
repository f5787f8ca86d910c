// Linear interpolation over a patch from values at its corners, so that energy a patch
// receives as a whole still varies smoothly across its elements.
#ifndef RadiosityCore_PatchNodes_h
#define RadiosityCore_PatchNodes_h

#include "Scene.h"

#include <vector>

namespace radiosity
{

/// Each patch gets nodes: the corners of its outline (straight runs merged), or its centre
/// alone where the outline is not one simple loop. Each element gets mean value
/// coordinates (Floater 2003) of its centroid over its patch's nodes: weights that sum to 1
/// and reproduce linear functions exactly.
class PatchNodes
{
public:
  /// `outlines[p]`: the patch's boundary as start/end point pairs (empty: not planar or a
  /// single element, whose own polygon is used).
  PatchNodes(const SceneMesh& mesh, const SceneGeometry& geometry, const std::vector<std::vector<Vec3>>& outlines,
    const std::vector<Vec3>& centres);

  int Count() const { return static_cast<int>(Position.size()); }
  int Begin(int patch) const { return NodeBegin[patch]; }
  int End(int patch) const { return NodeBegin[patch + 1]; }
  const Vec3& Node(int node) const { return Position[node]; }
  /// Sum over the patch's elements of weight x area: what a unit value at the node covers.
  double CoveredArea(int node) const { return Area[node]; }
  /// The element's weights, one per node of its patch, in node order.
  const double* Weights(int element) const { return WeightData.data() + WeightBegin[element]; }

private:
  void AddNodes(int patch, const SceneMesh& mesh, const SceneGeometry& g, const std::vector<Vec3>& outline,
    const Vec3& centre);
  std::vector<Vec3> Position;
  std::vector<int> NodeBegin{ 0 };
  std::vector<double> Area, WeightData;
  std::vector<size_t> WeightBegin;
};

/// Mean value coordinates of x in the planar polygon `loop` (unit `normal`); falls back to
/// the nearest corner where x sits on one.
void MeanValueCoordinates(const Vec3& x, const Vec3& normal, const std::vector<Vec3>& loop, double* weights);

} // namespace radiosity

#endif
