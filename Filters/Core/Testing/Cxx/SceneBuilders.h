// Small scenes with known answers, built directly (independent of the mesher).
#ifndef RadiosityTest_SceneBuilders_h
#define RadiosityTest_SceneBuilders_h

#include "Solve/RadiositySolver.h"
#include "Geometry/Scene.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace radiosity_test
{
using radiosity::SceneMesh;
using radiosity::Vec3;

/// Options that run a solve to `threshold` (the shot cap is never what stops it).
inline radiosity::SolverOptions Converged(double threshold = 1e-7)
{
  radiosity::SolverOptions o;
  o.MaximumShots = 1000000;
  o.ConvergenceThreshold = threshold;
  return o;
}

/// Power absorbed over the scene, recomputed from the output radiosity rather than the
/// solver's bookkeeping: (B - E) / rho is the irradiance, (1 - rho) of it is absorbed.
/// Solution m's emitters are the cells with LightId m, at unit exitance.
inline double AbsorbedPower(const SceneMesh& mesh, const radiosity::Solution& s)
{
  const radiosity::SceneGeometry g(mesh);
  const int L = s.Solutions;
  double absorbed = 0;
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    for (int m = 0; m < L; ++m)
    {
      const double emitted = mesh.LightId[e] == m ? 1.0 : 0.0;
      for (int c = 0; c < 3; ++c)
      {
        const double rho = mesh.Reflectance[e][c];
        absorbed += (s.Radiosity[static_cast<size_t>(e) * L + m][c] - emitted) / rho * (1 - rho) * g.Area[e];
      }
    }
  }
  return absorbed;
}

/// Per light, sum |a - b| A / sum b A over the elements: the mean relative difference.
inline std::vector<double> RelativeDifference(const SceneMesh& mesh, const radiosity::Solution& a, const radiosity::Solution& b)
{
  const radiosity::SceneGeometry g(mesh);
  const int L = a.Solutions;
  std::vector<double> diff(L, 0.0), sum(L, 0.0);
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    for (int m = 0; m < L; ++m)
    {
      const Vec3& x = a.Radiosity[static_cast<size_t>(e) * L + m];
      const Vec3& y = b.Radiosity[static_cast<size_t>(e) * L + m];
      diff[m] += (std::fabs(x.x - y.x) + std::fabs(x.y - y.y) + std::fabs(x.z - y.z)) * g.Area[e];
      sum[m] += (y.x + y.y + y.z) * g.Area[e];
    }
  }
  for (int m = 0; m < L; ++m)
  {
    diff[m] /= sum[m];
  }
  return diff;
}

/// The largest difference between the sum of the k light-tagged solutions and the one
/// combined solution, over the elements (red channel), relative to the combined peak.
inline double TaggedMinusCombined(const radiosity::Solution& tagged, const radiosity::Solution& combined)
{
  const int L = tagged.Solutions;
  double peak = 0, worst = 0;
  for (size_t e = 0; e < combined.Radiosity.size(); ++e)
  {
    double sum = 0;
    for (int m = 0; m < L; ++m)
    {
      sum += tagged.Radiosity[e * L + m].x;
    }
    peak = std::max(peak, combined.Radiosity[e].x);
    worst = std::max(worst, std::fabs(sum - combined.Radiosity[e].x));
  }
  return peak > 0 ? worst / peak : worst;
}

/// Every polygon's index: the whole mesh as one set.
inline std::vector<int> AllPolygons(const SceneMesh& mesh)
{
  std::vector<int> all(mesh.NumberOfPolygons());
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    all[e] = e;
  }
  return all;
}

/// Adds the quad origin + [0,1]u + [0,1]v as an n x n grid of elements (normal u x v)
/// grouped into patches of `per` x `per` elements, with its own points.
inline void AddGrid(SceneMesh& mesh, const Vec3& origin, const Vec3& u, const Vec3& v, int n,
  int per, const Vec3& rho, int light, int& nextPatch)
{
  const int base = static_cast<int>(mesh.Points.size());
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      mesh.Points.push_back(origin + u * (double(i) / n) + v * (double(j) / n));
    }
  }
  const int patchesPerRow = (n + per - 1) / per;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const int a = base + j * (n + 1) + i;
      mesh.AddPolygon({ a, a + 1, a + n + 2, a + n + 1 });
      mesh.Reflectance.push_back(rho);
      mesh.LightId.push_back(light);
      mesh.PatchId.push_back(nextPatch + (j / per) * patchesPerRow + i / per);
    }
  }
  nextPatch += patchesPerRow * patchesPerRow;
}

