// Cell values carried to the vertices, for smooth shading of a solution.
#ifndef RadiosityCore_PointAverages_h
#define RadiosityCore_PointAverages_h

#include "Geometry/Scene.h"

#include <vector>

namespace radiosity
{

/// Vertex values as the area-weighted mean of the cells around each vertex. Vertices are
/// shared only within a flat surface of one material, so nothing bleeds across corners.
std::vector<Vec3> AverageToPoints(
  const SceneMesh& mesh, const SceneGeometry& geometry, const std::vector<Vec3>& cells, int columns);

} // namespace radiosity

#endif
