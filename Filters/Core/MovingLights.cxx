#include "MovingLights.h"

#include <algorithm>
#include <cmath>
#include <atomic>

namespace radiosity
{

namespace
{
SceneMesh Merge(const SceneMesh& scene, const SceneMesh* extra)
{
  SceneMesh all = scene;
  if (extra)
  {
    const int base = static_cast<int>(all.points.size());
    all.points.insert(all.points.end(), extra->points.begin(), extra->points.end());
    for (int i = 0; i < extra->NumberOfPolygons(); ++i)
    {
      std::vector<int> ids(extra->Polygon(i), extra->Polygon(i) + extra->PolygonSize(i));
      for (int& id : ids)
      {
        id += base;
      }
      all.AddPolygon(ids);
    }
  }
  return all;
}
} // namespace

MovingLightShader::MovingLightShader(const SceneMesh& scene, const SceneMesh* dynamicObjects)
  : Scene(scene)
  , Geometry_(scene)
  , Rays(new Visibility(Merge(scene, dynamicObjects)))
{
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
        const double scale = intensity * (cosReceiver / r) / r2;
        irradiance += light.Color * scale;
      }
      const Vec3& rho = Scene.reflectance[e];
      direct[e] = { rho.x * irradiance.x, rho.y * irradiance.y, rho.z * irradiance.z };
    }
    rays += cast;
  });
  return rays;
}

void AddBasisInterreflection(const SceneGeometry& g, const std::vector<Vec3>& direct,
  const float* basis, int patches, const WorkerPool& pool, std::vector<Vec3>& result)
{
  const int n = static_cast<int>(g.normal.size());
  // Each patch emits what it reflects directly: the area mean of D over its elements.
  std::vector<Vec3> emission(patches);
  for (int e = 0; e < n; ++e)
  {
    const int q = g.elementPatch[e];
    emission[q] += g.patchOpenArea[q] > 0 ? direct[e] * (g.area[e] / g.patchOpenArea[q]) : Vec3();
  }
  result = direct;
  const size_t stride = 3 * static_cast<size_t>(patches);
  pool.For(n, 256, [&](int begin, int end) {
    for (int e = begin; e < end; ++e)
    {
      const float* b = basis + e * stride;
      Vec3 sum;
      for (int q = 0; q < patches; ++q)
      {
        sum.x += emission[q].x * b[3 * q + 0];
        sum.y += emission[q].y * b[3 * q + 1];
        sum.z += emission[q].z * b[3 * q + 2];
      }
      result[e] += sum;
    }
  });
}

std::vector<float> SolvePatchBasis(
  const RadiositySolver& solver, const SceneMesh& mesh, const SolverOptions& options, SolverStatistics& stats)
{
  const SceneGeometry& g = solver.Geometry();
  const int n = mesh.NumberOfPolygons();
  const int P = static_cast<int>(g.patchElements.size());
  std::vector<Vec3> emission(static_cast<size_t>(n) * P);
  for (int e = 0; e < n; ++e)
  {
    if (!g.enclosed[e]) // unit exitance over the patch's open area
    {
      emission[static_cast<size_t>(e) * P + g.elementPatch[e]] = { 1, 1, 1 };
    }
  }
  SolverOptions basisOptions = options;
  basisOptions.AmbientTerm = false;
  basisOptions.SeparateDirect = false;
  basisOptions.DirectToElements = false; // every patch emits: links, not P x N factors
  const Solution s = solver.Solve(emission, P, basisOptions);
  stats = s.Statistics;
  std::vector<float> basis(static_cast<size_t>(n) * 3 * P);
  for (int e = 0; e < n; ++e)
  {
    for (int q = 0; q < P; ++q)
    {
      const size_t i = static_cast<size_t>(e) * P + q;
      const Vec3 reflected = s.Radiosity[i] - emission[i];
      float* b = &basis[static_cast<size_t>(e) * 3 * P + 3 * q];
      b[0] = static_cast<float>(reflected.x);
      b[1] = static_cast<float>(reflected.y);
      b[2] = static_cast<float>(reflected.z);
    }
  }
  return basis;
}

} // namespace radiosity
