// The boundary of a set of coplanar polygons as straight segments: what Lambert's contour
// integral needs to see a whole meshed emitter as one polygon.
#ifndef RadiosityCore_Outline_h
#define RadiosityCore_Outline_h

#include "Geometry/Scene.h"

#include <vector>

namespace radiosity
{

/// The outline of `polygons` (coplanar polygons of `mesh`) as start/end point pairs: an edge
/// shared by two of them cancels, T-junctions are split first so it still does, and
/// straight runs are joined, so the outline's length does not grow with the number of
/// elements a lamp was meshed into (each segment costs Lambert's formula an atan2).
std::vector<Vec3> PolygonSetOutline(const SceneMesh& mesh, const std::vector<int>& polygons);

} // namespace radiosity

#endif