/// Axis-aligned box [0,s]^3 with inward-facing faces; face f gets lightId light(f).
template <typename LightOf>
SceneMesh Box(double s, int n, int per, const Vec3& rho, LightOf light)
{
  SceneMesh mesh;
  int patch = 0;
  const Vec3 X{ s, 0, 0 }, Y{ 0, s, 0 }, Z{ 0, 0, s }, O{ 0, 0, 0 };
  // Each (origin, u, v) with u x v pointing into the box.
  AddGrid(mesh, O, X, Y, n, per, rho, light(0), patch); // z = 0
  AddGrid(mesh, Z, Y, X, n, per, rho, light(1), patch); // z = s
  AddGrid(mesh, O, Z, X, n, per, rho, light(2), patch); // y = 0
  AddGrid(mesh, Y, X, Z, n, per, rho, light(3), patch); // y = s
  AddGrid(mesh, O, Y, Z, n, per, rho, light(4), patch); // x = 0
  AddGrid(mesh, X, Z, Y, n, per, rho, light(5), patch); // x = s
  return mesh;
}

/// Two rooms side by side, [0, 1] and [1.2, 2.2] in x, one floor and one ceiling running
/// through both and under the 0.2 m wall between them (its two faces stand on element
/// edges); a lamp under the ceiling of the first room unless `lamp` is false. `n` elements
/// per metre.
inline SceneMesh TwoRooms(int n, bool lamp = true)
{
  SceneMesh mesh;
  int patch = 0;
  const Vec3 grey{ 0.6, 0.6, 0.6 };
  const double w = 2.2;
  const int across = static_cast<int>(std::lround(w * n));
  auto strip = [&](const Vec3& origin, const Vec3& u, const Vec3& v, int nu, int nv) {
    // an nu x nv grid of quads (normal u x v), patches of 2 x 2 elements
    const int base = static_cast<int>(mesh.Points.size());
    for (int j = 0; j <= nv; ++j)
      for (int i = 0; i <= nu; ++i)
        mesh.Points.push_back(origin + u * (double(i) / nu) + v * (double(j) / nv));
    for (int j = 0; j < nv; ++j)
      for (int i = 0; i < nu; ++i)
      {
        const int a = base + j * (nu + 1) + i;
        mesh.AddPolygon({ a, a + 1, a + nu + 2, a + nu + 1 });
        mesh.Reflectance.push_back(grey);
        mesh.LightId.push_back(-1);
        mesh.PatchId.push_back(patch + (j / 2) * ((nu + 1) / 2) + i / 2);
      }
    patch += ((nu + 1) / 2) * ((nv + 1) / 2);
  };
  strip({ 0, 0, 0 }, { w, 0, 0 }, { 0, 1, 0 }, across, n);     // floor, up
  strip({ 0, 0, 1 }, { 0, 1, 0 }, { w, 0, 0 }, n, across);     // ceiling, down
  strip({ 0, 0, 0 }, { 0, 0, 1 }, { w, 0, 0 }, n, across);     // y = 0, faces +y
  strip({ 0, 1, 0 }, { w, 0, 0 }, { 0, 0, 1 }, across, n);     // y = 1, faces -y
  strip({ 0, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, n, n);          // x = 0, faces +x
  strip({ w, 0, 0 }, { 0, 0, 1 }, { 0, 1, 0 }, n, n);          // x = 2.2, faces -x
  strip({ 1.0, 0, 0 }, { 0, 0, 1 }, { 0, 1, 0 }, n, n);        // the wall's face to room 1, -x
  strip({ 1.2, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, n, n);        // its face to room 2, +x
  if (!lamp)
  {
    return mesh;
  }
  AddGrid(mesh, { 0.35, 0.35, 0.95 }, { 0.3, 0, 0 }, { 0, 0.3, 0 }, 1, 1, { 0, 0, 0 }, 0, patch); // lamp, down
  // AddGrid's quad faces +z for (x, y): turn it to face down
  std::swap(mesh.Connectivity[mesh.Offsets[mesh.NumberOfPolygons() - 1] + 1],
    mesh.Connectivity[mesh.Offsets[mesh.NumberOfPolygons() - 1] + 3]);
  return mesh;
}
}

#endif
