#include "Solve/FinalGather.h"
#include "Solve/IrradianceCache.h"

#include "Base/SampleStream.h"
#include "Base/WorkerPool.h"
#include "Geometry/FormFactor.h"
#include "Geometry/PointAverages.h"
#include "Geometry/Polygon.h"
#include "Lights/PointShading.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

namespace radiosity
{
namespace
{
/// Where and how a point is evaluated: the mean of the elements around it.
struct PointFrame
{
  Vec3 Origin; ///< the point, a quarter of the way into its elements and a hair off them
  Vec3 Normal;
  /// An edge of its first element, so the gather's directions turn with the scene and the
  /// answer does not depend on its placement.
  Vec3 Edge;
  Vec3 Reflectance;
  bool Used = false;
  /// For an element's frame, the element: its rays then start at points spread over it,
  /// so they estimate its mean (a centroid overrates an element facing a lamp up close).
  int Element = -1;
  double Radius = 0; ///< for an element's frame, its farthest corner from the centroid
};

/// An emitter this many element radii away (from its bounding sphere) lights an element all
/// but linearly: the sweep takes its mean at the centre (Gather::SpreadDirectLight).
const double kFar = 10.0;

/// An emitting patch: its elements' loops for Lambert's formula, its fan triangles for
/// shadow-ray ends, its emission per solution.
struct Emitter
{
  std::vector<int> Elements;
  std::vector<Vec3> Triangles; ///< a, b, c per fan triangle, each lifted off the surface
  std::vector<double> Cdf;     ///< cumulative area fraction per triangle
  Vec3 Centre, Normal;
  double Radius = 0;
  bool Planar = true;
  /// Where every element emits alike: the patch's outline (start, end pairs; the shared
  /// edges cancel), so Lambert's formula costs its outline, not its elements (a lamp meshed
  /// fine is thousands), and that exitance per solution.
  std::vector<Vec3> Outline;
  std::vector<Vec3> Exitance;
};

/// Points at one place (equal coordinates) on one smooth surface of one material: the
/// corners a curved model's triangles each hold of their own (the CGAL bunny: 237,203
/// points for 89,163 elements). Each maps to the first of them whose elements' normals
/// agree with its own within 30 degrees, and that one is gathered for all (bunny: its solve
/// 26.7 s -> 19.9 s); a crease or another material keeps its own. -1 for points no polygon
/// uses.
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

/// Each representative point's frame from the elements around it (area-weighted, its own
/// only: the copies' elements, averaged in, could put a saddle's point under one of them),
/// and its emission per solution into `pointEmission`; other points stay unused.
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

/// Each open element as a frame of its own, for a sweep over the element solution (its rays
/// start at points spread over it, Gather::Spot).
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

bool Emits(const std::vector<Vec3>& emission, int e, int solutions)
{
  for (int m = 0; m < solutions; ++m)
  {
    const Vec3& v = emission[static_cast<size_t>(e) * solutions + m];
    if (v.x > 0 || v.y > 0 || v.z > 0)
    {
      return true;
    }
  }
  return false;
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
  std::map<std::pair<int, int>, int> edges;
  for (int e : out.Elements)
  {
    const int* ids = mesh.Polygon(e);
    const int n = mesh.PolygonSize(e);
    for (int v = 0; v < n; ++v)
    {
      const int a = ids[v], b = ids[(v + 1) % n];
      auto reverse = edges.find({ b, a });
      if (reverse != edges.end() && reverse->second > 0)
      {
        --reverse->second;
      }
      else
      {
        ++edges[{ a, b }];
      }
    }
  }
  for (const auto& edge : edges)
  {
    for (int c = 0; c < edge.second; ++c)
    {
      out.Outline.push_back(mesh.Points[edge.first.first]);
      out.Outline.push_back(mesh.Points[edge.first.second]);
    }
  }
  out.Exitance.assign(emission.begin() + first, emission.begin() + first + solutions);
}

/// The emitting, unenclosed elements grouped by patch.
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

/// A point of stratum r of `count` over the emitter, by area, from three numbers in [0, 1).
Vec3 EmitterPointAt(const Emitter& emitter, int r, int count, const double* xi)
{
  const double u = (r + xi[0]) / count;
  const size_t t = std::min<size_t>(
    std::lower_bound(emitter.Cdf.begin(), emitter.Cdf.end(), u) - emitter.Cdf.begin(), emitter.Cdf.size() - 1);
  const Vec3* abc = &emitter.Triangles[3 * t];
  return TrianglePoint(abc[0], abc[1], abc[2], xi[1], xi[2]);
}

/// The same, drawing its numbers from `random`.
Vec3 EmitterPoint(const Emitter& emitter, int r, int count, SampleStream& random)
{
  double xi[3];
  for (double& x : xi)
  {
    x = random.Next();
  }
  return EmitterPointAt(emitter, r, count, xi);
}

/// A step coprime to n near n times the golden ratio's fraction: r -> (r * step + o) % n
/// visits every stratum once, far from the order it is given in.
int CoprimeStep(int n)
{
  int step = std::max(1, static_cast<int>(n * 0.618));
  while (std::gcd(step, n) != 1)
  {
    ++step;
  }
  return step;
}

/// How far a point's gather rays went before they hit (misses went infinitely far): the
/// irradiance cache's reach from them.
struct HitDistances
{
  double InverseSum = 0;
  double Nearest = std::numeric_limits<double>::infinity();
  int Backs = 0; ///< hits on back faces
  /// Where given, each ray's direction, distance and what it brought back, for a record's
  /// gradients (IrradianceGradients).
  StratifiedRays* Samples = nullptr;
  void Add(double distance)
  {
    InverseSum += 1.0 / std::max(distance, 1e-300);
    Nearest = std::min(Nearest, distance);
  }
};

/// The whole state of one gather, shared read-only by the threads.
class Gather
{
public:
  /// Evaluates `frames` (with their emission, [frame * solutions + m]; both held by
  /// reference, as are the others) against the element solution `radiosity`; `salt` draws
  /// other numbers for another pass over the same frames.
  Gather(const SceneMesh& mesh, const SceneGeometry& g, const Visibility& rays, const std::vector<Vec3>& emission,
    const std::vector<Vec3>& radiosity, int solutions, const std::vector<Emitter>& emitters,
    const std::vector<PointFrame>& frames, const std::vector<Vec3>& frameEmission, int gatherRays, int lightRays, bool shadows,
    std::uint64_t salt, const GatherSettings& settings)
    : Mesh(mesh)
    , G(g)
    , Rays(rays)
    , Emission(emission)
    , Radiosity(radiosity)
    , S(solutions)
    , Side(std::max(0, static_cast<int>(std::sqrt(static_cast<double>(gatherRays)))))
    , LightRays(std::max(1, lightRays))
    , Shadows(shadows)
    , RayStep(CoprimeStep(std::max(1, Side * Side)))
    , LightStep(CoprimeStep(std::max(1, lightRays)))
    , Salt(salt)
    , Frames(frames)
    , PointEmission(frameEmission)
    , Emitters(emitters)
    , FirstPoint(settings.FirstPointSolution)
    , PointLightsCombined(settings.PointLightsCombined)
  {
    if (settings.PointLights)
    {
      for (PointLight light : *settings.PointLights)
      {
        // A light's own solution is white (relighting colors it); a combined one is not.
        light.Color = PointLightsCombined ? light.Color : Vec3{ 1, 1, 1 };
        PointLights.push_back(light);
      }
    }
  }

