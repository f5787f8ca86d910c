/**
 * The Embree scene of a polydata's polygons, kept between renders of the same geometry.
 *
 * A relit animation writes an image per frame of one mesh whose arrays change and whose
 * points and polygons do not (the relight filter shallow-copies them). Building the ray
 * scene was most of each write (217,800 elements: 0.32 s a write). The last scene built is
 * kept, keyed by the points and polygon objects and their modification times, and reused
 * while they are unchanged. It holds the ray scene (about 100 bytes a triangle) until a
 * different mesh replaces it or Release() is called.
 */
#ifndef vtkRadiosityPreparedRays_h
#define vtkRadiosityPreparedRays_h

#include "Geometry/Visibility.h"

#include <memory>
#include <string>

class vtkPolyData;

namespace vtkRadiosityPreparedRays
{
/// The ray scene of `data`'s polygons (`mesh`: those polygons, as CopyPolygons gives
/// them), shared; null with `error` set where Embree failed.
std::shared_ptr<const radiosity::Visibility> For(vtkPolyData* data, const radiosity::SceneMesh& mesh, std::string& error);

/// Drops the kept scene.
void Release();
}

#endif
