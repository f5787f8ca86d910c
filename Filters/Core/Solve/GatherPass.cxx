#include "Solve/GatherPass.h"

#include "Geometry/FormFactor.h"
#include "Geometry/Polygon.h"
#include "Lights/PointShading.h"

#include <algorithm>
#include <cmath>

namespace radiosity
{
namespace gathering
{

Gather::Gather(const SceneMesh& mesh, const SceneGeometry& g, const Visibility& rays, const std::vector<Vec3>& emission,
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

long long Gather::Evaluate(size_t p, Vec3* radiosity, Vec3* direct, Vec3* irradiance, Vec3* arriving, bool known,
  std::vector<Vec3>& scratch, char& hidden) const
{
  if (!Frames[p].Used)
  {
    return 0;
  }
  std::vector<Vec3> gathered(S);
  HitDistances hits;
  long long rays = known ? 0 : DirectAt(p, arriving, scratch);
  rays += IndirectAt(p, gathered.data(), hits);
  hidden = SeesBacks(hits);
  Compose(p, arriving, gathered.data(), radiosity, direct, irradiance);
  return rays;
}

long long Gather::DirectAt(size_t p, Vec3* arriving, std::vector<Vec3>& scratch) const
{
  const PointFrame& f = Frames[p];
  std::vector<Vec3> sum(S);
  const long long rays = f.Element < 0 ? DirectLight(p, f, sum, scratch) : SpreadDirectLight(p, f, sum, scratch);
  std::copy(sum.begin(), sum.end(), arriving);
  return rays;
}

long long Gather::IndirectAt(size_t p, Vec3* gathered, HitDistances& hits) const
{
  std::vector<Vec3> sum(S);
  const long long rays = Interreflection(p, Frames[p], sum, hits);
  std::copy(sum.begin(), sum.end(), gathered);
  return rays;
}

void Gather::Compose(size_t p, const Vec3* arriving, const Vec3* gathered, Vec3* radiosity, Vec3* direct,
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

long long Gather::DirectLight(size_t p, const PointFrame& f, std::vector<Vec3>& out, std::vector<Vec3>& scratch) const
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

long long Gather::PointLightsAt(const Vec3& x, const Vec3& normal, double weight, std::vector<Vec3>& out) const
{
  for (size_t i = 0; i < PointLights.size(); ++i)
  {
    out[PointLightsCombined ? FirstPoint : FirstPoint + i] += PointIrradianceAt(PointLights[i], x, normal, Rays, 0.0) * weight;
  }
  return static_cast<long long>(PointLights.size());
}

long long Gather::SpreadDirectLight(size_t p, const PointFrame& f, std::vector<Vec3>& out, std::vector<Vec3>& scratch) const
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
      if (far[k] ? !AnyPositive(&atCentre[k * S], S) : Behind(em, x, f.Normal))
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

bool Gather::Behind(const Emitter& em, const Vec3& x, const Vec3& normal)
{
  return Dot(em.Centre - x, normal) < -em.Radius || (em.Planar && Dot(x - em.Centre, em.Normal) <= 0);
}

Vec3 Gather::Spot(const PointFrame& f, int r, int count, SampleStream& random) const
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

bool Gather::Unshadowed(const Emitter& em, const Vec3& x, const Vec3& normal, std::vector<Vec3>& out,
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

double Gather::ElementFactor(int e, const Vec3& x, const Vec3& normal, std::vector<Vec3>& loop,
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

double Gather::SeenFraction(size_t p, size_t k, const Vec3& from, long long& rays) const
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

long long Gather::Interreflection(size_t p, const PointFrame& f, std::vector<Vec3>& out, HitDistances& hits) const
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
      const double r = std::sqrt(u), cosine = std::cos(phi), sine = std::sin(phi);
      const Vec3 d = t * (r * cosine) + b * (r * sine) + f.Normal * std::sqrt(1 - u);
      const int start = ((i * Side + j) * RayStep + 1) % (Side * Side);
      const size_t cell = static_cast<size_t>(i) * Side + j;
      if (hits.Samples)
      {
        hits.Samples->U[cell] = u;
        hits.Samples->SetPhi(cell, cosine, sine);
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

} // namespace gathering
} // namespace radiosity