  /// Point p's values into radiosity[p * S ...], direct[p * S ...] and the light arriving,
  /// irradiance[p * S ...]; returns its rays.
  long long Evaluate(size_t p, Vec3* radiosity, Vec3* direct, Vec3* irradiance, std::vector<Vec3>& scratch,
    char& hidden) const
  {
    if (!Frames[p].Used)
    {
      return 0;
    }
    std::vector<Vec3> arriving(S), gathered(S);
    HitDistances hits;
    long long rays = 0;
    if (Known && (*Known)[p])
    {
      std::copy(Given->begin() + p * S, Given->begin() + (p + 1) * S, arriving.begin());
    }
    else
    {
      rays += DirectAt(p, arriving.data(), scratch);
    }
    rays += IndirectAt(p, gathered.data(), hits);
    hidden = SeesBacks(hits);
    Compose(p, arriving.data(), gathered.data(), radiosity, direct, irradiance);
    return rays;
  }

  /// The direct light arriving at point p (before its reflectance), per solution, into
  /// arriving[0 .. S); returns the shadow rays cast.
  long long DirectAt(size_t p, Vec3* arriving, std::vector<Vec3>& scratch) const
  {
    const PointFrame& f = Frames[p];
    std::vector<Vec3> sum(S);
    const long long rays = f.Element < 0 ? DirectLight(p, f, sum, scratch) : SpreadDirectLight(p, f, sum, scratch);
    std::copy(sum.begin(), sum.end(), arriving);
    return rays;
  }

  /// The interreflection arriving at point p, per solution, into gathered[0 .. S), and how
  /// far its rays went; returns the rays cast.
  long long IndirectAt(size_t p, Vec3* gathered, HitDistances& hits) const
  {
    std::vector<Vec3> sum(S);
    const long long rays = Interreflection(p, Frames[p], sum, hits);
    std::copy(sum.begin(), sum.end(), gathered);
    return rays;
  }

  /// Mostly back faces: behind something resting on the point's surface (see FillHidden).
  bool SeesBacks(const HitDistances& hits) const { return 2 * hits.Backs > Side * Side; }

  /// Point p's emission plus what arrives, reflected: radiosity, its direct part and the
  /// irradiance, per solution.
  void Compose(size_t p, const Vec3* arriving, const Vec3* gathered, Vec3* radiosity, Vec3* direct,
    Vec3* irradiance) const
  {
    const Vec3& rho = Frames[p].Reflectance;
    for (int m = 0; m < S; ++m)
    {
      direct[m] = PointEmission[p * S + m] + Times(rho, arriving[m]);
      radiosity[m] = direct[m] + Times(rho, gathered[m]);
      irradiance[m] = arriving[m] + gathered[m];
    }
  }

  const PointFrame& Frame(size_t p) const { return Frames[p]; }
  const std::vector<PointFrame>& AllFrames() const { return Frames; }

  /// Frames with `known` set take `given` as their direct light instead of casting rays.
  void TakeArriving(const std::vector<Vec3>* given, const std::vector<char>* known)
  {
    Given = given;
    Known = known;
  }
  int GatherRays() const { return Side * Side; }
  size_t Points() const { return Frames.size(); }

private:
  /// Irradiance from every emitter: Lambert's formula per element, times the fraction of
  /// stratified shadow rays to the emitter that arrive.
  long long DirectLight(size_t p, const PointFrame& f, std::vector<Vec3>& out, std::vector<Vec3>& scratch) const
  {
    long long rays = 0;
    std::vector<Vec3> loop, unshadowed(S);
    for (size_t k = 0; k < Emitters.size(); ++k)
    {
      const Emitter& em = Emitters[k];
      if (Behind(em, f.Origin, f.Normal) || !Unshadowed(em, f.Origin, f.Normal, unshadowed, loop, scratch))
      {
        continue;
      }
      const double seen = Shadows ? SeenFraction(p, k, f.Origin, rays) : 1.0;
      for (int m = 0; m < S; ++m)
      {
        out[m] += unshadowed[m] * seen;
      }
    }
    return rays + PointLightsAt(f.Origin, f.Normal, 1.0, out);
  }

  /// Adds `weight` times the direct light of each point light at x (already off its
  /// surface) to its solution; returns the shadow rays cast.
  long long PointLightsAt(const Vec3& x, const Vec3& normal, double weight, std::vector<Vec3>& out) const
  {
    for (size_t i = 0; i < PointLights.size(); ++i)
    {
      out[PointLightsCombined ? FirstPoint : FirstPoint + i] += PointIrradianceAt(PointLights[i], x, normal, Rays, 0.0) * weight;
    }
    return static_cast<long long>(PointLights.size());
  }

