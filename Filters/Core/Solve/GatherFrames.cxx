#include "Solve/GatherFrames.h"

#include "Geometry/Outline.h"
#include "Geometry/PointAverages.h"
#include "Geometry/Polygon.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>

namespace radiosity
{
namespace gathering
{
namespace
{
bool Emits(const std::vector<Vec3>& emission, int e, int solutions)
{
  return AnyPositive(&emission[static_cast<size_t>(e) * solutions], solutions);
}

void AddTriangles(const SceneMesh& mesh, const SceneGeometry& g, int e, Emitter& out)
{
  const int* ids = mesh.Polygon(e);
  const Vec3 lift = g.Normal[e] * g.RayLift;
  for (int v = 1; v + 1 < mesh.PolygonSize(e); ++v)
  {
    const Vec3 a = mesh.Points[ids[0]] + lift, b = mesh.Points[ids[v]] + lift, c = mesh.Points[ids[v + 1]] + lift;
    const double area = 0.5 * Norm(Cross(b - a, c - a));
    out.Triangles.insert(out.Triangles.end(), { a, b, c });
    out.Cdf.push_back((out.Cdf.empty() ? 0.0 : out.Cdf.back()) + area);
  }
}

/// The outline and common exitance of a planar emitter whose elements emit alike; both
/// stay empty where they do not.
void AddOutline(const SceneMesh& mesh, const std::vector<Vec3>& emission, int solutions, Emitter& out)
{
  const size_t first = static_cast<size_t>(out.Elements.front()) * solutions;
  for (int e : out.Elements)
  {
    for (int m = 0; m < solutions; ++m)
    {
      const Vec3 d = emission[static_cast<size_t>(e) * solutions + m] - emission[first + m];
      if (d.x != 0 || d.y != 0 || d.z != 0 || !out.Planar)
      {
        return;
      }
    }
  }
  out.Outline = PolygonSetOutline(mesh, out.Elements);
  out.Exitance.assign(emission.begin() + first, emission.begin() + first + solutions);
}
} // namespace

bool AnyPositive(const Vec3* values, int count)
{
  for (int m = 0; m < count; ++m)
  {
    if (values[m].x > 0 || values[m].y > 0 || values[m].z > 0)
    {
      return true;
    }
  }
  return false;
}

std::vector<int> Representatives(const SceneMesh& mesh, const SceneGeometry& g)
{
  const size_t points = mesh.Points.size();
  std::vector<Vec3> normal(points), rho(points);
  std::vector<int> rep(points, -1);
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    for (int v = 0; v < mesh.PolygonSize(e); ++v)
    {
      const int p = mesh.Polygon(e)[v];
      normal[p] += g.Normal[e] * g.Area[e];
      rho[p] = rep[p] < 0 ? mesh.Reflectance[e] : rho[p];
      rep[p] = p;
    }
  }
  std::map<std::array<double, 3>, std::vector<int>> byPlace;
  for (size_t p = 0; p < points; ++p)
  {
    if (rep[p] >= 0)
    {
      byPlace[{ mesh.Points[p].x, mesh.Points[p].y, mesh.Points[p].z }].push_back(static_cast<int>(p));
    }
  }
  const double agree = std::cos(30.0 * M_PI / 180.0);
  for (const auto& place : byPlace)
  {
    const std::vector<int>& here = place.second;
    for (size_t i = 1; i < here.size(); ++i)
    {
      const int p = here[i];
      for (size_t j = 0; j < i && rep[p] == p; ++j)
      {
        const int q = here[j];
        const Vec3 d = rho[p] - rho[q];
        if (rep[q] == q && d.x == 0 && d.y == 0 && d.z == 0 &&
          Dot(Normalized(normal[p]), Normalized(normal[q])) > agree)
        {
          rep[p] = q;
        }
      }
    }
  }
  return rep;
}

std::vector<PointFrame> MakeFrames(const SceneMesh& mesh, const SceneGeometry& g, const std::vector<Vec3>& emission,
  int solutions, const std::vector<int>& rep, std::vector<Vec3>& pointEmission)
{
  const size_t points = mesh.Points.size();
  const std::vector<char> open = PointsTouchingOpenElements(mesh, g);
  std::vector<PointFrame> frames(points);
  std::vector<Vec3> centre(points);
  std::vector<double> weight(points, 0.0);
  std::vector<Vec3> firstNormal(points);
  pointEmission.assign(points * solutions, Vec3());
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    const int* ids = mesh.Polygon(e);
    const double w = g.Area[e];
    for (int v = 0; v < mesh.PolygonSize(e) && w > 0; ++v)
    {
      const int p = ids[v];
      if (g.Sheltered[e] && open[p])
      {
        continue;
      }
      if (weight[p] == 0)
      {
        frames[p].Edge = mesh.Points[ids[1 % mesh.PolygonSize(e)]] - mesh.Points[ids[0]];
        firstNormal[p] = g.Normal[e];
      }
      weight[p] += w;
      frames[p].Normal += g.Normal[e] * w;
      frames[p].Reflectance += mesh.Reflectance[e] * w;
      centre[p] += g.Centroid[e] * w;
      for (int m = 0; m < solutions; ++m)
      {
        pointEmission[static_cast<size_t>(p) * solutions + m] += emission[static_cast<size_t>(e) * solutions + m] * w;
      }
    }
  }
  for (size_t p = 0; p < points; ++p)
  {
    if (weight[p] <= 0 || rep[p] != static_cast<int>(p))
    {
      continue;
    }
    const double inv = 1.0 / weight[p];
    PointFrame& f = frames[p];
    f.Used = true;
    // Faces back to back on shared points sum to no normal: take the first one's.
    f.Normal = Norm(f.Normal) > 1e-9 ? Normalized(f.Normal) : firstNormal[p];
    f.Reflectance = f.Reflectance * inv;
    for (int m = 0; m < solutions; ++m)
    {
      pointEmission[p * solutions + m] = pointEmission[p * solutions + m] * inv;
    }
    // A quarter of the way to its elements' centre: the value that linear interpolation
    // over the elements needs is the neighbourhood's, not the corner's alone (a door's top
    // corner sits in the reveal's 5 cm shadow, which the whole element would take on;
    // measured on the FZK-Haus at probes traced from the lamps: 5.15 % from Mitsuba 3 at a
    // hundredth of the way, 4.87 % at a quarter, 4.80 % at 0.4). Off the edge, too, so a
    // ray along a wall standing on that edge meets the wall instead of slipping past it.
    // On a curved surface's convex side that centre lies under the surface: only the move
    // along it is kept, or the point would start inside the solid and see only back faces.
    Vec3 inward = (centre[p] * inv - mesh.Points[p]) * 0.25;
    inward = inward - f.Normal * std::min(0.0, Dot(inward, f.Normal));
    f.Origin = mesh.Points[p] + inward + f.Normal * g.RayLift;
  }
  return frames;
}

