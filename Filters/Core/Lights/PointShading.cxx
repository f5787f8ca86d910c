#include "Lights/PointShading.h"

#include <algorithm>
#include <cmath>

namespace radiosity
{

namespace
{
/// cos(theta) / r^2 of a point at `position` averaged over element e's fan triangles where
/// it is within twice the element's size; 0 elsewhere, meaning: use the centroid.
double NearFieldFactor(const SceneMesh& mesh, const SceneGeometry& g, int e, const Vec3& position)
{
  const Vec3& c = g.Centroid[e];
  if (Norm(position - c) > 2 * std::sqrt(g.Area[e]))
  {
    return 0;
  }
  const double mean = FanAverage(mesh, g, e, [&](const Vec3& x) {
    const Vec3 d = position - x;
    const double r2 = Dot(d, d);
    return r2 > 0 ? std::max(0.0, Dot(g.Normal[e], d)) / (std::sqrt(r2) * r2) : 0.0;
  });
  return std::isnan(mean) ? 0 : mean;
}

/// What the light gives element e where nothing blocks it, at `strength` toward e.
double Unoccluded(const SceneMesh& mesh, const SceneGeometry& g, const Vec3& position, int e, double strength)
{
  const Vec3 d = position - g.Centroid[e];
  const double r2 = Dot(d, d);
  const double r = std::sqrt(r2);
  const double near = NearFieldFactor(mesh, g, e, position);
  return strength * (near > 0 ? near : (Dot(g.Normal[e], d) / r) / r2);
}
} // namespace

long long AddPointIrradiance(const PointLight& light, const SceneMesh& mesh, const SceneGeometry& g,
  const Visibility& rays, int begin, int end, std::vector<Vec3>& irradiance)
{
  int waiting[Visibility::PacketSize];
  double strength[Visibility::PacketSize];
  Vec3 from[Visibility::PacketSize];
  int count = 0;
  long long cast = 0;
  auto flush = [&]() {
    bool blocked[Visibility::PacketSize];
    // The segments stop short of the light, so a light touching a surface still shines.
    rays.OccludedPacket(from, light.Position, count, 1e-6, blocked);
    for (int i = 0; i < count; ++i)
    {
      if (!blocked[i])
      {
        irradiance[waiting[i] - begin] += light.Color * Unoccluded(mesh, g, light.Position, waiting[i], strength[i]);
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
    const double toward = light.Toward(d * -1.0);
    if (!(toward > 0))
    {
      continue;
    }
    ++cast;
    waiting[count] = e;
    strength[count] = toward;
    from[count] = g.Centroid[e] + g.Normal[e] * g.RayLift;
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

Vec3 PointIrradianceAt(const PointLight& light, const Vec3& point, const Vec3& normal, const Visibility& rays, double lift)
{
  const Vec3 d = light.Position - point;
  const double r2 = Dot(d, d);
  const double cosine = r2 > 0 ? Dot(normal, d) / std::sqrt(r2) : 0;
  if (!(cosine > 0))
  {
    return {};
  }
  const double toward = light.Toward(d * -1.0);
  if (!(toward > 0) || rays.Occluded(point + normal * lift, light.Position, 1e-6))
  {
    return {};
  }
  return light.Color * (toward * cosine / r2);
}

} // namespace radiosity
