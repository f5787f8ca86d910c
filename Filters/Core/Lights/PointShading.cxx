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

/// Within this many opening sizes of a surface the light is spread over its opening (as a
/// point its light would be a few per cent too sharp there: (size / 2d)^2 at distance d).
constexpr double kNearOpenings = 5;
constexpr int kOpeningPoints = 16;

/// Where the light is taken from for a receiver at `at`: its opening's points where the
/// receiver is near it, else its position alone.
std::vector<Vec3> SourcesFor(const PointLight& light, const Vec3& at)
{
  const double size = light.OpeningSize();
  return size > 0 && Norm(light.Position - at) < kNearOpenings * size ? light.OpeningPoints(kOpeningPoints)
                                                                      : std::vector<Vec3>{ light.Position };
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
/// Element e's irradiance from a light spread over its opening's `sources` (each a share of
/// it, with its own shadow ray), added to `out`; returns the rays cast.
long long OpeningIrradiance(const PointLight& light, const std::vector<Vec3>& sources, const SceneMesh& mesh,
  const SceneGeometry& g, const Visibility& rays, int e, Vec3& out)
{
  long long cast = 0;
  const double share = 1.0 / sources.size();
  for (const Vec3& source : sources)
  {
    const Vec3 d = source - g.Centroid[e];
    const double toward = light.Toward(d * -1.0);
    if (!(Dot(d, d) > 0) || Dot(g.Normal[e], d) <= 0 || !(toward > 0))
    {
      continue;
    }
    ++cast;
    if (!rays.Occluded(g.Centroid[e] + g.Normal[e] * g.RayLift, source, 1e-6))
    {
      out += light.Color * (share * Unoccluded(mesh, g, source, e, toward));
    }
  }
  return cast;
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
    const std::vector<Vec3> sources = SourcesFor(light, g.Centroid[e]);
    if (sources.size() > 1)
    {
      cast += OpeningIrradiance(light, sources, mesh, g, rays, e, irradiance[e - begin]);
      continue;
    }
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
  const std::vector<Vec3> sources = SourcesFor(light, point);
  Vec3 sum;
  for (const Vec3& source : sources)
  {
    const Vec3 d = source - point;
    const double r2 = Dot(d, d);
    const double cosine = r2 > 0 ? Dot(normal, d) / std::sqrt(r2) : 0;
    if (!(cosine > 0))
    {
      continue;
    }
    const double toward = light.Toward(d * -1.0);
    if (toward > 0 && !rays.Occluded(point + normal * lift, source, 1e-6))
    {
      sum += light.Color * (toward * cosine / r2);
    }
  }
  return sum * (1.0 / sources.size());
}

} // namespace radiosity
