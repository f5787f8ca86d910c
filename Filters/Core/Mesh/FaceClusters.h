// Face clusters: a curved surface tessellated into many small polygons (a CAD export, a
// scan) is grouped into patches of about PatchSize, so that light is shot from and received
// by groups of polygons, not by each one (after Willmott, Heckbert & Garland 1999).
#ifndef RadiosityCore_FaceClusters_h
#define RadiosityCore_FaceClusters_h

#include "Mesh/Mesher.h"

#include <vector>

namespace radiosity
{

/// Merges small patches (at most 0.3 `patchSize` across) of `mesh` into face clusters:
/// grown from each patch in order over the edges its `input` polygons share (the polygons
/// MeshPolygons meshed into `mesh`, `mesh.MeshedPolygon` naming each element's), through
/// patches of the same
/// `surfaceKey` (per input polygon, as MeshPolygons takes it) whose normals are within
/// `coneDegrees` of the first one's, while every corner stays within 0.3 `patchSize` of its
/// centre (a curved cluster shoots one value, so it is kept smaller than a flat patch). Patch ids are made 0..patches-1 again. Returns the number of patches merged away.
/// `weld`: how far apart two corners may be and still meet (the input's noise; at least a
/// billionth of its span).
int ClusterFaces(MeshedPolygons& mesh, const PolygonArrays& input, const std::vector<int>& surfaceKey, double patchSize,
  double coneDegrees, double weld = 0);

} // namespace radiosity

#endif
