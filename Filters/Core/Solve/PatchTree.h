// A bounding-sphere tree over all patches of a scene (volume clusters of patches of any
// orientation), so that a shooter's link building passes over whole regions at once: those
// behind it, those it faces the back of, and those its rays cannot reach (the other rooms
// of a building), instead of testing each of their patches.
#ifndef RadiosityCore_PatchTree_h
#define RadiosityCore_PatchTree_h

#include "Solve/ShooterFormFactors.h"

#include <vector>

namespace radiosity
{

class PatchTree
{
public:
  struct Node
  {
    Vec3 Centre;
    double Radius = 0; ///< the ball holds every point of the node's patches
    NormalCone Cone;   ///< of all their normals
    int First = 0, Count = 0;                ///< range in Patches()
    int ElementFirst = 0, ElementCount = 0;  ///< range in Targets(): open elements
    int Left = -1, Right = -1;
  };

  /// Leaves hold at most `leafPatches` patches; Frontier() lists about `tasks` disjoint
  /// subtrees covering all patches, for a parallel walk.
  PatchTree(const SceneGeometry& g, const ShooterFormFactors& factors, int leafPatches = 8, int tasks = 256);

  const std::vector<Node>& Nodes() const { return All; }
  /// Patch indices in tree order: node n holds Patches()[First, First + Count).
  const std::vector<int>& Patches() const { return Order; }
  /// The open (not sheltered) elements of the patches in the same order: where rays to
  /// a node are aimed.
  const std::vector<int>& Targets() const { return Open; }
  /// Roots of disjoint subtrees that together hold every patch.
  const std::vector<int>& Frontier() const { return Tasks; }

private:
  int Build(int first, int count, int leafPatches);
  void Summarise(Node& node) const;
  void FindFrontier(int tasks);
  /// Where each patch of a node lies along the line between its two patches farthest
  /// apart (the one farthest from the mean, then the one farthest from that), in steps of
  /// Quantum: splits at their median, ties broken by patch index, make the same tree
  /// however the scene is scaled, rotated or placed, so that the regions passed over are
  /// too (splits along the world's axes would differ under a rotation).
  std::vector<long long> SplitKeys(int first, int count) const;

  const SceneGeometry& G;
  const ShooterFormFactors& Factors;
  std::vector<int> Order, Open, Tasks;
  std::vector<Node> All;
  double Quantum = 1;
};

} // namespace radiosity

#endif
