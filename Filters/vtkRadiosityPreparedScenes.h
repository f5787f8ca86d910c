/**
 * The prepared scenes (radiosity::PreparedScene: the Embree scene and, for transport, the
 * geometry) of the meshes the filters traced last, kept for the process and shared.
 *
 * A preparation depends on a mesh's points, polygons and PatchId only, and the pipeline
 * passes those on by reference (the solver's and the relight's outputs shallow-copy their
 * input), so one preparation serves a re-solve with other settings, the moving lights of
 * the solver's output and every EXR picture of it. Measured at 217,800 elements: 1.2 s of
 * preparation (BVH, patch splitting, the hemisphere probes) skipped by each of them.
 *
 * The keys are weak: a scene goes when the points it was made for are deleted. Up to four
 * keys are kept, the least recently used dropped first; where two keys share one
 * preparation (the solver's input and output) it is held once. Not wrapped.
 */
#ifndef vtkRadiosityPreparedScenes_h
#define vtkRadiosityPreparedScenes_h

#include "Geometry/PreparedScene.h"

class vtkPolyData;

namespace vtkRadiosityPreparedScenes
{

/// The preparation kept for `data`'s points and polygons, unchanged since; with
/// `transport`, only one that has geometry for `data`'s PatchId as it is now. Otherwise an
/// empty one (null Rays).
radiosity::PreparedScene Find(vtkPolyData* data, bool transport);

/// Keeps `scene` for `data`'s points, polygons and PatchId as they are now.
void Keep(vtkPolyData* data, const radiosity::PreparedScene& scene);

/// How many preparations are held (distinct ones, however many keys share them).
int Held();

}

#endif
