// Auto's cost model: how long the hierarchical and the clustered methods would take on a
// scene, estimated before either runs, so that Auto picks the faster and says why.
#ifndef RadiosityCore_MethodCost_h
#define RadiosityCore_MethodCost_h

#include "Geometry/Scene.h"

namespace radiosity
{

/// About how many ordered pairs of elements the clustered method links one to one: pairs
/// of its elements (open, of some area) closer than `separation` times their radii that
/// face each other at least in part, the near pairs that no group of elements can stand
/// for. Counted around a sample of at most 4,000 elements spread over the scene (a grid
/// over the centroids), scaled to all: 0.18 s on the furnished room at 1.1M elements.
double EstimateNearPairs(const SceneMesh& mesh, const SceneGeometry& g, double separation);

/// Estimated seconds of the hierarchical method (links per element-patch pair).
double HierarchicalSeconds(double elements, double patches);

/// Estimated seconds of the clustered method: a share per element (gathers, direct light,
/// the group links) and one per near pair (each its own shadow rays and link).
double ClusteredSeconds(double elements, double nearPairs);

} // namespace radiosity

#endif
