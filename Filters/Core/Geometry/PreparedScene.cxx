#include "Geometry/PreparedScene.h"

#include "Base/WorkerPool.h"

namespace radiosity
{

std::string PrepareRays(const SceneMesh& mesh, int threads, PreparedScene& scene)
{
  std::shared_ptr<const Visibility> rays;
  // Embree's BVH build runs in the pool's arena, so it keeps to the threads it was given.
  WorkerPool(threads).Within([&] { rays = std::make_shared<const Visibility>(mesh); });
  if (!rays->Error().empty())
  {
    return rays->Error();
  }
  scene = PreparedScene();
  scene.Rays = std::move(rays);
  scene.Points = static_cast<long long>(mesh.Points.size());
  scene.Polygons = mesh.NumberOfPolygons();
  scene.Corners = static_cast<long long>(mesh.Connectivity.size());
  return "";
}

bool PreparedScene::Fits(const SceneMesh& mesh, bool transport) const
{
  return Rays && (!transport || Geometry) && Points == static_cast<long long>(mesh.Points.size()) &&
    Polygons == mesh.NumberOfPolygons() && Corners == static_cast<long long>(mesh.Connectivity.size());
}

std::string PrepareTransport(const SceneMesh& mesh, int threads, const ProcessGroup& group, PreparedScene& scene)
{
  std::string error = scene.Rays ? "" : PrepareRays(mesh, threads, scene);
  error = AgreeOnFailure(group, error, "could not prepare the scene for rays");
  if (!error.empty())
  {
    return error;
  }
  auto geometry = std::make_shared<SceneGeometry>(mesh);
  scene.SplitPatches = SplitSeparatedPatches(*scene.Rays, mesh, *geometry);
  MarkEnclosed(*scene.Rays, mesh, *geometry, threads, group);
  scene.Geometry = std::move(geometry);
  return "";
}

} // namespace radiosity
