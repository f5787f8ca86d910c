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
 * A preparation is found by content: a hash of the points, the polygons and PatchId, so
 * edits in place (numpy, InsertNextCell) are never mistaken for the mesh prepared before
 * (modification times miss them). It is kept for the points object it was made for and goes
 * when those points are deleted or edited; up to four are kept, the least recently used
 * dropped first; where two entries share one preparation (the solver's input and output)
 * it is held once. Under MPI the solver's whole scene is gathered anew for each solve, so
 * only the relight and the writers on a rank's own piece reuse there. Not wrapped.
 */
#ifndef vtkRadiosityPreparedScenes_h
#define vtkRadiosityPreparedScenes_h

#include "Geometry/PreparedScene.h"

#include <cstdint>

class vtkPolyData;

namespace vtkRadiosityPreparedScenes
{

/// What a preparation is made from, by content: the points, the polygons and the points'
/// precision hashed (Mesh), and PatchId (Patches). Modification times would miss edits in
/// place (numpy writes, InsertNextCell, a cell array's own arrays); hashing the 10 MB of a
/// 217,800-element mesh costs a few milliseconds against a second of preparation. A filter
/// takes its input's key once and hands it to Find and Keep.
struct MeshKey
{
  std::uint64_t Mesh = 0, Patches = 0;
};

/// `data`'s key as it is now.
MeshKey KeyOf(vtkPolyData* data);

/// `key` with the patches of `data`, a mesh sharing the points and polygons `key` was
/// taken from (the solver's output, whose PatchId may say where patches were split).
MeshKey WithPatchesOf(MeshKey key, vtkPolyData* data);

/// The preparation kept for `data`'s mesh (`key`, KeyOf(data)); with `transport`, one that
/// also has geometry for its PatchId. Where only rays are kept for the mesh (the EXR writer
/// prepared it), those (null Geometry); otherwise an empty one (null Rays).
radiosity::PreparedScene Find(vtkPolyData* data, const MeshKey& key, bool transport);

/// Keeps `scene` for `data`'s points under `key` (KeyOf(data) as it is now).
void Keep(vtkPolyData* data, const MeshKey& key, const radiosity::PreparedScene& scene);

/// Drops every kept preparation (memory back now; the next solve prepares again).
void Clear();

/// How many preparations are held (distinct ones, however many entries share them).
int Held();

}

#endif
