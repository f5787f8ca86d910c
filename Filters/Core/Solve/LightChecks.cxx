#include "Solve/LightChecks.h"

#include "Geometry/FaceContact.h"
#include "Geometry/Polygon.h"

#include <algorithm>
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
    const Vec3& n = g.Normal[e];
    Vec3 t, b;
    TangentFrame(n, t, b);
    for (int r = 0; r < 9; ++r)
    {
      const double polar = r == 0 ? 0.0 : (r <= 4 ? 0.5236 : 1.0472);
      const double azimuth = 1.5708 * (r % 4) + (r > 4 ? 0.7854 : 0.0);
      const Vec3 d = n * std::cos(polar) + (t * std::cos(azimuth) + b * std::sin(azimuth)) * std::sin(polar);
      Visibility::Hit hit;
      ++cast;
      const bool found = rays.Intersect(g.Centroid[e] + n * g.RayLift, d, hit);
      met += found ? 1 : 0;
      hits += found && hit.Distance < near ? 1 : 0;
      // An element closed off (the floor under a box the lamp is in) takes no light either.
      fronts += found && Dot(g.Normal[hit.Polygon], d) < 0 && !g.Enclosed[hit.Polygon] ? 1 : 0;
    }
    any += met;
    front += fronts;
    area += g.Area[e];
    behind += met > 0 && fronts == 0 ? g.Area[e] : 0.0;
  }
  return cast ? ProbeHits{ static_cast<double>(hits) / cast, static_cast<double>(any) / cast,
                  static_cast<double>(front) / cast, area > 0 ? behind / area : 0.0 }
              : ProbeHits();
}
/// The bounds of every element that is no light's: the scene the lights are meant for.
Bounds SurfaceBounds(const SceneMesh& mesh)
{
  Bounds b;
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    b.Add(mesh.LightId[e] < 0 ? ElementBounds(mesh, e) : Bounds());
  }
  return b;
}

/// Empty, or how the light sits apart from the scene's surfaces: far outside their bounds, or
/// larger than all of them together (a lamp given in millimetres in a scene in metres).
std::string Apart(const SceneMesh& mesh, const std::vector<int>& lamp, const Bounds& surfaces)
{
  if (lamp.empty() || surfaces.Lo.x > surfaces.Hi.x)
  {
    return std::string();
  }
  Bounds b;
  for (int e : lamp)
  {
    b.Add(ElementBounds(mesh, e));
  }
  char text[320] = "";
  const Vec3 c = b.Centre(), &lo = surfaces.Lo, &hi = surfaces.Hi;
  Vec3 gap;
  for (int a = 0; a < 3; ++a)
  {
    gap[a] = std::max({ 0.0, b.Lo[a] - hi[a], lo[a] - b.Hi[a] });
  }
  if (Norm(gap) > surfaces.Diagonal()) // just outside (above the ceiling) is said by the probes
  {
    std::snprintf(text, sizeof(text), "lies far outside the scene: its centre (%.4g, %.4g, %.4g) is past the "
      "surfaces' bounds (%.4g..%.4g, %.4g..%.4g, %.4g..%.4g) by more than their size", c.x, c.y, c.z, lo.x, hi.x,
      lo.y, hi.y, lo.z, hi.z);
  }
  else if (b.Diagonal() > surfaces.Diagonal())
  {
    std::snprintf(text, sizeof(text), "is %.4g across, larger than all the other surfaces together (%.4g)",
      b.Diagonal(), surfaces.Diagonal());
  }
  return text;
}

/// An element of another surface whose face the light's element lies on (same plane,
/// parallel, centroid inside it), or -1.
int CoplanarCover(const SceneMesh& mesh, const SceneGeometry& g, int lamp, double tolerance)
{
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    if (mesh.LightId[e] < 0 && std::fabs(Dot(g.Normal[e], g.Normal[lamp])) > 1 - 1e-9 &&
      InsideElement(mesh, g, e, g.Centroid[lamp], tolerance))
    {
      return e;
    }
  }
  return -1;
}
} // namespace