std::vector<PointFrame> ElementFrames(const SceneMesh& mesh, const SceneGeometry& g)
{
  std::vector<PointFrame> frames(mesh.NumberOfPolygons());
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    PointFrame& f = frames[e];
    f.Used = !g.Enclosed[e] && g.Area[e] > 0;
    f.Element = e;
    f.Normal = g.Normal[e];
    f.Reflectance = mesh.Reflectance[e];
    f.Origin = g.Centroid[e] + f.Normal * g.RayLift;
    f.Edge = mesh.Points[mesh.Polygon(e)[1 % mesh.PolygonSize(e)]] - mesh.Points[mesh.Polygon(e)[0]];
    for (int v = 0; v < mesh.PolygonSize(e); ++v)
    {
      f.Radius = std::max(f.Radius, Norm(mesh.Points[mesh.Polygon(e)[v]] - g.Centroid[e]));
    }
  }
  return frames;
}

std::vector<Emitter> MakeEmitters(
  const SceneMesh& mesh, const SceneGeometry& g, const std::vector<Vec3>& emission, int solutions)
{
  std::vector<int> slot(g.PatchElements.size(), -1);
  std::vector<Emitter> emitters;
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    if (g.Enclosed[e] || g.Area[e] <= 0 || !Emits(emission, e, solutions))
    {
      continue;
    }
    int& s = slot[g.ElementPatch[e]];
    if (s < 0)
    {
      s = static_cast<int>(emitters.size());
      emitters.emplace_back();
    }
    emitters[s].Elements.push_back(e);
    AddTriangles(mesh, g, e, emitters[s]);
  }
  for (Emitter& emitter : emitters)
  {
    double area = 0;
    for (int e : emitter.Elements)
    {
      emitter.Centre += g.Centroid[e] * g.Area[e];
      emitter.Normal += g.Normal[e] * g.Area[e];
      area += g.Area[e];
    }
    emitter.Centre = emitter.Centre * (1.0 / area);
    emitter.Normal = Normalized(emitter.Normal);
    for (const Vec3& corner : emitter.Triangles)
    {
      emitter.Radius = std::max(emitter.Radius, Norm(corner - emitter.Centre));
    }
    for (int e : emitter.Elements)
    {
      emitter.Planar = emitter.Planar && Dot(g.Normal[e], emitter.Normal) > 1 - 1e-9;
    }
    for (double& c : emitter.Cdf)
    {
      c /= emitter.Cdf.back();
    }
    AddOutline(mesh, emission, solutions, emitter);
  }
  return emitters;
}

Vec3 EmitterPointAt(const Emitter& emitter, int r, int count, const double* xi)
{
  const double u = (r + xi[0]) / count;
  const size_t t = std::min<size_t>(
    std::lower_bound(emitter.Cdf.begin(), emitter.Cdf.end(), u) - emitter.Cdf.begin(), emitter.Cdf.size() - 1);
  const Vec3* abc = &emitter.Triangles[3 * t];
  return TrianglePoint(abc[0], abc[1], abc[2], xi[1], xi[2]);
}

Vec3 EmitterPoint(const Emitter& emitter, int r, int count, SampleStream& random)
{
  double xi[3];
  for (double& x : xi)
  {
    x = random.Next();
  }
  return EmitterPointAt(emitter, r, count, xi);
}

int CoprimeStep(int n)
{
  int step = std::max(1, static_cast<int>(n * 0.618));
  while (std::gcd(step, n) != 1)
  {
    ++step;
  }
  return step;
}

} // namespace gathering
} // namespace radiosity
