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
  const Vec3& c = g.Centroid[e];
  if (Norm(light.Position - c) > 2 * std::sqrt(g.Area[e]))
  {
    return 0;
  }
  const double mean = FanAverage(mesh, g, e, [&](const Vec3& x) {
    const Vec3 d = light.Position - x;
    const double r2 = Dot(d, d);
    return r2 > 0 ? std::max(0.0, Dot(g.Normal[e], d)) / (std::sqrt(r2) * r2) : 0.0;
  });
  return std::isnan(mean) ? 0 : mean;
}
} // namespace

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
      cast += ShadeChunk(light, begin, end, irradiance);
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

long long MovingLightShader::ShadeChunk(const MovingLight& light, int begin, int end, std::vector<Vec3>& irradiance) const
{
  const SceneGeometry& g = Geometry();
  const double eps = g.RayLift;
  int waiting[Visibility::PacketSize];
  double intensity[Visibility::PacketSize];
  Vec3 from[Visibility::PacketSize];
  int count = 0;
  long long cast = 0;
  auto flush = [&]() {
    bool blocked[Visibility::PacketSize];
    // The segments stop short of the light, so a light touching a surface still shines.
    Rays().OccludedPacket(from, light.Position, count, 1e-6, blocked);
    for (int i = 0; i < count; ++i)
    {
      if (!blocked[i])
      {
        irradiance[waiting[i] - begin] += light.Color * Unoccluded(light, waiting[i], intensity[i]);
      }
    }
    count = 0;
  };
  for (int e = begin; e < end; ++e)
  {
    const Vec3 d = light.Position - g.Centroid[e];
    const double r2 = Dot(d, d);
    if (!(r2 > 0) || Dot(g.Normal[e], d) <= 0)
    {
      continue;
    }
    double strength = light.Intensity;
    if (Dot(light.Normal, light.Normal) > 0)
    {
      strength *= std::max(0.0, -Dot(Normalized(light.Normal), d) / std::sqrt(r2));
    }
    if (strength <= 0)
    {
      continue;
    }
    ++cast;
    waiting[count] = e;
    intensity[count] = strength;
    from[count] = g.Centroid[e] + g.Normal[e] * eps;
    if (++count == Visibility::PacketSize)
    {
      flush();
    }
  }
  if (count > 0)
  {
    flush();
  }
  return cast;
}

double MovingLightShader::Unoccluded(const MovingLight& light, int e, double intensity) const
{
  const SceneGeometry& g = Geometry();
  const Vec3 d = light.Position - g.Centroid[e];
  const double r2 = Dot(d, d);
  const double r = std::sqrt(r2);
  const double near = NearFieldFactor(Scene, g, e, light);
  return intensity * (near > 0 ? near : (Dot(g.Normal[e], d) / r) / r2);
}

} // namespace radiosity