  /// The element mean of the irradiance from every emitter: at each of LightRays points
  /// spread over the element, Lambert's formula to the emitter and one shadow ray to it.
  long long SpreadDirectLight(size_t p, const PointFrame& f, std::vector<Vec3>& out, std::vector<Vec3>& scratch) const
  {
    long long rays = 0;
    std::vector<Vec3> loop, unshadowed(S);
    // An emitter far away against the element's size lights it all but linearly, so its
    // mean is the value at the centre: Lambert's formula once, the spread points casting
    // only their shadow rays (a million small elements: four formulas an emitter become one).
    thread_local std::vector<Vec3> atCentre;
    thread_local std::vector<char> far;
    atCentre.assign(Emitters.size() * S, Vec3());
    far.assign(Emitters.size(), 0);
    for (size_t k = 0; k < Emitters.size(); ++k)
    {
      const Emitter& em = Emitters[k];
      far[k] = Norm(em.Centre - f.Origin) - em.Radius > kFar * f.Radius;
      if (far[k] && !Behind(em, f.Origin, f.Normal) && Unshadowed(em, f.Origin, f.Normal, unshadowed, loop, scratch))
      {
        std::copy(unshadowed.begin(), unshadowed.end(), atCentre.begin() + k * S);
      }
    }
    SampleStream spots(p, 0x5a3d, Salt);
    for (int r = 0; r < LightRays; ++r)
    {
      const Vec3 x = Spot(f, r, LightRays, spots);
      for (size_t k = 0; k < Emitters.size(); ++k)
      {
        const Emitter& em = Emitters[k];
        if (far[k] ? IsZero(&atCentre[k * S]) : Behind(em, x, f.Normal))
        {
          continue;
        }
        const bool any = far[k] || Unshadowed(em, x, f.Normal, unshadowed, loop, scratch);
        SampleStream random(p * LightRays + r, k, 0x5eed + Salt);
        const int end = (r * LightStep + 1) % LightRays;
        if (!any || (Shadows && (++rays, Rays.Occluded(x, EmitterPoint(em, end, LightRays, random)))))
        {
          continue;
        }
        const Vec3* value = far[k] ? &atCentre[k * S] : unshadowed.data();
        for (int m = 0; m < S; ++m)
        {
          out[m] += value[m] * (1.0 / LightRays);
        }
      }
      rays += PointLightsAt(x, f.Normal, 1.0 / LightRays, out);
    }
    return rays;
  }

  /// The emitter wholly behind the point's surface, or the point behind a flat emitter.
  static bool Behind(const Emitter& em, const Vec3& x, const Vec3& normal)
  {
    return Dot(em.Centre - x, normal) < -em.Radius || (em.Planar && Dot(x - em.Centre, em.Normal) <= 0);
  }

  bool IsZero(const Vec3* values) const
  {
    for (int m = 0; m < S; ++m)
    {
      if (values[m].x != 0 || values[m].y != 0 || values[m].z != 0)
      {
        return false;
      }
    }
    return true;
  }

  /// Where ray r of `count` starts: the point itself, or for an element's frame the r-th
  /// of `count` points stratified by area over the element's fan triangles.
  Vec3 Spot(const PointFrame& f, int r, int count, SampleStream& random) const
  {
    if (f.Element < 0)
    {
      return f.Origin;
    }
    const int* ids = Mesh.Polygon(f.Element);
    const int n = Mesh.PolygonSize(f.Element);
    const Vec3& a = Mesh.Points[ids[0]];
    double total = 0;
    for (int v = 1; v + 1 < n; ++v)
    {
      total += Norm(Cross(Mesh.Points[ids[v]] - a, Mesh.Points[ids[v + 1]] - a));
    }
    double u = (r + random.Next()) / count * total;
    int v = 1;
    for (; v + 2 < n; ++v)
    {
      const double part = Norm(Cross(Mesh.Points[ids[v]] - a, Mesh.Points[ids[v + 1]] - a));
      if (u < part)
      {
        break;
      }
      u -= part;
    }
    const double s = random.Next(), q = random.Next();
    return TrianglePoint(a, Mesh.Points[ids[v]], Mesh.Points[ids[v + 1]], s, q) + f.Normal * G.RayLift;
  }

  /// The irradiance the emitter gives dA at x with `normal` where nothing blocks it, per
  /// solution; false where it gives none. By the outline where every corner of it is in
  /// front of x (no clipping needed), else element by element.
  bool Unshadowed(const Emitter& em, const Vec3& x, const Vec3& normal, std::vector<Vec3>& out,
    std::vector<Vec3>& loop, std::vector<Vec3>& scratch) const
  {
    std::fill(out.begin(), out.end(), Vec3());
    bool whole = !em.Outline.empty();
    for (size_t i = 0; whole && i < em.Outline.size(); ++i)
    {
      whole = Dot(em.Outline[i] - x, normal) > 0;
    }
    if (whole)
    {
      const double factor =
        EdgeSetFormFactor(x, normal, em.Outline.data(), static_cast<int>(em.Outline.size() / 2));
      for (int m = 0; m < S; ++m)
      {
        out[m] = em.Exitance[m] * factor;
      }
      return factor > 0;
    }
    bool any = false;
    for (int e : em.Elements)
    {
      const double factor = ElementFactor(e, x, normal, loop, scratch);
      for (int m = 0; m < S && factor > 0; ++m)
      {
        out[m] += Emission[static_cast<size_t>(e) * S + m] * factor;
      }
      any = any || factor > 0;
    }
    return any;
  }

  /// F(dA at x with `normal` -> element e), 0 where x is behind the element.
  double ElementFactor(int e, const Vec3& x, const Vec3& normal, std::vector<Vec3>& loop,
    std::vector<Vec3>& scratch) const
  {
    if (Dot(x - G.Centroid[e], G.Normal[e]) <= 0)
    {
      return 0.0;
    }
    const int* ids = Mesh.Polygon(e);
    loop.clear();
    for (int v = 0; v < Mesh.PolygonSize(e); ++v)
    {
      loop.push_back(Mesh.Points[ids[v]]);
    }
    return PointToPolygonFormFactor(x, normal, loop.data(), static_cast<int>(loop.size()), scratch);
  }