namespace
{
/// What the probe rays from light `name` say of it (none where they find nothing amiss);
/// `apart` (Apart) where it sits far from the scene: then its unit or place, not its
/// winding, is the first suspect.
std::vector<std::string> ProbeMessages(const std::string& name, const ProbeHits& probe, double near,
  const std::string& apart)
{
  const char* n = name.c_str();
  char text[768];
  std::vector<std::string> messages;
  const auto say = [&]() { messages.push_back(text); };
  if (!apart.empty())
  {
    std::snprintf(text, sizeof(text), "Light '%s' %s, and %s. Is it in another unit than the scene, or are its "
      "coordinates off?", n, apart.c_str(), probe.Any == 0 ? "none of its probe rays meets the scene"
        : probe.Front == 0 ? "it lights nothing" : "most of its light lands on a surface right in front of it");
    say();
    return messages;
  }
  if (probe.Any == 0)
  {
    std::snprintf(text, sizeof(text), "Light '%s' faces away from every surface: none of its probe rays meets the "
      "scene, so its light leaves it. Does it face the wrong way (an area light emits along its normal; a "
      "polygon to the right-hand side of its points' order)?", n);
    say();
  }
  if (probe.Any > 0 && probe.Front == 0)
  {
    std::snprintf(text, sizeof(text), "Light '%s' lights nothing: every probe ray from it meets the back of a "
      "surface, which takes no light. Is it outside the room (above the ceiling, behind a wall, in another unit "
      "than the scene), inside a closed object, or do the surfaces around it face away from it?", n);
    say();
  }
  if (probe.Front > 0 && probe.Behind >= 0.01)
  {
    std::snprintf(text, sizeof(text), "Light '%s' lights nothing from %.0f %% of its area: there its probe rays "
      "meet only the backs of surfaces (it reaches through a wall or past the room: is it larger than the ceiling "
      "it hangs from?).", n, 100 * probe.Behind);
    say();
  }
  if (probe.Near > 0.5)
  {
    std::snprintf(text, sizeof(text), "Light '%s' faces a surface closer than %.3g (5 %% of its size): most of its "
      "light lands there. Does it face the wrong way (an area light emits along its normal; a polygon to the "
      "right-hand side of its points' order)?", n, near);
    say();
  }
  return messages;
}

/// Each light's elements (ids past `lights` left out).
std::vector<std::vector<int>> LightElements(const SceneMesh& mesh, size_t lights)
{
  std::vector<std::vector<int>> elements(lights);
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    if (mesh.LightId[e] >= 0 && mesh.LightId[e] < static_cast<int>(lights))
    {
      elements[mesh.LightId[e]].push_back(e);
    }
  }
  return elements;
}
} // namespace

std::vector<std::string> CheckLights(const SceneMesh& mesh, const SceneGeometry& g, const Visibility& rays,
  const std::vector<std::string>& names)
{
  const std::vector<std::vector<int>> elements = LightElements(mesh, names.size());
  const Bounds surfaces = SurfaceBounds(mesh);
  std::vector<std::string> messages;
  char text[768];
  for (size_t l = 0; l < names.size(); ++l)
  {
    double area = 0;
    bool closed = !elements[l].empty();
    for (int e : elements[l])
    {
      area += g.Area[e];
      closed = closed && g.Enclosed[e];
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
    const int cover = elements[l].empty() ? -1 : CoplanarCover(mesh, g, elements[l][0], 1e-9 * g.SceneDiagonal);
    if (cover >= 0)
    {
      std::snprintf(text, sizeof(text),
        "Light '%s' lies in the plane of a surface it overlaps (element %d): both show in the same place and "
        "the surface under the lamp still takes light. Move the lamp a little in front of it.", names[l].c_str(), cover);
      messages.push_back(text);
    }
    const double near = 0.05 * std::sqrt(area);
    const ProbeHits probe = elements[l].empty() ? ProbeHits{ 0, 1 } : Probe(g, rays, elements[l], near);
    const bool astray = probe.Any == 0 || probe.Front == 0 || probe.Near > 0.5;
    for (std::string& said : ProbeMessages(names[l], probe, near, astray ? Apart(mesh, elements[l], surfaces) : ""))
    {
      messages.push_back(std::move(said));
    }
  }
  return messages;
}

} // namespace radiosity
