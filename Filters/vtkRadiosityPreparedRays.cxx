#include "vtkRadiosityPreparedRays.h"

#include "vtkCellArray.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <mutex>

namespace vtkRadiosityPreparedRays
{
namespace
{
/// The kept scene and what it was built from. The smart pointers keep the keys' objects
/// alive, so a new object at a freed one's address is never taken for it.
struct Kept
{
  vtkSmartPointer<vtkPoints> Points;
  vtkSmartPointer<vtkCellArray> Polygons;
  vtkMTimeType PointsTime = 0, PolygonsTime = 0;
  std::shared_ptr<const radiosity::Visibility> Rays;
};

std::mutex& Lock()
{
  static std::mutex lock;
  return lock;
}

Kept& Last()
{
  static Kept last;
  return last;
}
} // namespace

std::shared_ptr<const radiosity::Visibility> For(vtkPolyData* data, const radiosity::SceneMesh& mesh, std::string& error)
{
  vtkPoints* points = data->GetPoints();
  vtkCellArray* polygons = data->GetPolys();
  std::lock_guard<std::mutex> hold(Lock());
  Kept& last = Last();
  if (last.Rays && points && polygons && last.Points == points && last.Polygons == polygons &&
    last.PointsTime == points->GetMTime() && last.PolygonsTime == polygons->GetMTime())
  {
    return last.Rays;
  }
  last = Kept(); // the old scene goes before the new one is built: one in memory at a time
  auto rays = std::make_shared<const radiosity::Visibility>(mesh);
  if (!rays->Error().empty())
  {
    error = rays->Error();
    return nullptr;
  }
  if (points && polygons)
  {
    last = Kept{ points, polygons, points->GetMTime(), polygons->GetMTime(), rays };
  }
  return rays;
}

void Release()
{
  std::lock_guard<std::mutex> hold(Lock());
  Last() = Kept();
}
}