  /// The fraction of LightRays stratified shadow rays to emitter k that arrive. Four strata
  /// spread over the emitter go first; where they agree (a room away, or in full view) the
  /// others are not cast: most of a building's points see a lamp wholly or not at all.
  double SeenFraction(size_t p, size_t k, const Vec3& from, long long& rays) const
  {
    // Every stratum's numbers are drawn, its point made only where its ray is cast: most
    // points stop after the first four.
    SampleStream random(p, k, 0x5eed + Salt);
    thread_local std::vector<double> xi;
    xi.resize(3 * static_cast<size_t>(LightRays));
    for (double& x : xi)
    {
      x = random.Next();
    }
    auto arrives = [&](int r) { return !Rays.Occluded(from, EmitterPointAt(Emitters[k], r, LightRays, &xi[3 * r])); };
    const int step = std::max(1, LightRays / 4);
    int seen = 0, cast = 0;
    for (int r = 0; r < LightRays; r += step, ++cast)
    {
      seen += arrives(r) ? 1 : 0;
    }
    rays += cast;
    if (seen == 0 || seen == cast || cast == LightRays)
    {
      return static_cast<double>(seen) / cast;
    }
    for (int r = 0; r < LightRays; ++r)
    {
      seen += r % step != 0 && arrives(r) ? 1 : 0;
    }
    rays += LightRays - cast;
    return static_cast<double>(seen) / LightRays;
  }

  /// Irradiance from the element solution less its emission (the emitters were taken
  /// directly), along Side x Side stratified cosine rays; back faces send nothing.
  long long Interreflection(size_t p, const PointFrame& f, std::vector<Vec3>& out, HitDistances& hits) const
  {
    if (Side == 0)
    {
      return 0;
    }
    Vec3 t = Normalized(f.Edge - f.Normal * Dot(f.Edge, f.Normal)), b;
    if (Norm(t) == 0)
    {
      TangentFrame(f.Normal, t, b);
    }
    b = Cross(f.Normal, t);
    if (hits.Samples)
    {
      hits.Samples->Reset(Side, S);
      hits.Samples->T = t;
      hits.Samples->B = b;
    }
    SampleStream random(p, 0x9a7e, Salt);
    Visibility::Hit hit;
    for (int i = 0; i < Side; ++i)
    {
      for (int j = 0; j < Side; ++j)
      {
        const double u = (i + random.Next()) / Side, phi = 2 * M_PI * (j + random.Next()) / Side;
        const double r = std::sqrt(u);
        const Vec3 d = t * (r * std::cos(phi)) + b * (r * std::sin(phi)) + f.Normal * std::sqrt(1 - u);
        const int start = ((i * Side + j) * RayStep + 1) % (Side * Side);
        const size_t cell = static_cast<size_t>(i) * Side + j;
        if (hits.Samples)
        {
          hits.Samples->U[cell] = u;
          hits.Samples->Phi[cell] = phi;
        }
        if (!Rays.Intersect(Spot(f, start, Side * Side, random), d, hit) || hit.Polygon < 0)
        {
          continue;
        }
        hits.Add(hit.Distance);
        if (hits.Samples)
        {
          hits.Samples->Distance[cell] = hit.Distance;
        }
        if (Dot(G.Normal[hit.Polygon], d) >= 0)
        {
          ++hits.Backs;
          continue;
        }
        const size_t at = static_cast<size_t>(hit.Polygon) * S;
        for (int m = 0; m < S; ++m)
        {
          out[m] += Radiosity[at + m] - Emission[at + m];
        }
        for (int m = 0; m < S && hits.Samples; ++m)
        {
          hits.Samples->Values[cell * S + m] = Radiosity[at + m] - Emission[at + m];
        }
      }
    }
    const double inv = 1.0 / (Side * Side);
    for (int m = 0; m < S; ++m)
    {
      out[m] = out[m] * inv;
    }
    return static_cast<long long>(Side) * Side;
  }

