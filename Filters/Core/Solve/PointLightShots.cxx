#include "Solve/PointLightShots.h"

#include "Base/WorkerPool.h"
#include "Lights/PointShading.h"

namespace radiosity
{

std::vector<Vec3> PointLightIrradiance(const SceneMesh& mesh, const SceneGeometry& g, const Visibility& rays,
  const std::vector<PointLight>& lights, int threads)
{
  const int n = mesh.NumberOfPolygons();
  const int k = static_cast<int>(lights.size());
  std::vector<Vec3> irradiance(static_cast<size_t>(n) * k);
  const WorkerPool pool(threads);
  pool.For(n, 256, [&](int begin, int end) {
    std::vector<Vec3> chunk(end - begin);
    for (int i = 0; i < k; ++i)
    {
      PointLight white = lights[i];
      white.Color = { 1, 1, 1 };
      std::fill(chunk.begin(), chunk.end(), Vec3());
      AddPointIrradiance(white, mesh, g, rays, begin, end, chunk);
      for (int e = begin; e < end; ++e)
      {
        irradiance[static_cast<size_t>(e) * k + i] = chunk[e - begin];
      }
    }
  });
  return irradiance;
}

void AddReflectedDirect(const SceneMesh& mesh, const std::vector<Vec3>& irradiance, int lights,
  std::vector<Vec3>& emission, int solutions, int first)
{
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    for (int i = 0; i < lights; ++i)
    {
      emission[static_cast<size_t>(e) * solutions + first + i] +=
        Times(mesh.Reflectance[e], irradiance[static_cast<size_t>(e) * lights + i]);
    }
  }
}

void SettlePointLights(const SceneMesh& mesh, const SceneGeometry& g, const std::vector<PointLight>& lights,
  const std::vector<Vec3>& irradiance, int first, Solution& out)
{
  const int k = static_cast<int>(lights.size());
  const int s = out.Solutions;
  const bool combined = first < 0; // at their colors, in the one solution
  double flux = 0, arrived = 0, reflected = 0;
  for (const PointLight& light : lights)
  {
    const Vec3 c = combined ? light.Color : Vec3{ 1, 1, 1 };
    flux += (c.x + c.y + c.z) * light.Flux(); // channel-summed, as the ledger is
  }
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    for (int i = 0; i < k; ++i)
    {
      const Vec3 white = irradiance[static_cast<size_t>(e) * k + i];
      const Vec3 in = combined ? Times(lights[i].Color, white) : white;
      const Vec3 sent = Times(mesh.Reflectance[e], in);
      arrived += (in.x + in.y + in.z) * g.Area[e];
      reflected += (sent.x + sent.y + sent.z) * g.Area[e];
      if (!out.Direct.empty() && !combined)
      {
        out.Direct[static_cast<size_t>(e) * s + first + i] = sent;
      }
    }
  }
  out.Statistics.EmittedPower += flux - reflected;
  out.Statistics.EscapedPower += flux - arrived;
}

} // namespace radiosity
