#include "Relight/MovingLights.h"

#include "Lights/PointShading.h"

#include <algorithm>
#include <cmath>
#include <atomic>

namespace radiosity
{


MovingLightShader::MovingLightShader(const SceneMesh& scene, const PreparedScene& prepared, const SceneMesh* dynamicObjects)
  : Scene(scene)
  , Prepared(prepared)
{
  if (!Prepared.Fits(scene, true))
  {
    Error_ = "the prepared scene is not this mesh's";
    return;
  }
  SetDynamicObjects(dynamicObjects);
}

bool MovingLightShader::SetDynamicObjects(const SceneMesh* objects)
{
  WithObjects.reset();
  if (!Prepared.Fits(Scene, true))
  {
    return false; // Error_ says why
  }
  Error_.clear(); // a failure with earlier objects does not stick
  if (!objects || objects->NumberOfPolygons() == 0)
  {
    return true;
  }
  WithObjects.reset(new Visibility(Prepared.Rays, *objects));
  Error_ = WithObjects->Error();
  if (!Error_.empty())
  {
    WithObjects.reset();
  }
  return Error_.empty();
}

long long MovingLightShader::Direct(
  const std::vector<MovingLight>& lights, const WorkerPool& pool, std::vector<Vec3>& direct) const
{
  const SceneGeometry& g = Geometry();
  const int n = static_cast<int>(g.Normal.size());
  direct.assign(n, Vec3());
  std::atomic<long long> rays{ 0 };
  pool.For(n, 128, [&](int begin, int end) {
    std::vector<Vec3> irradiance(end - begin);
    long long cast = 0;
    // Light by light, the chunk's shadow rays go in packets (they all end at the light);
    // each element still sums its lights in their order, so the result is as one by one.
    for (const MovingLight& light : lights)
    {
      cast += AddPointIrradiance(light, Scene, g, Rays(), begin, end, irradiance);
    }
    for (int e = begin; e < end; ++e)
    {
      const Vec3& rho = Scene.Reflectance[e];
      const Vec3& in = irradiance[e - begin];
      direct[e] = { rho.x * in.x, rho.y * in.y, rho.z * in.z };
    }
    rays += cast;
  });
  return rays;
}

} // namespace radiosity