  const SceneMesh& Mesh;
  const SceneGeometry& G;
  const Visibility& Rays;
  const std::vector<Vec3>& Emission;
  const std::vector<Vec3>& Radiosity;
  const int S;
  const int Side;
  const int LightRays;
  const bool Shadows;
  /// The start stratum of a ray over an element is its direction's (or its lamp point's)
  /// stratum shuffled by these steps: paired as given, near-normal rays would all start on
  /// one half of a quad and the shadow rays' ends would follow their starts.
  const int RayStep, LightStep;
  const std::uint64_t Salt;
  const std::vector<PointFrame>& Frames;
  const std::vector<Vec3>& PointEmission;
  /// Where given (Known[p] set), frame p's direct light arriving, [p * S + m]: a sweep's
  /// small elements take their corners' (KnownArriving).
  const std::vector<Vec3>* Given = nullptr;
  const std::vector<char>* Known = nullptr;
  const std::vector<Emitter>& Emitters;
  std::vector<PointLight> PointLights; ///< white where each is its own solution
  const int FirstPoint;
  const bool PointLightsCombined;
};
} // namespace

namespace
{
/// Each point that shares its representative's place and surface takes its values.
void CopyToCopies(const std::vector<int>& rep, int solutions, GatheredPoints& out)
{
  for (size_t p = 0; p < rep.size(); ++p)
  {
    const int r = rep[p];
    for (int m = 0; m < solutions && r >= 0 && static_cast<size_t>(r) != p; ++m)
    {
      out.Radiosity[p * solutions + m] = out.Radiosity[static_cast<size_t>(r) * solutions + m];
      out.Direct[p * solutions + m] = out.Direct[static_cast<size_t>(r) * solutions + m];
      out.Irradiance[p * solutions + m] = out.Irradiance[static_cast<size_t>(r) * solutions + m];
    }
    if (r >= 0)
    {
      out.Hidden[p] = out.Hidden[r];
    }
  }
}

/// Elements a sweep does not evaluate (enclosed, or of no area) keep what they had, the
/// solver's value (a lamp shut in a box keeps its emission).
void KeepUnswept(const SceneMesh& mesh, const SceneGeometry& g, const std::vector<Vec3>& before, int solutions,
  GatheredPoints& swept)
{
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    for (int m = 0; m < solutions && (g.Enclosed[e] || g.Area[e] <= 0); ++m)
    {
      const size_t at = static_cast<size_t>(e) * solutions + m;
      swept.Radiosity[at] = before[at];
      swept.Direct[at] = before[at];
    }
  }
}

/// Sums `values` over the ranks in place (each rank filled only its own points).
void SumOverRanks(Collective& ranks, std::vector<Vec3>& values)
{
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 is three doubles");
  ranks.Sum(reinterpret_cast<double*>(values.data()), 3 * values.size());
}

/// Calls evaluate(i, scratch) for i in [0, count) on the pool (on several ranks each every
/// `Ranks()`-th item: the caller sums what they wrote, and as each item is computed by one
/// rank alone the sum is the serial answer bit for bit), in blocks between which `progress`
/// may stop it (all ranks agree). Returns the rays evaluate reported, summed over items on
/// this rank, or -1 where it was stopped.
template <typename Evaluate>
long long ForEachItem(size_t count, const WorkerPool& pool, Collective& ranks,
  const std::function<bool(double)>& progress, double from, double to, const Evaluate& evaluate)
{
  const size_t rank = static_cast<size_t>(ranks.Rank()), share = static_cast<size_t>(ranks.Ranks());
  const int blocks = static_cast<int>(std::min<size_t>(64, std::max<size_t>(1, count / 256)));
  std::vector<long long> itemRays(count, 0);
  for (int block = 0; block < blocks; ++block)
  {
    const size_t first = count * block / blocks, last = count * (block + 1) / blocks;
    pool.For(static_cast<int>(last - first), 16, [&](int begin, int end) {
      std::vector<Vec3> scratch;
      for (int i = begin; i < end; ++i)
      {
        const size_t item = first + i;
        if (item % share == rank)
        {
          itemRays[item] = evaluate(item, scratch);
        }
      }
    });
    double stop = progress && !progress(from + (to - from) * (block + 1) / blocks) && block + 1 < blocks ? 1 : 0;
    ranks.Sum(&stop, 1);
    if (stop > 0)
    {
      return -1;
    }
  }
  return std::accumulate(itemRays.begin(), itemRays.end(), 0LL);
}

/// Evaluates every point of `gather` (each rank its share, then summed), in blocks between
/// which `progress` may stop it.
GatheredPoints Run(const Gather& gather, int solutions, const WorkerPool& pool, const ProcessGroup& group,
  const std::function<bool(double)>& progress, double from, double to)
{
  Collective ranks(group);
  GatheredPoints out;
  const size_t points = gather.Points();
  out.Radiosity.assign(points * solutions, Vec3());
  out.Direct.assign(points * solutions, Vec3());
  out.Irradiance.assign(points * solutions, Vec3());
  out.Hidden.assign(points, 0);
  const long long rays = ForEachItem(points, pool, ranks, progress, from, to, [&](size_t p, std::vector<Vec3>& scratch) {
    return gather.Evaluate(
      p, &out.Radiosity[p * solutions], &out.Direct[p * solutions], &out.Irradiance[p * solutions], scratch, out.Hidden[p]);
  });
  out.Aborted = rays < 0;
  double total = static_cast<double>(std::max(0LL, rays));
  if (!out.Aborted && ranks.Distributed())
  {
    SumOverRanks(ranks, out.Radiosity);
    SumOverRanks(ranks, out.Direct);
    SumOverRanks(ranks, out.Irradiance);
    std::vector<double> hidden(out.Hidden.begin(), out.Hidden.end());
    ranks.Sum(hidden);
    ranks.Sum(&total, 1);
    for (size_t p = 0; p < points; ++p)
    {
      out.Hidden[p] = hidden[p] > 0 ? 1 : 0;
    }
  }
  out.Rays = static_cast<long long>(total);
  return out;
}

/// The gathered interreflection of `list`'s points as irradiance-cache records (Point: the
/// index into `list`'s own list of points, `items`), each rank its share; their values go
/// to `gathered` by point, their gradients (IrradianceGradients: 3 translation then 3
/// rotation per solution) after `gradients`' end, in the records' order.
std::vector<CacheRecord> GatherRecords(const Gather& gather, const std::vector<int>& items,
  const std::vector<int>& list, double accuracy, const WorkerPool& pool, Collective& ranks,
  const std::function<bool(double)>& progress, double from, double to, std::vector<Vec3>& gathered,
  std::vector<Vec3>& gradients, long long& rays)
{
  const int S = static_cast<int>(gathered.size() / items.size());
  const size_t per = 6 * static_cast<size_t>(S);
  std::vector<Vec3> values(list.size() * S), slopes(list.size() * per);
  std::vector<double> reach(list.size(), 0.0);
  const long long cast = ForEachItem(list.size(), pool, ranks, progress, from, to, [&](size_t i, std::vector<Vec3>&) {
    thread_local StratifiedRays samples;
    HitDistances hits;
    hits.Samples = &samples;
    const long long n = gather.IndirectAt(items[list[i]], &values[i * S], hits);
    IrradianceGradients(samples, &slopes[i * per], &slopes[i * per + 3 * S]);
    // A record that saw mostly back faces holds for nobody else (FillHidden mends it).
    reach[i] = gather.SeesBacks(hits) ? -1.0 : RecordReach(accuracy, hits.InverseSum, gather.GatherRays(), hits.Nearest);
    return n;
  });
  if (cast < 0)
  {
    return {};
  }
  double total = static_cast<double>(cast);
  if (ranks.Distributed())
  {
    SumOverRanks(ranks, values);
    SumOverRanks(ranks, slopes);
    ranks.Sum(reach);
    ranks.Sum(&total, 1);
  }
  rays += static_cast<long long>(total);
  std::vector<CacheRecord> records(list.size());
  for (size_t i = 0; i < list.size(); ++i)
  {
    const PointFrame& f = gather.Frame(items[list[i]]);
    records[i] = { list[i], f.Origin, f.Normal, std::max(0.0, reach[i]) };
    std::copy(values.begin() + i * S, values.begin() + (i + 1) * S, gathered.begin() + static_cast<size_t>(list[i]) * S);
  }
  gradients.insert(gradients.end(), slopes.begin(), slopes.end());
  return records;
}

/// Each point that did not gather for itself (own[i] 0) takes the weighted mean of the
/// records that reach it, each moved to the point by its gradients (`gradients`, 6 per
/// solution, at slot[record's point]).
void Interpolate(const IrradianceCache& cache, const std::vector<char>& own, const std::vector<Vec3>& origins,
  const std::vector<Vec3>& normals, const std::vector<int>& slot, const std::vector<Vec3>& gradients, int solutions,
  const WorkerPool& pool, std::vector<Vec3>& gathered)
{
  const size_t per = 6 * static_cast<size_t>(solutions);
  pool.For(static_cast<int>(own.size()), 256, [&](int begin, int end) {
    std::vector<std::pair<int, double>> weights;
    for (int i = begin; i < end; ++i)
    {
      const double sum = own[i] ? 0.0 : cache.Weights(origins[i], normals[i], weights);
      for (int m = 0; m < solutions && sum > 0; ++m)
      {
        Vec3 value;
        for (const auto& w : weights)
        {
          const CacheRecord& r = cache.Records()[w.first];
          const Vec3 moved = origins[i] - r.Origin, turned = Cross(r.Normal, normals[i]);
          const Vec3* slope = &gradients[slot[r.Point] * per + 3 * m];
          const Vec3* turn = slope + 3 * solutions;
          const Vec3 change{ Dot(slope[0], moved) + Dot(turn[0], turned), Dot(slope[1], moved) + Dot(turn[1], turned),
            Dot(slope[2], moved) + Dot(turn[2], turned) };
          value += (gathered[static_cast<size_t>(r.Point) * solutions + m] + change) * w.second;
        }
        gathered[static_cast<size_t>(i) * solutions + m] = value * (1.0 / sum);
      }
    }
  });
}

/// The direct light arriving at each of `items`' points, into arriving[p * S ...] (each
/// rank its share, then summed); returns the rays cast, -1 where it was stopped.
long long PointsDirect(const Gather& gather, const std::vector<int>& items, int solutions, const WorkerPool& pool,
  Collective& ranks, const std::function<bool(double)>& progress, double from, double to, std::vector<Vec3>& arriving)
{
  const long long cast = ForEachItem(items.size(), pool, ranks, progress, from, to,
    [&](size_t i, std::vector<Vec3>& scratch) { return gather.DirectAt(items[i], &arriving[items[i] * solutions], scratch); });
  if (cast < 0)
  {
    return cast;
  }
  double total = static_cast<double>(cast);
  if (ranks.Distributed())
  {
    SumOverRanks(ranks, arriving);
    ranks.Sum(&total, 1);
  }
  return static_cast<long long>(total);
}

/// The points' values from their direct light `arriving` and their gathered interreflection
/// (`gathered`, [i * S + m] for items[i]).
void ComposePoints(const Gather& gather, const std::vector<int>& items, int solutions,
  const std::vector<Vec3>& arriving, const std::vector<Vec3>& gathered, GatheredPoints& out)
{
  const size_t points = gather.Points();
  out.Radiosity.assign(points * solutions, Vec3());
  out.Direct.assign(points * solutions, Vec3());
  out.Irradiance.assign(points * solutions, Vec3());
  for (size_t i = 0; i < items.size(); ++i)
  {
    const size_t p = items[i];
    gather.Compose(p, &arriving[p * solutions], &gathered[i * solutions], &out.Radiosity[p * solutions],
      &out.Direct[p * solutions], &out.Irradiance[p * solutions]);
  }
}

/// Every point gathers its own interreflection.
GatheredPoints EveryPointGathers(const Gather& gather, const std::vector<int>& items, int solutions,
  const std::vector<Vec3>& arriving, const WorkerPool& pool, Collective& ranks,
  const std::function<bool(double)>& progress, double from, double to)
{
  GatheredPoints out;
  std::vector<Vec3> gathered(items.size() * solutions);
  std::vector<double> hidden(items.size(), 0.0);
  const long long cast = ForEachItem(items.size(), pool, ranks, progress, from, to, [&](size_t i, std::vector<Vec3>&) {
    HitDistances hits;
    const long long n = gather.IndirectAt(items[i], &gathered[i * solutions], hits);
    hidden[i] = gather.SeesBacks(hits) ? 1 : 0;
    return n;
  });
  out.Aborted = cast < 0;
  if (out.Aborted)
  {
    return out;
  }
  double total = static_cast<double>(cast);
  if (ranks.Distributed())
  {
    SumOverRanks(ranks, gathered);
    ranks.Sum(hidden);
    ranks.Sum(&total, 1);
  }
  out.Rays = static_cast<long long>(total);
  out.Hidden.assign(gather.Points(), 0);
  for (size_t i = 0; i < items.size(); ++i)
  {
    out.Hidden[items[i]] = hidden[i] > 0 ? 1 : 0;
  }
  ComposePoints(gather, items, solutions, arriving, gathered, out);
  return out;
}

/// The points' interreflection shared through an irradiance cache (IrradianceCache.h):
/// gathered at the points PlaceRecords picks and interpolated between them elsewhere.
/// Records that saw mostly back faces are the hidden points.
GatheredPoints PointsShareGathers(const Gather& gather, const std::vector<int>& items, int solutions,
  const std::vector<Vec3>& arriving, double accuracy, const WorkerPool& pool, Collective& ranks,
  const std::function<bool(double)>& progress, double from, double to)
{
  GatheredPoints out;
  std::vector<Vec3> gathered(items.size() * solutions), origins(items.size()), normals(items.size());
  for (size_t i = 0; i < items.size(); ++i)
  {
    origins[i] = gather.Frame(items[i]).Origin;
    normals[i] = gather.Frame(items[i]).Normal;
  }
  int level = 0;
  long long rays = 0;
  std::vector<Vec3> gradients;
  const std::vector<CacheRecord> records = PlaceRecords(origins, normals,
    [&](const std::vector<int>& list) {
      const double a = from + (to - from) * std::min(1.0, level / 5.0), b = from + (to - from) * std::min(1.0, ++level / 5.0);
      std::vector<CacheRecord> found =
        GatherRecords(gather, items, list, accuracy, pool, ranks, progress, a, b, gathered, gradients, rays);
      out.Aborted = found.empty();
      return found;
    },
    [&](int count, const std::function<void(int, int)>& body) { pool.For(count, 256, body); });
  out.Rays = rays;
  out.Records = static_cast<int>(records.size());
  std::vector<char> own(items.size(), 0);
  std::vector<int> slot(items.size(), -1);
  out.Hidden.assign(gather.Points(), 0);
  for (size_t k = 0; k < records.size(); ++k)
  {
    const CacheRecord& r = records[k];
    own[r.Point] = 1;
    slot[r.Point] = static_cast<int>(k);
    out.Hidden[items[r.Point]] = r.Reach > 0 ? 0 : 1;
  }
  if (out.Aborted)
  {
    return out;
  }
  Interpolate(IrradianceCache(records), own, origins, normals, slot, gradients, solutions, pool, gathered);
  ComposePoints(gather, items, solutions, arriving, gathered, out);
  return out;
}

/// The used frames of `frames`, in order.
std::vector<int> UsedFrames(const std::vector<PointFrame>& frames)
{
  std::vector<int> items;
  for (size_t p = 0; p < frames.size(); ++p)
  {
    if (frames[p].Used)
    {
      items.push_back(static_cast<int>(p));
    }
  }
  return items;
}

/// The direct light arriving at each element that is small against its distance from every
/// emitter and point light, as the mean of its corners' (`arriving`, per point, through
/// their representatives `rep`): the light across it is all but linear there, so a sweep
/// need not cast its shadow rays again. Set in `known` where taken: every corner evaluated
/// and facing as the element does (not a crease's point, whose normal is the mean).
std::vector<Vec3> KnownArriving(const SceneMesh& mesh, const SceneGeometry& g, const std::vector<PointFrame>& points,
  const std::vector<int>& rep, const std::vector<Vec3>& arriving, const std::vector<Emitter>& emitters,
  const std::vector<PointFrame>& elements, const GatherSettings& settings, int solutions, std::vector<char>& known)
{
  const double agree = std::cos(10.0 * M_PI / 180.0);
  std::vector<Vec3> out(static_cast<size_t>(mesh.NumberOfPolygons()) * solutions);
  known.assign(mesh.NumberOfPolygons(), 0);
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    const PointFrame& f = elements[e];
    bool small = f.Used;
    for (size_t k = 0; k < emitters.size() && small; ++k)
    {
      small = Norm(emitters[k].Centre - f.Origin) - emitters[k].Radius > kFar * f.Radius;
    }
    for (size_t k = 0; settings.PointLights && k < settings.PointLights->size() && small; ++k)
    {
      small = Norm((*settings.PointLights)[k].Position - f.Origin) > kFar * f.Radius;
    }
    const int* ids = mesh.Polygon(e);
    for (int v = 0; v < mesh.PolygonSize(e) && small; ++v)
    {
      const int r = rep[ids[v]];
      small = r >= 0 && points[r].Used && Dot(points[r].Normal, g.Normal[e]) > agree;
    }
    if (!small)
    {
      continue;
    }
    known[e] = 1;
    const double share = 1.0 / mesh.PolygonSize(e);
    for (int v = 0; v < mesh.PolygonSize(e); ++v)
    {
      for (int m = 0; m < solutions; ++m)
      {
        out[static_cast<size_t>(e) * solutions + m] += arriving[static_cast<size_t>(rep[ids[v]]) * solutions + m] * share;
      }
    }
  }
  return out;
}
} // namespace

