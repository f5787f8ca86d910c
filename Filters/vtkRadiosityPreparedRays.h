/**
 * The Embree scene of a polydata's polygons, kept between renders of the same geometry.
 *
 * A relit animation writes an image per frame of one mesh whose arrays change and whose
 * points and polygons do not (the relight filter shallow-copies them). Building the ray
 * scene was most of each write (217,800 elements: 0.32 s a write). A writer keeps the last
 * scene it built, keyed by the points and polygon objects and their modification times,
 * and reuses it while they are unchanged. The keys are weak: a mesh that is gone is not
 * kept alive, and its scene goes with the writer or with the next mesh.
 */
#ifndef vtkRadiosityPreparedRays_h
#define vtkRadiosityPreparedRays_h

#include "Geometry/Visibility.h"

#include "vtkWeakPointer.h"

#include <memory>
#include <string>

class vtkCellArray;
class vtkPoints;
class vtkPolyData;

class vtkRadiosityPreparedRays
{
public:
  /// The ray scene of `data`'s polygons (`mesh`: those polygons, as CopyPolygons gives
  /// them); null with `error` set where Embree failed.
  std::shared_ptr<const radiosity::Visibility> For(vtkPolyData* data, const radiosity::SceneMesh& mesh, std::string& error);

  /// How many scenes were built (the rest of the calls reused one).
  int Builds() const { return this->Built; }

private:
  vtkWeakPointer<vtkPoints> Points;
  vtkWeakPointer<vtkCellArray> Polygons;
  vtkMTimeType PointsTime = 0, PolygonsTime = 0;
  std::shared_ptr<const radiosity::Visibility> Rays;
  int Built = 0;
};

#endif
