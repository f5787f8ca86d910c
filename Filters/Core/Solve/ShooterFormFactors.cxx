#include "Solve/ShooterFormFactors.h"
#include "Geometry/FormFactor.h"
#include "Geometry/Outline.h"
#include "Geometry/Polygon.h"
#include "Base/SampleStream.h"

#include <algorithm>
#include <iterator>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <array>
#include <map>

namespace radiosity
{

namespace
{

} // namespace

ShooterFormFactors::ShooterFormFactors(const SceneMesh& mesh, const SceneGeometry& geometry,
  const Visibility& rays, const WorkerPool& pool, bool cullVisibility)
  : Mesh(mesh)
  , Geometry(geometry)
  , Rays(rays)
  , Pool(pool)
  , CullVisibility(cullVisibility)
{
  // Offsets keep rays from starting or ending inside their own surfaces; relative to the
  // scene so the result does not depend on its units (SceneGeometry::RayLift).
  Epsilon = geometry.RayLift;
  Loops.reserve(mesh.Connectivity.size());
  for (int id : mesh.Connectivity)
  {
    Loops.push_back(mesh.Points[id]);
  }
  const size_t patches = geometry.PatchElements.size();
  PatchTriangles.resize(patches);
  PatchCdf.resize(patches);
  PatchCentre.resize(patches);
  PatchNormal.resize(patches);
  for (size_t p = 0; p < patches; ++p)
  {
    double total = 0;
    Vec3 centre, normal;
    for (int e : geometry.PatchElements[p])
    {
      const Vec3* loop = Loops.data() + mesh.Offsets[e];
      const std::vector<int> corners = Triangulate(loop, mesh.PolygonSize(e));
      for (size_t t = 0; t + 2 < corners.size(); t += 3)
      {
        const Vec3 &a = loop[corners[t]], &b = loop[corners[t + 1]], &c = loop[corners[t + 2]];
        const Vec3 cross = Cross(b - a, c - a);
        total += 0.5 * Norm(cross);
        PatchTriangles[p].push_back({ a, b, c, Normalized(cross) });
        PatchCdf[p].push_back(total);
      }
      centre += geometry.Centroid[e] * geometry.Area[e];
      normal += geometry.Normal[e] * geometry.Area[e];
    }
    for (double& cdf : PatchCdf[p])
    {
      cdf = total > 0 ? cdf / total : 1.0;
    }
    PatchCentre[p] = centre * (1.0 / geometry.PatchArea[p]);
    PatchNormal[p] = Normalized(normal);
  }
  PatchRadius.assign(patches, 0.0);
  for (size_t p = 0; p < patches; ++p)
  {
    for (const SampleTriangle& tri : PatchTriangles[p])
    {
      for (const Vec3* corner : { &tri.A, &tri.B, &tri.C })
      {
        PatchRadius[p] = std::max(PatchRadius[p], Norm(*corner - PatchCentre[p]));
      }
    }
  }
  OpenElements.assign(patches, {});
  for (size_t p = 0; p < patches; ++p)
  {
    const std::vector<int>& elements = geometry.PatchElements[p];
    if (std::any_of(elements.begin(), elements.end(), [&](int e) { return geometry.Sheltered[e] != 0; }))
    {
      std::copy_if(elements.begin(), elements.end(), std::back_inserter(OpenElements[p]),
        [&](int e) { return geometry.Sheltered[e] == 0; });
    }
  }
  BuildOutlines();
  BuildTrees();
  if (CullVisibility)
  {
    FindBlockers();
  }
}

void ShooterFormFactors::BuildTrees()
{
  const int patches = static_cast<int>(Geometry.PatchElements.size());
  PatchCone.assign(patches, NormalCone());
  Trees.resize(patches);
  bool clusters = false;
  for (int p = 0; p < patches && !clusters; ++p)
  {
    clusters = !Planar(p);
  }
  Pool.For(patches, 16, [&](int begin, int end) {
    for (int p = begin; p < end; ++p)
    {
      const std::vector<int>& elements = Geometry.PatchElements[p];
      PatchCone[p] = Planar(p) ? NormalCone(PatchNormal[p], 0.0) : ConeOf(Geometry, elements);
      // Below this a plain sum over the elements is as fast as a walk down a tree. A flat
      // patch gets one only where clusters receive: to link to their parts (FactorVectorFor)
      // it must leave out its own parts behind them; its factors keep using its outline.
      if ((!Planar(p) || clusters) && elements.size() >= 8)
      {
        Trees[p] = std::make_unique<ClusterTree>(Mesh, Geometry, Loops, elements);
      }
    }
  });
}

void ShooterFormFactors::FindBlockers()
{
  const int n = Mesh.NumberOfPolygons();
  ElementBox.assign(n, Bounds());
  PatchBox.assign(Geometry.PatchElements.size(), Bounds());
  Bounds scene;
  for (int e = 0; e < n; ++e)
  {
    for (int v = 0; v < Mesh.PolygonSize(e); ++v)
    {
      ElementBox[e].Add(Mesh.Points[Mesh.Polygon(e)[v]]);
    }
    PatchBox[Geometry.ElementPatch[e]].Add(ElementBox[e]);
    scene.Add(ElementBox[e]);
  }
  // A segment between two points in front of (or on) a plane never crosses it. So a
  // polygon with no scene point strictly behind its plane cannot block any pair; only
  // the others ("blockers") can. Elements are grouped by plane: one test per plane.
  const double eps = 1e-9 * Geometry.SceneDiagonal;
  const Vec3 centre = scene.Centre();
  std::map<std::array<long long, 4>, Bounds> planes;
  std::map<std::array<long long, 4>, bool> blocking;
  std::map<int, Bounds> patches; // blocking elements' boxes per patch: tighter than per plane
  for (int e = 0; e < n; ++e)
  {
    const Vec3& normal = Geometry.Normal[e];
    const double offset = Dot(normal, Geometry.Centroid[e] - centre);
    const std::array<long long, 4> key = PlaneKey(normal, offset, 1e-6, eps * 1e3);
    auto known = blocking.find(key);
    if (known == blocking.end())
    {
      bool behind = false;
      // The scene box's corners bound every point: if none is behind, nothing is.
      for (int corner = 0; corner < 8 && !behind; ++corner)
      {
        const Vec3 p{ corner & 1 ? scene.Hi.x : scene.Lo.x, corner & 2 ? scene.Hi.y : scene.Lo.y,
          corner & 4 ? scene.Hi.z : scene.Lo.z };
        behind = Dot(normal, p - centre) < offset - eps;
      }
      if (behind)
      {
        behind = false;
        for (size_t p = 0; p < Mesh.Points.size() && !behind; ++p)
        {
          behind = Dot(normal, Mesh.Points[p] - centre) < offset - eps;
        }
      }
      known = blocking.emplace(key, behind).first;
    }
    if (known->second)
    {
      planes[key].Add(ElementBox[e]);
      patches[Geometry.ElementPatch[e]].Add(ElementBox[e]);
    }
  }
  BlockingPlaneCount = static_cast<int>(planes.size());
  const auto& boxes = patches.size() <= 256 ? patches : std::map<int, Bounds>();
  for (const auto& patch : boxes)
  {
    Blockers.push_back(patch.second);
  }
  for (const auto& plane : planes)
  {
    if (boxes.empty())
    {
      Blockers.push_back(plane.second);
    }
    AllBlockers.Add(plane.second);
  }
}

bool ShooterFormFactors::MayBeBlocked(int patch, int element) const
{
  return ShaftMayBeBlocked(PatchBox[patch], ElementBox[element]);
}

bool ShooterFormFactors::MayBeBlockedBetweenPatches(int receiver, int shooter) const
{
  return !CullVisibility || ShaftMayBeBlocked(PatchBox[shooter], PatchBox[receiver]);
}

bool ShooterFormFactors::ShaftMayBeBlocked(const Bounds& from, const Bounds& to) const
{
  if (Blockers.empty())
  {
    return false;
  }
  Bounds shaft = from;
  shaft.Add(to);
  const double tolerance = 1e-9 * Geometry.SceneDiagonal;
  if (!shaft.Overlaps(AllBlockers, tolerance))
  {
    return false;
  }
  if (Blockers.size() > 256)
  {
    return true; // too many to check one by one: be conservative
  }
  for (const Bounds& blocker : Blockers)
  {
    if (shaft.Overlaps(blocker, tolerance))
    {
      return true;
    }
  }
  return false;
}

void ShooterFormFactors::BuildOutlines()
{
  const size_t patches = Geometry.PatchElements.size();
  PatchOutline.assign(patches, {});
  for (size_t p = 0; p < patches; ++p)
  {
    const std::vector<int>& elements = Geometry.PatchElements[p];
    const Vec3& n = PatchNormal[p];
    bool planar = true;
    for (int e : elements)
    {
      // Coplanar within a tolerance relative to the scene: then one front test and one
      // outline serve the whole patch.
      planar = planar && Dot(Geometry.Normal[e], n) > 1 - 1e-9 &&
        std::fabs(Dot(n, Geometry.Centroid[e] - PatchCentre[p])) <= 1e-9 * Geometry.SceneDiagonal;
    }
    if (!planar || elements.size() < 2)
    {
      continue;
    }
    PatchOutline[p] = PolygonSetOutline(Mesh, elements);
  }
  BuildLoops();
}

void ShooterFormFactors::BuildLoops()
{
  const size_t patches = Geometry.PatchElements.size();
  PatchLoop.assign(patches, {});
  ConvexLoop.assign(patches, 0);
  for (size_t p = 0; p < patches; ++p)
  {
    const std::vector<int>& elements = Geometry.PatchElements[p];
    if (elements.size() == 1)
    {
      for (int v = 0; v < Mesh.PolygonSize(elements[0]); ++v)
      {
        PatchLoop[p].push_back(Mesh.Points[Mesh.Polygon(elements[0])[v]]);
      }
    }
    else if (!PatchOutline[p].empty())
    {
      PatchLoop[p] = ChainLoop(PatchOutline[p]);
    }
    ConvexLoop[p] = PatchLoop[p].size() >= 3 && IsConvex(PatchLoop[p].data(), static_cast<int>(PatchLoop[p].size()));
  }
}

const ShooterFormFactors::SampleTriangle& ShooterFormFactors::PickTriangle(int patch, double u) const
{
  const std::vector<SampleTriangle>& triangles = PatchTriangles[patch];
  const std::vector<double>& cdf = PatchCdf[patch];
  const size_t i = static_cast<size_t>(std::lower_bound(cdf.begin(), cdf.end(), u) - cdf.begin());
  return i == triangles.size() ? triangles.back() : triangles[i];
}

int ShooterFormFactors::FrontHit(const Vec3& origin, const Vec3& direction) const
{
  Visibility::Hit hit;
  if (!Rays.Intersect(origin, direction, hit))
  {
    return -1;
  }
  // A ray reaching a polygon's back is absorbed there: back faces do not receive.
  return Dot(Geometry.Normal[hit.Polygon], direction) < 0 ? hit.Polygon : -1;
}

bool ShooterFormFactors::SeesClosedScene(int patch)
{
  if (ClosedView.empty())
  {
    ClosedView.assign(Geometry.PatchElements.size(), -1);
  }
  if (ClosedView[patch] < 0)
  {
    // Cosine-distributed rays from stratified points: one escaping (or meeting a back
    // face) means light can leave, and then only an excess is corrected.
    const int probes = 64;
    SampleStream random(static_cast<std::uint64_t>(patch), 0, 11);
    // The frame follows the patch's first edge, so a rotated scene probes alike.
    const Vec3& n = PatchNormal[patch];
    const int first = Geometry.PatchElements[patch][0];
    const Vec3 edge = Mesh.Points[Mesh.Polygon(first)[1]] - Mesh.Points[Mesh.Polygon(first)[0]];
    const Vec3 t = Normalized(edge - n * Dot(edge, n)), b = Cross(n, t);
    bool closed = Planar(patch);
    for (int r = 0; r < probes && closed; ++r)
    {
      const Vec3 from = SamplePoint(patch, r, probes, random);
      const double u = (r % 8 + random.Next()) / 8, phi = 2 * Pi * (r / 8 + random.Next()) / 8;
      const double radius = std::sqrt(u);
      const Vec3 direction = t * (radius * std::cos(phi)) + b * (radius * std::sin(phi)) + n * std::sqrt(1 - u);
      closed = FrontHit(from, direction) >= 0;
    }
    ClosedView[patch] = closed ? 1 : 0;
  }
  return ClosedView[patch] == 1;
}

double ShooterFormFactors::ConservationScale(int patch, double receiving)
{
  const double shooting = Geometry.PatchOpenArea[patch];
  if (!(receiving > 0) || !(shooting > 0))
  {
    return 1.0;
  }
  if (receiving > shooting || SeesClosedScene(patch))
  {
    return shooting / receiving;
  }
  return 1.0;
}

long long ShooterFormFactors::Compute(
  int patch, FormFactorMethod method, int samples, int shot, std::vector<double>& factors)
{
  switch (method)
  {
    case FormFactorMethod::Hemicube:
      return Hemicube(patch, samples, factors);
    case FormFactorMethod::MonteCarlo:
      return MonteCarlo(patch, samples, shot, factors);
    case FormFactorMethod::Analytic:
    default:
      return Analytic(patch, samples, factors);
  }
}

double ShooterFormFactors::PointFactor(int patch, const Vec3& x, const Vec3& normal, std::vector<Vec3>& scratch) const
{
  const std::vector<Vec3>& outline = PatchOutline[patch];
  bool outlineInFront = !outline.empty();
  for (size_t v = 0; v < outline.size() && outlineInFront; ++v)
  {
    outlineInFront = Dot(normal, outline[v] - x) >= 0;
  }
  if (outlineInFront)
  {
    // Planar patch wholly in front of the receiver: one outline instead of every
    // element, and one front test (emitters radiate only from their front side).
    if (Dot(PatchNormal[patch], x - PatchCentre[patch]) <= 0)
    {
      return 0;
    }
    return EdgeSetFormFactor(x, normal, outline.data(), static_cast<int>(outline.size() / 2));
  }
  if (ConvexLoop[patch] && !outline.empty())
  {
    // Cut by the receiver's plane: clip the patch's corner loop once, not every element.
    if (Dot(PatchNormal[patch], x - PatchCentre[patch]) <= 0)
    {
      return 0;
    }
    const std::vector<Vec3>& loop = PatchLoop[patch];
    return PointToPolygonFormFactor(x, normal, loop.data(), static_cast<int>(loop.size()), scratch);
  }
  if (Trees[patch] && !Planar(patch))
  {
    return Trees[patch]->PointFactor(x, normal, scratch);
  }
  double f = 0;
  for (int s : Geometry.PatchElements[patch])
  {
    if (Dot(Geometry.Normal[s], x - Geometry.Centroid[s]) <= 0)
    {
      continue;
    }
    f += PointToPolygonFormFactor(x, normal, Loops.data() + Mesh.Offsets[s], Mesh.PolygonSize(s), scratch);
  }
  return f;
}

Vec3 ShooterFormFactors::FactorVector(int patch, const Vec3& x) const
{
  const std::vector<Vec3>& loop = PatchLoop[patch];
  if (!loop.empty())
  {
    return Dot(PatchNormal[patch], x - PatchCentre[patch]) > 0
      ? PolygonFactorVector(x, loop.data(), static_cast<int>(loop.size()))
      : Vec3();
  }
  if (Trees[patch])
  {
    return Trees[patch]->FactorVector(x);
  }
  Vec3 sum;
  for (int s : Geometry.PatchElements[patch])
  {
    if (Dot(Geometry.Normal[s], x - Geometry.Centroid[s]) > 0)
    {
      sum += PolygonFactorVector(x, Loops.data() + Mesh.Offsets[s], Mesh.PolygonSize(s));
    }
  }
  return sum;
}

Vec3 ShooterFormFactors::SamplePoint(int patch, int r, int samples, SampleStream& random, const SampleTriangle** picked) const
{
  // Stratified in the area CDF, so the samples cover the whole patch.
  const SampleTriangle& tri = PickTriangle(patch, (r + random.Next()) / samples);
  if (picked)
  {
    *picked = &tri;
  }
  double a = random.Next(), b = random.Next();
  if (a + b > 1)
  {
    a = 1 - a;
    b = 1 - b;
  }
  return tri.A + (tri.B - tri.A) * a + (tri.C - tri.A) * b + tri.Normal * Epsilon;
}

Vec3 ShooterFormFactors::ReceiverPoint(int patch, int r, int samples, SampleStream& random) const
{
  const std::vector<int>& open = OpenElements[patch];
  if (open.empty())
  {
    return SamplePoint(patch, r, samples, random);
  }
  const size_t pick = std::min(open.size() - 1, static_cast<size_t>((r + random.Next()) / samples * open.size()));
  const int e = open[pick];
  return Geometry.Centroid[e] + Geometry.Normal[e] * Epsilon;
}

int ShooterFormFactors::VisibleRays(int patch, int element, int samples) const
{
  SampleStream random(static_cast<std::uint64_t>(patch), static_cast<std::uint64_t>(element));
  const Vec3 from = Geometry.Centroid[element] + Geometry.Normal[element] * Epsilon;
  int visible = 0;
  for (int r = 0; r < samples; ++r)
  {
    visible += Rays.Occluded(from, SamplePoint(patch, r, samples, random), 0.0) ? 0 : 1;
  }
  return visible;
}

int ShooterFormFactors::VisibleRaysBetweenPatches(int receiver, int shooter, int samples) const
{
  SampleStream random(static_cast<std::uint64_t>(shooter), static_cast<std::uint64_t>(receiver), 7);
  int visible = 0;
  for (int r = 0; r < samples; ++r)
  {
    const Vec3 from = ReceiverPoint(receiver, r, samples, random);
    visible += Rays.Occluded(from, SamplePoint(shooter, r, samples, random), 0.0) ? 0 : 1;
  }
  return visible;
}

int ShooterFormFactors::VisibleRaysToElements(
  int shooter, const int* elements, int count, int samples, std::uint64_t seed) const
{
  SampleStream random(static_cast<std::uint64_t>(shooter), seed, 13);
  int visible = 0;
  for (int r = 0; r < samples && count > 0; ++r)
  {
    const int pick = std::min(count - 1, static_cast<int>((r + random.Next()) / samples * count));
    const int e = elements[pick];
    const Vec3 from = Geometry.Centroid[e] + Geometry.Normal[e] * Epsilon;
    visible += Rays.Occluded(from, SamplePoint(shooter, r, samples, random), 0.0) ? 0 : 1;
  }
  return visible;
}

double ShooterFormFactors::VisibleFractionOfFacing(
  int shooter, const int* elements, int count, int samples, std::uint64_t seed, long long& rays) const
{
  SampleStream random(static_cast<std::uint64_t>(shooter), seed, 17);
  int visible = 0, aimed = 0;
  for (int r = 0; r < samples && count > 0; ++r)
  {
    const int pick = std::min(count - 1, static_cast<int>((r + random.Next()) / samples * count));
    const int e = elements[pick];
    const Vec3 to = SamplePoint(shooter, r, samples, random);
    if (Dot(Geometry.Normal[e], to - Geometry.Centroid[e]) <= 0)
    {
      continue; // the element's back is turned: no light of this shooter point reaches it
    }
    ++aimed;
    ++rays;
    visible += Rays.Occluded(Geometry.Centroid[e] + Geometry.Normal[e] * Epsilon, to, 0.0) ? 0 : 1;
    if (visible > 0 && visible < aimed)
    {
      return 0.5; // partly in view: the callers need no closer estimate
    }
  }
  return aimed > 0 ? static_cast<double>(visible) / aimed : 0.0;
}

double ShooterFormFactors::ReceiverFactor(int patch, int e, std::vector<Vec3>& scratch) const
{
  const Vec3& c = Geometry.Centroid[e];
  const double size = std::sqrt(Geometry.Area[e]);
  if (Norm(c - PatchCentre[patch]) - PatchRadius[patch] > 2 * size)
  {
    return PointFactor(patch, c, Geometry.Normal[e], scratch);
  }
  // Near the shooter the factor changes across the element faster than one point can
  // tell (a point beside a lamp sees far more of it than the element's far edge).
  const double mean =
    FanAverage(Mesh, Geometry, e, [&](const Vec3& x) { return PointFactor(patch, x, Geometry.Normal[e], scratch); });
  return std::isnan(mean) ? PointFactor(patch, c, Geometry.Normal[e], scratch) : mean;
}

double ShooterFormFactors::ElementFactor(int patch, int e, int samples, std::vector<Vec3>& scratch, RayCounts& counts) const
{
  const double f = ReceiverFactor(patch, e, scratch);
  if (f <= 0 || samples <= 0)
  {
    return f;
  }
  if (CullVisibility && !MayBeBlocked(patch, e))
  {
    ++counts.Unblockable;
    return f;
  }
  counts.Rays += samples;
  return f * VisibleRays(patch, e, samples) / samples;
}

void ShooterFormFactors::Count(const RayCounts& counts, int samples)
{
  Unblockable += counts.Unblockable;
  Skipped += counts.Unblockable * samples;
}

long long ShooterFormFactors::Analytic(int patch, int samples, std::vector<double>& factors)
{
  const SceneGeometry& g = Geometry;
  const int n = static_cast<int>(g.Normal.size());
  std::atomic<long long> rays{ 0 };
  Pool.For(n, 64, [&](int begin, int end) {
    thread_local std::vector<Vec3> scratch; // clipping buffer, allocated once per thread
    RayCounts counts;
    for (int e = begin; e < end; ++e)
    {
      const int q = g.ElementPatch[e];
      factors[e] = q == patch || (Receivers && !(*Receivers)[q]) ? 0.0 : ElementFactor(patch, e, samples, scratch, counts);
    }
    rays += counts.Rays;
    Count(counts, samples);
  });
  return rays;
}

long long ShooterFormFactors::Hemicube(int patch, int resolution, std::vector<double>& factors)
{
  resolution = std::max(2, resolution + (resolution & 1)); // side faces need R/2 rows
  if (resolution != CubeResolution)
  {
    // Delta form factors of the unit hemicube (Cohen & Greenberg 1985): top face z = 1,
    // dF = dA / (pi (x^2 + y^2 + 1)^2); side face x = 1, dF = z dA / (pi (y^2 + z^2 + 1)^2).
    CubeResolution = resolution;
    CubeDirections.clear();
    CubeWeights.clear();
    const double d = 2.0 / resolution, dA = d * d;
    for (int i = 0; i < resolution; ++i)
    {
      for (int j = 0; j < resolution; ++j)
      {
        const double x = -1 + (i + 0.5) * d, y = -1 + (j + 0.5) * d;
        const double r = x * x + y * y + 1;
        CubeDirections.push_back({ x, y, 1 });
        CubeWeights.push_back(dA / (Pi * r * r));
      }
    }
    for (int side = 0; side < 4; ++side)
    {
      for (int i = 0; i < resolution; ++i)
      {
        for (int k = 0; k < resolution / 2; ++k)
        {
          const double u = -1 + (i + 0.5) * d, z = (k + 0.5) * d;
          const double r = u * u + z * z + 1;
          const Vec3 dir = side == 0 ? Vec3{ 1, u, z }
            : side == 1              ? Vec3{ -1, u, z }
            : side == 2              ? Vec3{ u, 1, z }
                                     : Vec3{ u, -1, z };
          CubeDirections.push_back(dir);
          CubeWeights.push_back(z * dA / (Pi * r * r));
        }
      }
    }
  }
  const int count = static_cast<int>(CubeDirections.size());
  HitElement.resize(count);
  const Vec3 n = PatchNormal[patch];
  Vec3 t, b;
  TangentFrame(n, t, b);
  const Vec3 origin = PatchCentre[patch] + n * Epsilon;
  Pool.For(count, 256, [&](int begin, int end) {
    for (int i = begin; i < end; ++i)
    {
      const Vec3& l = CubeDirections[i];
      HitElement[i] = FrontHit(origin, t * l.x + b * l.y + n * l.z);
    }
  });
  std::fill(factors.begin(), factors.end(), 0.0);
  for (int i = 0; i < count; ++i) // in pixel order: deterministic sums
  {
    if (HitElement[i] >= 0 && Geometry.ElementPatch[HitElement[i]] != patch)
    {
      factors[HitElement[i]] += CubeWeights[i];
    }
  }
  Reciprocal(patch, Geometry.PatchOpenArea[patch], factors); // the centre sees for the open part
  return count;
}

long long ShooterFormFactors::MonteCarlo(int patch, int samples, int shot, std::vector<double>& factors)
{
  samples = std::max(1, samples);
  HitElement.resize(samples);
  Pool.For(samples, 256, [&](int begin, int end) {
    for (int r = begin; r < end; ++r)
    {
      SampleStream random(static_cast<std::uint64_t>(patch), static_cast<std::uint64_t>(shot),
        static_cast<std::uint64_t>(r) + 1);
      const SampleTriangle* picked = nullptr;
      const Vec3 origin = SamplePoint(patch, r, samples, random, &picked);
      const SampleTriangle& tri = *picked;
      // Cosine-distributed direction (Malley): uniform on the disk, lifted to the hemisphere.
      const double u = random.Next(), phi = 2 * Pi * random.Next();
      const double radius = std::sqrt(u);
      Vec3 t, bt;
      TangentFrame(tri.Normal, t, bt);
      const Vec3 dir = t * (radius * std::cos(phi)) + bt * (radius * std::sin(phi)) +
        tri.Normal * std::sqrt(std::max(0.0, 1 - u));
      HitElement[r] = FrontHit(origin, dir);
    }
  });
  std::fill(factors.begin(), factors.end(), 0.0);
  const double w = 1.0 / samples;
  for (int r = 0; r < samples; ++r)
  {
    if (HitElement[r] >= 0 && Geometry.ElementPatch[HitElement[r]] != patch)
    {
      factors[HitElement[r]] += w;
    }
  }
  Reciprocal(patch, Geometry.PatchArea[patch], factors); // rays from enclosed points are lost
  return samples;
}

void ShooterFormFactors::Reciprocal(int patch, double shooterArea, std::vector<double>& factors) const
{
  for (size_t e = 0; e < factors.size(); ++e)
  {
    factors[e] = factors[e] > 0 ? factors[e] * shooterArea / Geometry.Area[e] : 0.0;
  }
}

} // namespace radiosity