namespace
{
/// Points that see mostly back faces lie behind something resting on their surface (the
/// ceiling over a lamp hung just below it, the floor under a cabinet): dark for a reason
/// that stops at the object's edge, and no one sees them. Each takes the mean of the
/// visible points it shares an element with, as a baker dilates its texels into such
/// places, so interpolation does not carry the dark out past the edge (a ring around every
/// lamp of the demo room otherwise). A few passes reach hidden points beside hidden ones.
void FillHidden(const SceneMesh& mesh, int solutions, std::vector<char>& hidden,
  const std::vector<std::vector<Vec3>*>& values)
{
  for (int pass = 0; pass < 4; ++pass)
  {
    std::vector<std::vector<Vec3>> sums(values.size(), std::vector<Vec3>(hidden.size() * solutions));
    std::vector<int> count(hidden.size(), 0);
    for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
    {
      const int* ids = mesh.Polygon(e);
      for (int a = 0; a < mesh.PolygonSize(e); ++a)
      {
        for (int b = 0; b < mesh.PolygonSize(e) && hidden[ids[a]]; ++b)
        {
          if (hidden[ids[b]])
          {
            continue;
          }
          ++count[ids[a]];
          for (size_t v = 0; v < values.size(); ++v)
          {
            for (int m = 0; m < solutions; ++m)
            {
              sums[v][static_cast<size_t>(ids[a]) * solutions + m] += (*values[v])[static_cast<size_t>(ids[b]) * solutions + m];
            }
          }
        }
      }
    }
    bool filled = false;
    for (size_t p = 0; p < hidden.size(); ++p)
    {
      for (size_t v = 0; v < values.size() && count[p] > 0; ++v)
      {
        for (int m = 0; m < solutions; ++m)
        {
          (*values[v])[p * solutions + m] = sums[v][p * solutions + m] * (1.0 / count[p]);
        }
      }
      filled = filled || count[p] > 0;
      hidden[p] = hidden[p] && count[p] == 0;
    }
    if (!filled)
    {
      break;
    }
  }
}
} // namespace

