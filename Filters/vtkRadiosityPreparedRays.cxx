#include "vtkRadiosityPreparedRays.h"

#include "vtkCellArray.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

std::shared_ptr<const radiosity::Visibility> vtkRadiosityPreparedRays::For(
  vtkPolyData* data, const radiosity::SceneMesh& mesh, std::string& error)
{
  vtkPoints* points = data->GetPoints();
  vtkCellArray* polygons = data->GetPolys();
  // A freed key reads null, so a new object at its address is never taken for it.
  if (this->Rays && points && polygons && this->Points == points && this->Polygons == polygons &&
    this->PointsTime == points->GetMTime() && this->PolygonsTime == polygons->GetMTime())
  {
    return this->Rays;
  }
  this->Rays.reset(); // the old scene goes before the new one is built: one in memory at a time
  auto rays = std::make_shared<const radiosity::Visibility>(mesh);
  ++this->Built;
  if (!rays->Error().empty())
  {
    error = rays->Error();
    return nullptr;
  }
  this->Points = points;
  this->Polygons = polygons;
  this->PointsTime = points ? points->GetMTime() : 0;
  this->PolygonsTime = polygons ? polygons->GetMTime() : 0;
  this->Rays = rays;
  return rays;
}
