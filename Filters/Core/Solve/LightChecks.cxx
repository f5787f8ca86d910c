#include "Solve/LightChecks.h"

#include <cmath>
#include <cstdio>

namespace radiosity
{

namespace
{
/// Of the rays from the light's element centroids (normal, and rings at 30 and 60
/// degrees): the fractions that hit something closer than `near`, anything at all, and a
/// surface's front (the side that takes light); and the share of the light's area whose
/// rays met only backs (it lies behind a wall or past the room).
struct ProbeHits
{
  double Near = 0, Any = 0, Front = 1, Behind = 0;
};

ProbeHits Probe(const SceneGeometry& g, const Visibility& rays, const std::vector<int>& elements, double near)
{
  int hits = 0, any = 0, front = 0, cast = 0;
  double area = 0, behind = 0;
  for (int e : elements)
  {
    int met = 0, fronts = 0;
    const Vec3& n = g.normal[e];
    Vec3 t, b;
    TangentFrame(n, t, b);
    for (int r = 0; r < 9; ++r)
    {
      const double polar = r == 0 ? 0.0 : (r <= 4 ? 0.5236 : 1.0472);
      const double azimuth = 1.5708 * (r % 4) + (r > 4 ? 0.7854 : 0.0);
      const Vec3 d = n * std::cos(polar) + (t * std::cos(azimuth) + b * std::sin(azimuth)) * std::sin(polar);
      Visibility::Hit hit;
      ++cast;
      const bool found = rays.Intersect(g.centroid[e] + n * g.rayLift, d, hit);
      met += found ? 1 : 0;
      hits += found && hit.distance < near ? 1 : 0;
      fronts += found && Dot(g.normal[hit.polygon], d) < 0 ? 1 : 0;
    }
    any += met;
    front += fronts;
    area += g.area[e];
    behind += met > 0 && fronts == 0 ? g.area[e] : 0.0;
  }
  return cast ? ProbeHits{ static_cast<double>(hits) / cast, static_cast<double>(any) / cast,
                  static_cast<double>(front) / cast, area > 0 ? behind / area : 0.0 }
              : ProbeHits();
}
/// True when x lies inside convex element e (in its plane, within `tolerance` of it).
bool InsideElement(const SceneMesh& mesh, const SceneGeometry& g, int e, const Vec3& x, double tolerance)
{
  const Vec3& n = g.normal[e];
  if (std::fabs(Dot(n, x - g.centroid[e])) > tolerance)
  {
    return false;
  }
  const int* ids = mesh.Polygon(e);
  for (int v = 0; v < mesh.PolygonSize(e); ++v)
  {
    const Vec3& a = mesh.points[ids[v]];
    const Vec3& b = mesh.points[ids[(v + 1) % mesh.PolygonSize(e)]];
    if (Dot(Cross(b - a, x - a), n) < 0)
    {
      return false;
    }
  }
  return true;
}

/// An element of another surface whose face the light's element lies on (same plane,
/// parallel, centroid inside it), or -1.
int CoplanarCover(const SceneMesh& mesh, const SceneGeometry& g, int lamp, double tolerance)
{
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    if (mesh.lightId[e] < 0 && std::fabs(Dot(g.normal[e], g.normal[lamp])) > 1 - 1e-9 &&
      InsideElement(mesh, g, e, g.centroid[lamp], tolerance))
    {
      return e;
    }
  }
  return -1;
}
} // namespace

std::vector<std::string> CheckLights(const SceneMesh& mesh, const SceneGeometry& g, const Visibility& rays,
  const std::vector<std::string>& names)
{
  std::vector<std::vector<int>> elements(names.size());
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    if (mesh.lightId[e] >= 0 && mesh.lightId[e] < static_cast<int>(names.size()))
    {
      elements[mesh.lightId[e]].push_back(e);
    }
  }
  std::vector<std::string> messages;
  char text[512];
  for (size_t l = 0; l < names.size(); ++l)
  {
    double area = 0;
    bool closed = !elements[l].empty();
    for (int e : elements[l])
    {
      area += g.area[e];
      closed = closed && g.enclosed[e];
    }
    if (closed)
    {
      std::snprintf(text, sizeof(text),
        "Light '%s' cannot emit: every element of it is closed off (inside an object, or lying in another "
        "surface's plane, such as a lamp drawn in the ceiling; or the surfaces around it face away from "
        "it: check their winding).", names[l].c_str());
      messages.push_back(text);
      continue;
    }
    const int cover = elements[l].empty() ? -1 : CoplanarCover(mesh, g, elements[l][0], 1e-9 * g.sceneDiagonal);
    if (cover >= 0)
    {
      std::snprintf(text, sizeof(text),
        "Light '%s' lies in the plane of a surface it overlaps (element %d): both show in the same place and "
        "the surface under the lamp still takes light. Move the lamp a little in front of it.", names[l].c_str(), cover);
      messages.push_back(text);
    }
    const double near = 0.05 * std::sqrt(area);
    const ProbeHits probe = elements[l].empty() ? ProbeHits{ 0, 1 } : Probe(g, rays, elements[l], near);
    if (probe.Any == 0)
    {
      std::snprintf(text, sizeof(text),
        "Light '%s' faces away from every surface: none of its probe rays meets the scene, so its light leaves "
        "it. Is it wound the wrong way (its front is the right-hand side of its points' order)?", names[l].c_str());
      messages.push_back(text);
    }
    if (probe.Any > 0 && probe.Front == 0)
    {
      std::snprintf(text, sizeof(text),
        "Light '%s' lights nothing: every probe ray from it meets the back of a surface, which takes no light. "
        "Is it outside the room (above the ceiling, behind a wall, in another unit than the scene), or do the "
        "surfaces around it face away from it?", names[l].c_str());
      messages.push_back(text);
    }
    if (probe.Front > 0 && probe.Behind >= 0.01)
    {
      std::snprintf(text, sizeof(text),
        "Light '%s' lights nothing from %.0f %% of its area: there its probe rays meet only the backs of "
        "surfaces (it reaches through a wall or past the room: is it larger than the ceiling it hangs from?).",
        names[l].c_str(), 100 * probe.Behind);
      messages.push_back(text);
    }
    if (probe.Near > 0.5)
    {
      std::snprintf(text, sizeof(text),
        "Light '%s' faces a surface closer than %.3g (5 %% of its size): most of its light lands there. Is it "
        "wound the wrong way (its front is the right-hand side of its points' order)?", names[l].c_str(), near);
      messages.push_back(text);
    }
  }
  return messages;
}

} // namespace radiosity