namespace
{
/// The cosine rays a point can take in what is left of `settings.TimeBudget` after
/// `elapsed` seconds that cast `cast` rays (the points' shadow rays and the sweeps), at that
/// pace, for `gathers` points: settings.Rays where it fits or there is no budget, 0 where
/// fewer than four would. Counted as if every point gathered (the cache makes it fewer).
int AffordableRays(const GatherSettings& settings, double elapsed, long long cast, int gathers)
{
  if (!(settings.TimeBudget > 0) || cast <= 0 || gathers <= 0 || !(elapsed > 0))
  {
    return settings.Rays;
  }
  const double perRay = elapsed / static_cast<double>(cast);
  const double affordable = (settings.TimeBudget - elapsed) / perRay / gathers;
  if (affordable >= settings.Rays)
  {
    return settings.Rays;
  }
  return affordable >= 4 ? static_cast<int>(affordable) : 0;
}
} // namespace

GatheredPoints GatherAtPoints(const SceneMesh& mesh, const SceneGeometry& geometry, const Visibility& rays,
  const std::vector<Vec3>& emission, const std::vector<Vec3>& radiosity, int solutions,
  const GatherSettings& settings, int threads, const std::function<bool(double)>& progress, bool shadows)
{
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Emitter> emitters = MakeEmitters(mesh, geometry, emission, solutions);
  const WorkerPool pool(threads);
  Collective ranks(settings.Group);
  const int sweeps = std::max(0, settings.Sweeps);
  // Progress: the points' direct light a fifth, then each sweep and the points alike.
  auto at = [&](double part) { return 0.2 + 0.8 * part / (sweeps + 1); };
  std::vector<Vec3> pointEmission, source = radiosity, cellDirect, cellIrradiance;
  const std::vector<int> rep = Representatives(mesh, geometry);
  const std::vector<PointFrame> frames = MakeFrames(mesh, geometry, emission, solutions, rep, pointEmission);
  const std::vector<int> items = UsedFrames(frames);
  // The points' direct light first: the sweeps' small elements take their corners' mean.
  std::vector<Vec3> arriving(frames.size() * solutions);
  const Gather lit(mesh, geometry, rays, emission, source, solutions, emitters, frames, pointEmission, 1,
    settings.LightRays, shadows, 0, settings);
  long long cast = PointsDirect(lit, items, solutions, pool, ranks, progress, 0.0, 0.2, arriving);
  GatheredPoints out;
  if (cast < 0)
  {
    out.Aborted = true;
    return out;
  }
  const std::vector<PointFrame> elementFrames = ElementFrames(mesh, geometry);
  std::vector<char> known;
  const std::vector<Vec3> given =
    KnownArriving(mesh, geometry, frames, rep, arriving, emitters, elementFrames, settings, solutions, known);
  for (int sweep = 0; sweep < sweeps; ++sweep)
  {
    Gather pass(mesh, geometry, rays, emission, source, solutions, emitters, elementFrames, emission,
      settings.SweepRays, settings.SweepLightRays, shadows, sweep + 1, settings);
    pass.TakeArriving(&given, &known);
    GatheredPoints elements = Run(pass, solutions, pool, settings.Group, progress, at(sweep), at(sweep + 1));
    cast += elements.Rays;
    if (elements.Aborted)
    {
      out.Aborted = true;
      out.Rays = cast;
      return out;
    }
    KeepUnswept(mesh, geometry, source, solutions, elements);
    source = std::move(elements.Radiosity);
    cellDirect = std::move(elements.Direct);
    cellIrradiance = std::move(elements.Irradiance);
  }
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  // Every rank gathers its share of the points: all take the fewest rays any can afford.
  const int pointRays = static_cast<int>(-LargestOverRanks(
    settings.Group, -AffordableRays(settings, elapsed.count(), cast, static_cast<int>(items.size()))));
  if (pointRays == 0 && sweeps > 0)
  {
    out.Rays = cast; // the points keep their elements' (swept) mean
    out.OutOfTime = true;
  }
  else
  {
    const Gather last(mesh, geometry, rays, emission, source, solutions, emitters, frames, pointEmission,
      std::max(pointRays, 1), settings.LightRays, shadows, 0, settings);
    out = settings.CacheAccuracy > 0
      ? PointsShareGathers(last, items, solutions, arriving, settings.CacheAccuracy, pool, ranks, progress, at(sweeps), 1.0)
      : EveryPointGathers(last, items, solutions, arriving, pool, ranks, progress, at(sweeps), 1.0);
    out.Rays += cast;
    out.PointRays = pointRays;
    out.Points = static_cast<int>(items.size());
  }
  if (out.Aborted)
  {
    out.Radiosity.clear();
    out.Direct.clear();
    out.Irradiance.clear();
    return out;
  }
  if (!out.OutOfTime)
  {
    CopyToCopies(rep, solutions, out);
    FillHidden(mesh, solutions, out.Hidden, { &out.Radiosity, &out.Direct, &out.Irradiance });
  }
  if (sweeps > 0)
  {
    out.Cells = std::move(source);
    out.CellsDirect = std::move(cellDirect);
    out.CellsIrradiance = std::move(cellIrradiance);
  }
  return out;
}

