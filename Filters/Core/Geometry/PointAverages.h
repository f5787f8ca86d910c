// Cell values carried to the vertices, for smooth shading of a solution.
#ifndef RadiosityCore_PointAverages_h
#define RadiosityCore_PointAverages_h

#include "Geometry/Scene.h"

#include <vector>

namespace radiosity
{

/// 1 for each point that some unsheltered element uses. Where a point has such an element,
/// only those count around it (a footprint's dark is its own, not its neighbours'); the
/// vertex averages and the final gather's point frames both take them so.
std::vector<char> PointsTouchingOpenElements(const SceneMesh& mesh, const SceneGeometry& geometry);

/// Vertex values as the area-weighted mean of the cells around each vertex. Vertices are
/// shared only within a flat surface of one material, so nothing bleeds across corners.
std::vector<Vec3> AverageToPoints(
  const SceneMesh& mesh, const SceneGeometry& geometry, const std::vector<Vec3>& cells, int columns);

} // namespace radiosity

#endif
