#include "Relight/MovingLights.h"

#include <algorithm>
#include <cmath>
#include <atomic>

namespace radiosity
{


namespace
{
/// cos(theta) / r^2 of a point light averaged over element e's fan triangles where the
/// light is within twice the element's size (one centroid would misjudge it there, as the
/// solver's receivers near a shooter would); 0 elsewhere, meaning: use the centroid. The
/// light's own falloff (its Normal) is taken at the centroid.
double NearFieldFactor(const SceneMesh& mesh, const SceneGeometry& g, int e, const MovingLight& light)
{
  const Vec3& c = g.centroid[e];
  if (Norm(light.Position - c) > 2 * std::sqrt(g.area[e]))
  {
    return 0;
  }
  const double mean = FanAverage(mesh, g, e, [&](const Vec3& x) {
    const Vec3 d = light.Position - x;
    const double r2 = Dot(d, d);
    return r2 > 0 ? std::max(0.0, Dot(g.normal[e], d)) / (std::sqrt(r2) * r2) : 0.0;
  });
  return std::isnan(mean) ? 0 : mean;
}
} // namespace

MovingLightShader::MovingLightShader(const SceneMesh& scene, const SceneMesh* dynamicObjects)
  : Scene(scene)
  , Geometry_(scene)
  , Rays(new Visibility(scene))
{
  SetDynamicObjects(dynamicObjects);
}

bool MovingLightShader::SetDynamicObjects(const SceneMesh* objects)
{
  return Rays->Error().empty() && Rays->SetDynamic(objects);
}

long long MovingLightShader::Direct(
  const std::vector<MovingLight>& lights, const WorkerPool& pool, std::vector<Vec3>& direct) const
{
  const SceneGeometry& g = Geometry_;
  const int n = static_cast<int>(g.normal.size());
  direct.assign(n, Vec3());
  const double eps = 1e-6 * g.sceneDiagonal;
  std::atomic<long long> rays{ 0 };
  pool.For(n, 128, [&](int begin, int end) {
    long long cast = 0;
    for (int e = begin; e < end; ++e)
    {
      const Vec3& x = g.centroid[e];
      Vec3 irradiance;
      for (const MovingLight& light : lights)
      {
        const Vec3 d = light.Position - x;
        const double r2 = Dot(d, d);
        const double cosReceiver = Dot(g.normal[e], d);
        if (!(r2 > 0) || cosReceiver <= 0)
        {
          continue;
        }
        const double r = std::sqrt(r2);
        double intensity = light.Intensity;
        if (Dot(light.Normal, light.Normal) > 0)
        {
          intensity *= std::max(0.0, -Dot(Normalized(light.Normal), d) / r);
        }
        if (intensity <= 0)
        {
          continue;
        }
        ++cast;
        // The segment stops short of the light, so a light touching a surface still shines.
        if (Rays->Occluded(x + g.normal[e] * eps, light.Position, 1e-6))
        {
          continue;
        }
        const double near = NearFieldFactor(Scene, g, e, light);
        const double scale = intensity * (near > 0 ? near : (cosReceiver / r) / r2);
        irradiance += light.Color * scale;
      }
      const Vec3& rho = Scene.reflectance[e];
      direct[e] = { rho.x * irradiance.x, rho.y * irradiance.y, rho.z * irradiance.z };
    }
    rays += cast;
  });
  return rays;
}

} // namespace radiosity