GatheredPoints IrradianceAtPoints(const SceneMesh& mesh, const SceneGeometry& geometry, const Visibility& rays,
  const std::vector<Vec3>& emission, const std::vector<Vec3>& radiosity, int solutions,
  const std::vector<Vec3>& points, const std::vector<Vec3>& normals, const GatherSettings& settings, int threads,
  const std::function<bool(double)>& progress)
{
  // A white, non-emitting surface at each point: what it would send is what arrives.
  std::vector<PointFrame> frames(points.size());
  for (size_t p = 0; p < points.size(); ++p)
  {
    PointFrame& f = frames[p];
    f.Origin = points[p];
    f.Normal = Normalized(normals[p]);
    Vec3 t, b;
    TangentFrame(f.Normal, t, b);
    f.Edge = t;
    f.Reflectance = { 1, 1, 1 };
    f.Used = Dot(f.Normal, f.Normal) > 0;
  }
  const std::vector<Emitter> emitters = MakeEmitters(mesh, geometry, emission, solutions);
  const WorkerPool pool(threads);
  const std::vector<Vec3> none(points.size() * solutions);
  const Gather free(mesh, geometry, rays, emission, radiosity, solutions, emitters, frames, none,
    std::max(1, settings.Rays), settings.LightRays, true, 0x17, settings);
  GatheredPoints out = Run(free, solutions, pool, settings.Group, progress, 0.0, 1.0);
  out.Hidden.clear();
  return out;
}

std::vector<Vec3> CellsFromPoints(const SceneMesh& mesh, const SceneGeometry& geometry,
  const std::vector<Vec3>& points, const std::vector<Vec3>& cells, int solutions)
{
  std::vector<Vec3> out = cells;
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    const int count = mesh.PolygonSize(e);
    if (geometry.Sheltered[e] || count == 0)
    {
      continue;
    }
    const int* ids = mesh.Polygon(e);
    for (int m = 0; m < solutions; ++m)
    {
      Vec3 sum;
      for (int v = 0; v < count; ++v)
      {
        sum += points[static_cast<size_t>(ids[v]) * solutions + m];
      }
      out[static_cast<size_t>(e) * solutions + m] = sum * (1.0 / count);
    }
  }
  return out;
}

} // namespace radiosity
