// Surfaces lying face to face: the floor under a box's bottom, the box's bottom on it.
#ifndef RadiosityCore_FaceContact_h
#define RadiosityCore_FaceContact_h

#include "Geometry/Polygon.h"
#include "Geometry/Scene.h"

#include <vector>

namespace radiosity
{

/// The bounds of element e's corners.
Bounds ElementBounds(const SceneMesh& mesh, int e);

/// True when x lies inside convex element e (in its plane and inside its edges, within
/// `tolerance`). A concave element can only be missed, never found where x is not.
bool InsideElement(const SceneMesh& mesh, const SceneGeometry& g, int e, const Vec3& x, double tolerance);

/// Of `candidates`, the elements that lie face to face on another element: in its plane
/// (within `tolerance`), facing the opposite way, their centroid inside it. Rays cannot
/// tell such a pair apart (they meet both at one distance), so their probes start past
/// the other face and see whatever lies beyond it.
std::vector<int> FaceToFace(const SceneMesh& mesh, const SceneGeometry& g, const std::vector<int>& candidates,
  double tolerance);

} // namespace radiosity

#endif
