// The hard-case suite: named failure modes of radiosity codes, each with an exact or
// reference expectation. Listed with what goes wrong in naive code in Testing/README.md.
#include "Geometry/FormFactor.h"
#include "Solve/LightSolutions.h"
#include "Geometry/CornerGrid.h"
#include "Geometry/Polygon.h"
#include "SceneBuilders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

using namespace radiosity;
using radiosity_test::AddGrid;
using radiosity_test::Box;
using radiosity_test::Converged;

namespace
{
Solution SolveOne(const SceneMesh& mesh, const SolverOptions& o, int lights = 1)
{
  RadiositySolver solver(mesh);
  return SolveLights(solver, mesh, LightGrouping::OnePerLight(lights), {}, SolutionMode::LightTagged, o);
}

bool AllFinite(const std::vector<Vec3>& values)
{
  for (const Vec3& v : values)
  {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z) || v.x < 0 || v.y < 0 || v.z < 0)
    {
      return false;
    }
  }
  return true;
}

/// Emitter (light 0) facing down at height h over a fine receiver floor, plus `extra`.
SceneMesh LampOverFloor(double h, int n)
{
  SceneMesh mesh;
  int patch = 0;
  AddGrid(mesh, { 0.4, 0.4, h }, { 0, 0.2, 0 }, { 0.2, 0, 0 }, 1, 1, { 0, 0, 0 }, 0, patch);
  AddGrid(mesh, { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, n, 1, { 0.5, 0.5, 0.5 }, -1, patch);
  return mesh;
}
} // namespace

// ---- Reflectance -> 1 -------------------------------------------------------------------

TEST(HardReflectance, NearOneConvergesWithoutOvershoot)
{
  for (double rho : { 0.99, 0.999 })
  {
    SceneMesh box = Box(1.0, 2, 1, { rho, rho, rho }, [](int) { return 0; }); // 24 patches
    const Solution s = SolveOne(box, Converged(1e-10));
    ASSERT_TRUE(s.Statistics.Converged) << rho;
    ASSERT_TRUE(AllFinite(s.Radiosity));
    const double exact = 1.0 / (1.0 - rho);
    for (const Vec3& b : s.Radiosity)
    {
      EXPECT_NEAR(b.x, exact, 1e-6 * exact) << rho;
      EXPECT_LE(b.x, exact * (1 + 1e-12)) << "overshoot at rho " << rho;
    }
    // Progressive refinement only ever removes unshot energy: no oscillation.
    const std::vector<double>& r = s.Statistics.RemainingHistory;
    for (size_t i = 1; i < r.size(); ++i)
    {
      ASSERT_LE(r[i], r[i - 1] * (1 + 1e-12)) << "shot " << i;
    }
  }
}

namespace
{
/// Jacobi-style shooting on a dense form-factor matrix, accumulating in T (optionally
/// with Kahan compensation): the accumulation question isolated from the solver.
template <typename T>
double FurnaceError(const std::vector<double>& F, int n, double rho, double residual, bool kahan)
{
  std::vector<T> b(n, T(1)), unshot(n, T(1)), carry(n, T(0));
  const double exact = 1.0 / (1.0 - rho);
  double remaining = n;
  while (remaining / n > residual)
  {
    int i = 0;
    for (int j = 1; j < n; ++j)
    {
      i = unshot[j] > unshot[i] ? j : i;
    }
    const T u = unshot[i];
    unshot[i] = 0;
    for (int j = 0; j < n; ++j)
    {
      const T d = static_cast<T>(rho * F[j * n + i]) * u; // F_ji, equal areas
      unshot[j] += d;
      if (kahan)
      {
        const T y = d - carry[j];
        const T t = b[j] + y;
        carry[j] = (t - b[j]) - y;
        b[j] = t;
      }
      else
      {
        b[j] += d;
      }
    }
    remaining = 0;
    for (T v : unshot)
    {
      remaining += v;
    }
  }
  double worst = 0;
  for (T v : b)
  {
    worst = std::max(worst, std::fabs(v - exact) / exact);
  }
  return worst;
}
} // namespace

TEST(HardReflectance, DoubleAccumulationMattersAtRhoNearOne)
{
  // The 24-element unit cube's exact-ish form factors (polygon to polygon), rho = 0.99,
  // shot to a residual of 1e-7: float accumulation drifts, double (what the solver uses)
  // and compensated float do not (REFERENCES.md: 1.1e-4, 1e-7, 1.2e-6).
  SceneMesh box = Box(1.0, 2, 1, { 0.99, 0.99, 0.99 }, [](int) { return 0; });
  const int n = box.NumberOfPolygons();
  std::vector<double> F(n * n, 0.0);
  for (int i = 0; i < n; ++i)
  {
    std::vector<Vec3> a;
    for (int v = 0; v < 4; ++v)
      a.push_back(box.Points[box.Polygon(i)[v]]);
    for (int j = 0; j < n; ++j)
    {
      std::vector<Vec3> b;
      for (int v = 0; v < 4; ++v)
        b.push_back(box.Points[box.Polygon(j)[v]]);
      F[i * n + j] = i == j ? 0.0 : PolygonToPolygonFormFactor(a.data(), 4, b.data(), 4, 24);
    }
  }
  // Normalize rows to sum to 1 so the furnace answer is exactly 1/(1-rho).
  for (int i = 0; i < n; ++i)
  {
    double sum = 0;
    for (int j = 0; j < n; ++j)
      sum += F[i * n + j];
    for (int j = 0; j < n; ++j)
      F[i * n + j] /= sum;
  }
  const double asFloat = FurnaceError<float>(F, n, 0.99, 1e-7, false);
  const double asDouble = FurnaceError<double>(F, n, 0.99, 1e-7, false);
  const double compensated = FurnaceError<float>(F, n, 0.99, 1e-7, true);
  std::printf("rho 0.99 furnace error: float %.2e, float + Kahan %.2e, double %.2e\n", asFloat,
    compensated, asDouble);
  EXPECT_LT(asDouble, 1e-6);
  EXPECT_GT(asFloat, 10 * asDouble);
  EXPECT_LT(compensated, asFloat);
}

// ---- Adjacency and near-singular geometry --------------------------------------------------

TEST(HardAdjacency, FloorTouchingEmittingWallAlongAnEdge)
{
  // Emitting unit wall on the floor's edge: the floor's area-mean radiosity is
  // rho * F(floor -> wall) = 0.5 * 0.200044 (Howell C-14), with no blow-up at the edge.
  SceneMesh mesh;
  int patch = 0;
  AddGrid(mesh, { 0, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, 1, 1, { 0, 0, 0 }, 0, patch); // x = 0, faces +x
  const int n = 64;
  AddGrid(mesh, { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, n, 4, { 0.5, 0.5, 0.5 }, -1, patch);
  const Solution s = SolveOne(mesh, Converged());
  ASSERT_TRUE(AllFinite(s.Radiosity));
  double mean = 0, peak = 0;
  for (int e = 1; e < mesh.NumberOfPolygons(); ++e)
  {
    mean += s.Radiosity[e].x / (n * n);
    peak = std::max(peak, s.Radiosity[e].x);
  }
  EXPECT_NEAR(mean, 0.5 * 0.200044, 0.5 * 5e-4);
  EXPECT_LT(peak, 0.5 * 0.5); // F(dA -> wall) < 1/2 everywhere on the floor
}

TEST(HardAdjacency, ReceiverTouchingEmitterAtACorner)
{
  // Two unit squares meeting at one corner, at right angles: bounded, and the area mean
  // matches the polygon-to-polygon quadrature (a second method).
  SceneMesh mesh;
  int patch = 0;
  const std::vector<Vec3> wall = { { 0, 1, 0 }, { 0, 2, 0 }, { 0, 2, 1 }, { 0, 1, 1 } }; // x = 0, faces +x
  AddGrid(mesh, wall[0], { 0, 1, 0 }, { 0, 0, 1 }, 1, 1, { 0, 0, 0 }, 0, patch);
  const int n = 48;
  AddGrid(mesh, { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, n, 4, { 1, 1, 1 }, -1, patch);
  const Solution s = SolveOne(mesh, Converged());
  double mean = 0;
  for (int e = 1; e < mesh.NumberOfPolygons(); ++e)
  {
    mean += s.Radiosity[e].x / (n * n);
  }
  const std::vector<Vec3> floor = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } };
  const double reference = PolygonToPolygonFormFactor(floor.data(), 4, wall.data(), 4, 128);
  EXPECT_GT(reference, 0.01);
  EXPECT_NEAR(mean, reference, 2e-3 * reference);
}

TEST(HardAdjacency, EmitterNearlyCoplanarWithReceiver)
{
  // An emitter tilted 1e-6 rad out of the floor plane, next to the floor: almost no
  // light reaches the floor, and what does is finite and non-negative.
  SceneMesh mesh;
  int patch = 0;
  const double tilt = 1e-6;
  AddGrid(mesh, { 0, 0, 0 }, { 0, 1, 0 }, { -1, 0, tilt }, 1, 1, { 0, 0, 0 }, 0, patch); // faces ~+z
  AddGrid(mesh, { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, 16, 4, { 0.5, 0.5, 0.5 }, -1, patch);
  const Solution s = SolveOne(mesh, Converged());
  ASSERT_TRUE(AllFinite(s.Radiosity));
  for (int e = 1; e < mesh.NumberOfPolygons(); ++e)
  {
    EXPECT_LT(s.Radiosity[e].x, 1e-5);
  }
}

// ---- Scale invariance ------------------------------------------------------------------------

TEST(HardScale, SameRadiosityFromMicrometresToKilometres)
{
  std::vector<std::vector<Vec3>> results;
  for (double scale : { 1e-4, 1.0, 1e4 })
  {
    SceneMesh box = Box(2.0 * scale, 6, 2, { 0.6, 0.5, 0.4 }, [](int f) { return f == 1 ? 0 : -1; });
    int patch = 1000;
    // An occluding plate so visibility rays matter too.
    AddGrid(box, Vec3{ 0.5, 0.5, 1.0 } * scale, Vec3{ 1, 0, 0 } * scale, Vec3{ 0, 1, 0 } * scale, 2, 1,
      { 0.3, 0.3, 0.3 }, -1, patch);
    results.push_back(SolveOne(box, Converged(1e-6)).Radiosity);
  }
  for (size_t i = 0; i < results[0].size(); ++i)
  {
    // Lambert's formula is exactly scale-free; what remains is Embree's float geometry,
    // where a rare grazing shadow ray may flip (measured: 1e-6 relative at 1e-4 scale).
    EXPECT_NEAR(results[0][i].x, results[1][i].x, 1e-12 + 1e-5 * results[1][i].x) << i;
    EXPECT_NEAR(results[2][i].x, results[1][i].x, 1e-12 + 1e-5 * results[1][i].x) << i;
  }
}

// ---- Degenerate input ------------------------------------------------------------------------

TEST(HardDegenerate, NonConvexPolygonIsTriangulatedNotFanned)
{
  // An L-shaped hexagon: a fan from vertex 0 would cover area outside it.
  const std::vector<Vec3> l = { { 0, 0, 0 }, { 2, 0, 0 }, { 2, 1, 0 }, { 1, 1, 0 }, { 1, 2, 0 }, { 0, 2, 0 } };
  {
    const std::vector<Vec3>& loop = l;
    const std::vector<int> tri = Triangulate(loop.data(), static_cast<int>(loop.size()));
    ASSERT_EQ(tri.size(), 3 * (loop.size() - 2));
    double area = 0;
    for (size_t t = 0; t < tri.size(); t += 3)
    {
      const double a = 0.5 * Cross(loop[tri[t + 1]] - loop[tri[t]], loop[tri[t + 2]] - loop[tri[t]]).z;
      EXPECT_GT(a, 0) << "every triangle keeps the polygon's orientation";
      area += a;
    }
    EXPECT_NEAR(area, PolygonArea(loop.data(), static_cast<int>(loop.size())), 1e-12);
    EXPECT_NEAR(area, 3.0, 1e-12);
  }
  // The centroid of the L is (5/6, 5/6), outside the fan's triangle (0, 3, 4) mistakes.
  const Vec3 c = PolygonCentroid(l.data(), 6);
  EXPECT_NEAR(c.x, 5.0 / 6.0, 1e-12);
  EXPECT_NEAR(c.y, 5.0 / 6.0, 1e-12);
}

// Polygons of many corners (CAD circles, gears, scanned outlines): ear clipping asks only
// the corners near each ear (CornerGrid) and the self-crossing check only the edges that
// overlap (a sweep), where both used to ask every corner and edge. Checked against what
// any valid answer must be: the triangles tile the polygon (area, orientation, no corner
// strictly inside one), and a loop that crosses itself is still found among thousands.
TEST(HardDegenerate, PolygonsOfManyCornersTriangulateAndCheckExactly)
{
  std::mt19937 random(4);
  std::uniform_real_distribution<double> jitter(0.4, 1.0);
  const Vec3 axis = Normalized({ 0.3, 0.8, 0.2 });
  const Vec3 u = Normalized(Cross(axis, { 1, 0, 0 })), v = Cross(axis, u);
  const double pi = 3.14159265358979;
  // The star again 1e8 m along its normal: the grid hashed the corners' whole coordinates,
  // whose rounding there outgrew its padding, and missed corners inside ears.
  for (const auto [corners, away] : { std::pair{ 2000, 0.0 }, { 20000, 0.0 }, { 2000, 1e8 } })
  {
    std::vector<Vec3> loop;
    for (int i = 0; i < corners; ++i)
    {
      // A star of random spikes, a gear at 20,000; every fifth corner on the rim exactly.
      const double r = corners == 20000 ? 1 - 0.05 * (i % 2) : (i % 5 == 0 ? 1.0 : jitter(random));
      const double t = 2 * pi * i / corners;
      loop.push_back(Vec3{ 5, -3, 2 } + axis * away + u * (r * std::cos(t)) + v * (r * std::sin(t)));
    }
    const int n = static_cast<int>(loop.size());
    ASSERT_EQ(PolygonProblem(loop.data(), n), "") << corners;
    const std::vector<int> tri = Triangulate(loop.data(), n);
    ASSERT_EQ(tri.size(), 3u * (n - 2)) << corners;
    double area = 0;
    for (size_t k = 0; k < tri.size(); k += 3)
    {
      const Vec3 &a = loop[tri[k]], &b = loop[tri[k + 1]], &c = loop[tri[k + 2]];
      const double twice = Dot(axis, Cross(b - a, c - b));
      ASSERT_GT(twice, 0) << corners << ": triangle " << k / 3 << " turned over";
      area += 0.5 * twice;
      if (corners == 2000) // every corner against every triangle
      {
        for (int p = 0; p < n; ++p)
        {
          const double margin = 1e-9 * twice;
          const bool strictly = Dot(axis, Cross(b - a, loop[p] - b)) > margin &&
            Dot(axis, Cross(c - b, loop[p] - c)) > margin && Dot(axis, Cross(a - c, loop[p] - a)) > margin;
          ASSERT_FALSE(strictly) << "corner " << p << " inside triangle " << k / 3;
        }
      }
    }
    EXPECT_NEAR(area, PolygonArea(loop.data(), n), 1e-9 * area) << corners;
    // The corner half way round pulled across to the far side: its edges cross the loop.
    loop[n / 2] = Vec3{ 5, -3, 2 } + axis * away + u * 1.5;
    EXPECT_NE(PolygonProblem(loop.data(), n).find("crosses itself"), std::string::npos) << corners;
  }
}

// The ear test's grid against asking every corner: the same corners, near the origin and
// 1e6..1e10 m away along the plane's normal (hashing the whole coordinates, the grid's
// rounding outgrew its padding there and it missed corners on an ear's edge).
TEST(HardDegenerate, CornerGridFindsEveryCornerATriangleHolds)
{
  std::mt19937 random(11);
  std::uniform_real_distribution<double> coordinate(0, 1);
  const Vec3 axis = Normalized({ 0.3, 0.8, 0.2 });
  const Vec3 u = Normalized(Cross(axis, { 1, 0, 0 })), v = Cross(axis, u);
  for (const double away : { 0.0, 1e6, 1e8, 1e10 })
  {
    std::vector<Vec3> points;
    for (int i = 0; i < 400; ++i)
    {
      // On a coarse lattice, so that many corners lie exactly on triangles' edges.
      const double x = std::round(coordinate(random) * 16) / 16, y = std::round(coordinate(random) * 16) / 16;
      points.push_back(axis * away + u * x + v * y);
    }
    std::vector<int> all(points.size());
    std::iota(all.begin(), all.end(), 0);
    const CornerGrid grid(points.data(), static_cast<int>(points.size()), axis, all);
    const auto turn = [&](int a, int b, int c) { return Dot(axis, Cross(points[b] - points[a], points[c] - points[b])); };
    int missed = 0, held = 0;
    for (int t = 0; t < 2000; ++t)
    {
      const int a = random() % 400, b = random() % 400, c = random() % 400;
      if (!(turn(a, b, c) > 1e-6))
      {
        continue; // an ear turns left: a triangle folded flat "holds" a whole line
      }
      const auto inside = [&](int p) { return turn(a, b, p) >= 0 && turn(b, c, p) >= 0 && turn(c, a, p) >= 0; };
      std::vector<char> found(points.size(), 0);
      grid.Any(a, b, c, [&](int p) { found[p] = 1; return false; });
      for (int p = 0; p < 400; ++p)
      {
        held += inside(p);
        missed += inside(p) && !found[p];
      }
    }
    EXPECT_EQ(missed, 0) << away << " m away, of " << held << " corners inside triangles";
  }
}

// A non-convex polygon with corners in a line (a wall's outline from a real model, the
// FZK-Haus: a long edge split by a vertex 1 mm from its end), turned and scaled so that
// rounding leaves the straight corner a hair off the line. Ear clipping must not cut it
// off as a triangle PolygonProblem calls zero area: the solver would reject the mesh.
TEST(HardDegenerate, StraightCornersMakeNoZeroAreaTriangles)
{
  const std::vector<Vec3> flat = { { 0, 0, 0 }, { 250, 0, 0 }, { 251.3, 0, 0 }, { 251.3, 40, 0 }, { 120, 40, 0 },
    { 120, 80, 0 }, { 0, 80, 0 } };
  for (double degrees : { 0.0, 17.0, 37.0, 61.0 })
  {
    const double t = degrees * 3.14159265358979 / 180;
    std::vector<Vec3> loop;
    for (const Vec3& p : flat)
    {
      const Vec3 q = p * 1000.0 + Vec3{ -524, 2100, -8096 } * 1000.0;
      loop.push_back({ std::cos(t) * q.x - std::sin(t) * q.z, q.y + 0.3 * std::sin(t) * q.x, std::sin(t) * q.x + std::cos(t) * q.z });
    }
    const std::vector<int> tri = Triangulate(loop.data(), static_cast<int>(loop.size()));
    double area = 0;
    for (size_t k = 0; k < tri.size(); k += 3)
    {
      const Vec3 corners[3] = { loop[tri[k]], loop[tri[k + 1]], loop[tri[k + 2]] };
      EXPECT_EQ(PolygonProblem(corners, 3), "") << degrees << " degrees, triangle " << k / 3;
      area += PolygonArea(corners, 3);
    }
    const double whole = PolygonArea(loop.data(), static_cast<int>(loop.size()));
    EXPECT_NEAR(area, whole, 1e-9 * whole) << degrees << " degrees: the triangles cover the polygon";
  }
}

TEST(HardDegenerate, SliversAndRepeatedVerticesStayFinite)
{
  SceneMesh mesh = LampOverFloor(1.0, 4);
  // A sliver triangle (1e-9 wide) and a quad with a repeated vertex, both on the floor.
  const int base = static_cast<int>(mesh.Points.size());
  mesh.Points.insert(mesh.Points.end(), { { 1.2, 0, 0 }, { 2.2, 0, 0 }, { 1.2, 1e-9, 0 } });
  mesh.AddPolygon({ base, base + 1, base + 2 });
  mesh.Points.insert(mesh.Points.end(), { { 1.2, 0.5, 0 }, { 1.7, 0.5, 0 }, { 1.7, 1.0, 0 } });
  mesh.AddPolygon({ base + 3, base + 4, base + 4, base + 5 });
  for (int i = 0; i < 2; ++i)
  {
    mesh.Reflectance.push_back({ 0.5, 0.5, 0.5 });
    mesh.LightId.push_back(-1);
    mesh.PatchId.push_back(100 + i);
  }
  int k = 0;
  ASSERT_EQ(ValidateScene(mesh, k), "");
  const Solution s = SolveOne(mesh, Converged());
  ASSERT_TRUE(AllFinite(s.Radiosity));
  // The degenerate quad is a triangle: it receives like one (positive, bounded).
  EXPECT_GT(s.Radiosity.back().x, 0);
  EXPECT_LT(s.Radiosity.back().x, 0.5);
}

TEST(HardDegenerate, FlippedRoomAndLightFacingAwayReceiveNothing)
{
  // Walls facing outwards see nothing from inside; a light facing away lights nothing.
  SceneMesh flipped = Box(1.0, 2, 1, { 0.5, 0.5, 0.5 }, [](int f) { return f == 1 ? 0 : -1; });
  for (int e = 0; e < flipped.NumberOfPolygons(); ++e)
  {
    std::reverse(flipped.Connectivity.begin() + flipped.Offsets[e], flipped.Connectivity.begin() + flipped.Offsets[e + 1]);
  }
  const Solution s = SolveOne(flipped, Converged());
  ASSERT_TRUE(s.Statistics.Converged);
  for (int e = 0; e < flipped.NumberOfPolygons(); ++e)
  {
    EXPECT_EQ(s.Radiosity[e].x, flipped.LightId[e] == 0 ? 1.0 : 0.0) << e;
  }
  EXPECT_NEAR(s.Statistics.EscapedPower, s.Statistics.EmittedPower, 1e-12);
}

TEST(HardDegenerate, LightCoplanarWithCeilingStillLightsTheFloor)
{
  // The Cornell box's trap: a lamp lying exactly in the ceiling plane. The floor's
  // direct light must be the same as without the ceiling.
  auto scene = [](bool ceiling) {
    SceneMesh mesh = LampOverFloor(1.0, 4);
    int patch = 100;
    if (ceiling)
    {
      AddGrid(mesh, { -1, -1, 1 }, { 0, 3, 0 }, { 3, 0, 0 }, 3, 1, { 0.7, 0.7, 0.7 }, -1, patch);
    }
    return mesh;
  };
  SolverOptions o = Converged();
  o.SeparateDirect = true;
  const Solution with = SolveOne(scene(true), o);
  const Solution without = SolveOne(scene(false), o);
  for (int e = 1; e <= 16; ++e)
  {
    EXPECT_NEAR(with.Direct[e].x, without.Direct[e].x, 1e-12) << e;
    EXPECT_GT(with.Direct[e].x, 0.0);
  }
}

TEST(HardDegenerate, CoincidentAndIntersectingFacesStayFinite)
{
  SceneMesh mesh = LampOverFloor(1.0, 4);
  int patch = 100;
  // A second floor exactly on top of the first (z-fighting), and a plate through it.
  AddGrid(mesh, { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, 4, 1, { 0.9, 0.1, 0.1 }, -1, patch);
  AddGrid(mesh, { 0.5, -0.2, -0.3 }, { 0, 1.4, 0 }, { 0, 0, 0.8 }, 2, 1, { 0.5, 0.5, 0.5 }, -1, patch);
  const Solution s = SolveOne(mesh, Converged());
  ASSERT_TRUE(AllFinite(s.Radiosity));
  EXPECT_LE(s.Statistics.UnshotPower, 1e-7 * s.Statistics.EmittedPower);
}

// ---- Many and extreme lights -----------------------------------------------------------------

TEST(HardLights, SixtyFourLightsTaggedEqualsSeparate)
{
  SceneMesh mesh = Box(4.0, 4, 2, { 0.5, 0.5, 0.5 }, [](int) { return -1; });
  int patch = 1000;
  for (int l = 0; l < 64; ++l)
  {
    const double x = 0.25 + 0.45 * (l % 8), y = 0.25 + 0.45 * (l / 8);
    AddGrid(mesh, { x, y, 3.99 }, { 0, 0.1, 0 }, { 0.1, 0, 0 }, 1, 1, { 0.5, 0.5, 0.5 }, l, patch);
  }
  int k = 0;
  ASSERT_EQ(ValidateScene(mesh, k), "");
  ASSERT_EQ(k, 64);
  RadiositySolver solver(mesh);
  const LightGrouping g = LightGrouping::OnePerLight(k);
  const Solution tagged = SolveLights(solver, mesh, g, {}, SolutionMode::LightTagged, Converged(1e-5));
  const Solution separate = SolveLights(solver, mesh, g, {}, SolutionMode::StandardSeparate, Converged(1e-5));
  double worst = 0;
  for (size_t i = 0; i < tagged.Radiosity.size(); ++i)
  {
    worst = std::max(worst, std::fabs(tagged.Radiosity[i].x - separate.Radiosity[i].x));
  }
  EXPECT_LT(worst, 1e-4);
}

TEST(HardLights, TinyLightGetsTheExactFormFactor)
{
  // A 1e-6 x 1e-6 lamp at height 1 over a receiver: the radiosity of the element right
  // below is rho * F(dA -> lamp) ~ rho * A / pi (cosines 1), however small the lamp.
  SceneMesh mesh;
  int patch = 0;
  const double s = 1e-6;
  AddGrid(mesh, { 0.5 - s / 2, 0.5 - s / 2, 1 }, { 0, s, 0 }, { s, 0, 0 }, 1, 1, { 0, 0, 0 }, 0, patch);
  AddGrid(mesh, { 0.49, 0.49, 0 }, { 0.02, 0, 0 }, { 0, 0.02, 0 }, 1, 1, { 0.5, 0.5, 0.5 }, -1, patch);
  const Solution sol = SolveOne(mesh, Converged());
  EXPECT_NEAR(sol.Radiosity[1].x, 0.5 * s * s / 3.14159265358979323846, 1e-6 * 0.5 * s * s);
}

TEST(HardLights, LightThatReachesNothing)
{
  // A lamp facing into empty space: its solution is zero everywhere but on itself.
  SceneMesh mesh;
  int patch = 0;
  AddGrid(mesh, { 0, 0, 2 }, { 1, 0, 0 }, { 0, 1, 0 }, 1, 1, { 0.5, 0.5, 0.5 }, 0, patch); // faces +z, away
  AddGrid(mesh, { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, 4, 1, { 0.5, 0.5, 0.5 }, -1, patch);
  const Solution s = SolveOne(mesh, Converged());
  ASSERT_TRUE(s.Statistics.Converged);
  EXPECT_EQ(s.Statistics.Shots, 1);
  for (int e = 1; e < mesh.NumberOfPolygons(); ++e)
  {
    EXPECT_EQ(s.Radiosity[e].x, 0.0);
  }
}

// ---- Light leaks -----------------------------------------------------------------------------

TEST(HardLeaks, ClosedBoxWithUnweldedSeamsKeepsOutsideLightOut)
{
  // Six quads with their own vertices (no shared points at the seams) enclose a room; a
  // lamp outside shines at the seams. Not a single ray may slip through an edge.
  SceneMesh mesh = Box(1.0, 8, 2, { 0.8, 0.8, 0.8 }, [](int) { return -1; }); // own points per face
  int patch = 1000;
  // Lamps facing each edge of the box from outside, very close to it.
  AddGrid(mesh, { 1.001, -0.5, -0.5 }, { 0, 0, 2 }, { 0, 2, 0 }, 1, 1, { 0, 0, 0 }, 0, patch); // faces -x
  AddGrid(mesh, { -0.5, -0.5, -0.001 }, { 0, 2, 0 }, { 2, 0, 0 }, 1, 1, { 0, 0, 0 }, 0, patch); // faces -z? below
  SolverOptions o = Converged(1e-9);
  o.FormFactorSamples = 64;
  const Solution s = SolveOne(mesh, o);
  // Interior faces point inward; the outside light hits only their backs.
  for (int e = 0; e < 6 * 64; ++e)
  {
    EXPECT_EQ(s.Radiosity[e].x, 0.0) << "light leaked into element " << e;
  }
}

TEST(HardLeaks, RaysAimedAtSharedEdgesAndVerticesAreBlocked)
{
  // A closed, welded cube mesh (8 x 8 per face, shared points): rays from inside to
  // outside points through exact vertex and edge positions must all be occluded.
  SceneMesh cube;
  const int n = 8;
  auto id = [&](int i, int j, int k) { return (i * (n + 1) + j) * (n + 1) + k; };
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k)
        cube.Points.push_back({ double(i) / n, double(j) / n, double(k) / n });
  auto quad = [&](int a, int b, int c, int d) { cube.AddPolygon({ a, b, c, d }); };
  for (int u = 0; u < n; ++u)
    for (int v = 0; v < n; ++v)
    {
      quad(id(0, u, v), id(0, u + 1, v), id(0, u + 1, v + 1), id(0, u, v + 1));
      quad(id(n, u, v), id(n, u, v + 1), id(n, u + 1, v + 1), id(n, u + 1, v));
      quad(id(u, 0, v), id(u, 0, v + 1), id(u + 1, 0, v + 1), id(u + 1, 0, v));
      quad(id(u, n, v), id(u + 1, n, v), id(u + 1, n, v + 1), id(u, n, v + 1));
      quad(id(u, v, 0), id(u + 1, v, 0), id(u + 1, v + 1, 0), id(u, v + 1, 0));
      quad(id(u, v, n), id(u, v + 1, n), id(u + 1, v + 1, n), id(u + 1, v, n));
    }
  Visibility rays(cube);
  ASSERT_EQ(rays.Error(), "");
  const Vec3 centre{ 0.5, 0.5, 0.5 };
  int escaped = 0, total = 0;
  for (const Vec3& p : cube.Points)
  {
    const bool onSurface = p.x == 0 || p.x == 1 || p.y == 0 || p.y == 1 || p.z == 0 || p.z == 1;
    if (!onSurface)
      continue;
    // Through the vertex itself and through the middle of an edge next to it.
    for (const Vec3& target : { p, p + Vec3{ 0.5 / n, 0, 0 } })
    {
      const Vec3 beyond = centre + (target - centre) * 3.0;
      ++total;
      escaped += rays.Occluded(centre, beyond, 1e-9) ? 0 : 1;
    }
  }
  EXPECT_GT(total, 700);
  EXPECT_EQ(escaped, 0);
}

// ---- Invariants on random scenes -------------------------------------------------------------

namespace
{
/// A random closed-ish room: box with random reflectances per face, random lamps on the
/// ceiling and a random occluding plate.
SceneMesh RandomRoom(std::mt19937& rng, int lights, double rhoScale = 1.0)
{
  std::uniform_real_distribution<double> u(0.0, 1.0);
  SceneMesh mesh;
  int patch = 0;
  const Vec3 X{ 3, 0, 0 }, Y{ 0, 2.5, 0 }, Z{ 0, 0, 3 }, O{ 0, 0, 0 };
  const Vec3 origins[6] = { O, Z, O, Y, O, X };
  const Vec3 us[6] = { X, Y, Z, X, Y, Z };
  const Vec3 vs[6] = { Y, X, X, Z, Z, Y };
  for (int f = 0; f < 6; ++f)
  {
    const Vec3 rho{ 0.1 + 0.8 * u(rng) * rhoScale, 0.1 + 0.8 * u(rng) * rhoScale, 0.1 + 0.8 * u(rng) * rhoScale };
    AddGrid(mesh, origins[f], us[f], vs[f], 6, 2, rho, -1, patch);
  }
  for (int l = 0; l < lights; ++l)
  {
    const Vec3 at{ 0.2 + 2.4 * u(rng), 2.49, 0.2 + 2.4 * u(rng) };
    AddGrid(mesh, at, { 0.3, 0, 0 }, { 0, 0, 0.3 }, 1, 1, { 0.5, 0.5, 0.5 }, l, patch); // faces -y
  }
  const Vec3 plate{ 0.5 + u(rng), 0.5 + u(rng), 0.5 + u(rng) };
  AddGrid(mesh, plate, { 1, 0, 0 }, { 0, 0, 1 }, 2, 1, { 0.5 * rhoScale, 0.4, 0.3 }, -1, patch); // faces -y
  AddGrid(mesh, plate + Vec3{ 0, 0.001, 0 }, { 0, 0, 1 }, { 1, 0, 0 }, 2, 1, { 0.5 * rhoScale, 0.4, 0.3 }, -1, patch);
  return mesh;
}
} // namespace

TEST(HardInvariants, ReciprocityOnRandomPolygonPairs)
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int checked = 0;
  for (int trial = 0; trial < 20; ++trial)
  {
    std::vector<Vec3> a, b;
    const Vec3 ca{ u(rng), u(rng), u(rng) }, cb = ca + Vec3{ u(rng), u(rng), 2 + u(rng) };
    for (int v = 0; v < 3; ++v)
    {
      a.push_back(ca + Vec3{ u(rng), u(rng), 0.2 * u(rng) });
      b.push_back(cb + Vec3{ u(rng), u(rng), 0.2 * u(rng) });
    }
    const double fab = PolygonToPolygonFormFactor(a.data(), 3, b.data(), 3, 40);
    const double fba = PolygonToPolygonFormFactor(b.data(), 3, a.data(), 3, 40);
    if (fab < 1e-3 || fba < 1e-3)
      continue; // facing away: nothing to compare
    ++checked;
    EXPECT_NEAR(PolygonArea(a.data(), 3) * fab, PolygonArea(b.data(), 3) * fba, 2e-3 * PolygonArea(a.data(), 3) * fab);
  }
  EXPECT_GE(checked, 3);
}

TEST(HardInvariants, EnergyLedgerClosesOnRandomRooms)
{
  // Emitted = absorbed + escaped + unshot, with "absorbed" recomputed from the output
  // radiosity, not from the solver's own bookkeeping.
  std::mt19937 rng(5);
  for (int trial = 0; trial < 4; ++trial)
  {
    SceneMesh mesh = RandomRoom(rng, 3);
    const Solution s = SolveOne(mesh, Converged(1e-3), 3);
    const double absorbed = radiosity_test::AbsorbedPower(mesh, s);
    const SolverStatistics& t = s.Statistics;
    EXPECT_NEAR(absorbed + t.EscapedPower + t.UnshotPower, t.EmittedPower, 1e-9 * t.EmittedPower) << trial;
    EXPECT_GT(t.UnshotPower, 0);
    // A closed room loses almost nothing: what shows is the centroid quadrature of the
    // form factors on 0.5 m elements (measured 1.6-2.5 %), not a leak.
    EXPECT_LT(std::fabs(t.EscapedPower), 0.05 * t.EmittedPower) << trial;
  }
}

TEST(HardInvariants, LinearityInEmission)
{
  std::mt19937 rng(3);
  SceneMesh mesh = RandomRoom(rng, 2);
  RadiositySolver solver(mesh);
  std::vector<Vec3> e1(mesh.NumberOfPolygons()), e2(mesh.NumberOfPolygons());
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    if (mesh.LightId[e] == 0)
      e1[e] = { 1, 1, 1 };
    if (mesh.LightId[e] == 1)
      e2[e] = { 1, 1, 1 };
  }
  std::vector<Vec3> mix(mesh.NumberOfPolygons());
  for (size_t e = 0; e < mix.size(); ++e)
  {
    mix[e] = e1[e] * 3.0 + e2[e] * 0.25;
  }
  const SolverOptions o = Converged(1e-10);
  const Solution a = solver.Solve(e1, 1, o), b = solver.Solve(e2, 1, o), c = solver.Solve(mix, 1, o);
  for (size_t e = 0; e < mix.size(); ++e)
  {
    EXPECT_NEAR(c.Radiosity[e].x, 3.0 * a.Radiosity[e].x + 0.25 * b.Radiosity[e].x, 1e-8);
  }
}

TEST(HardInvariants, MirrorSymmetricSceneGivesMirrorSymmetricResult)
{
  // A box with a lamp centred in x: element (x, ...) and its mirror (2 - x, ...) agree.
  SceneMesh mesh = Box(2.0, 8, 2, { 0.6, 0.6, 0.6 }, [](int) { return -1; });
  int patch = 1000;
  AddGrid(mesh, { 0.8, 0.8, 1.99 }, { 0, 0.4, 0 }, { 0.4, 0, 0 }, 2, 2, { 0.5, 0.5, 0.5 }, 0, patch);
  SolverOptions o = Converged(1e-9);
  o.FormFactorSamples = 0; // convex room: nothing to occlude, so no sampling noise either
  const Solution s = SolveOne(mesh, o);
  const SceneGeometry g(mesh);
  int pairs = 0;
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    const Vec3 mirror{ 2.0 - g.Centroid[e].x, g.Centroid[e].y, g.Centroid[e].z };
    for (int f = 0; f < mesh.NumberOfPolygons(); ++f)
    {
      if (Norm(g.Centroid[f] - mirror) < 1e-9 && Dot(g.Normal[f], Vec3{ -g.Normal[e].x, g.Normal[e].y, g.Normal[e].z }) > 0.999)
      {
        ++pairs;
        EXPECT_NEAR(s.Radiosity[e].x, s.Radiosity[f].x, 1e-9 + 1e-7 * s.Radiosity[e].x) << e << " vs " << f;
      }
    }
  }
  EXPECT_GT(pairs, 300);
}

TEST(HardInvariants, MoreReflectanceNeverDarkensAnything)
{
  std::mt19937 rngA(9), rngB(9);
  SceneMesh dim = RandomRoom(rngA, 2, 0.5);
  SceneMesh bright = RandomRoom(rngB, 2, 1.0); // same geometry, reflectances >= dim's
  SolverOptions o = Converged(1e-9);
  o.FormFactorSamples = 16;
  const Solution a = SolveOne(dim, o, 2), b = SolveOne(bright, o, 2);
  for (size_t i = 0; i < a.Radiosity.size(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_GE(b.Radiosity[i][c], a.Radiosity[i][c] - 1e-12) << i;
    }
  }
}

TEST(HardDegenerate, OpenBoxConvergesAndCountsWhatEscapes)
{
  // No lid: a third of the light leaves through the opening. The solve still converges
  // (escaping energy is simply never shot again) and the ledger accounts for it.
  SceneMesh box = Box(1.0, 6, 2, { 0.7, 0.7, 0.7 }, [](int f) { return f == 0 ? 0 : -1; });
  SceneMesh open;
  const SceneGeometry geometry(box);
  for (int e = 0; e < box.NumberOfPolygons(); ++e)
  {
    if (geometry.Centroid[e].z > 1 - 1e-9)
      continue; // drop the lid (z = 1)
    std::vector<int> ids(box.Polygon(e), box.Polygon(e) + 4);
    open.AddPolygon(ids);
    open.Reflectance.push_back(box.Reflectance[e]);
    open.LightId.push_back(box.LightId[e]);
    open.PatchId.push_back(box.PatchId[e]);
  }
  open.Points = box.Points;
  const Solution s = SolveOne(open, Converged(1e-8));
  ASSERT_TRUE(s.Statistics.Converged);
  ASSERT_TRUE(AllFinite(s.Radiosity));
  const SolverStatistics& t = s.Statistics;
  EXPECT_GT(t.EscapedPower, 0.2 * t.EmittedPower);
  EXPECT_LT(t.EscapedPower, t.EmittedPower);
}

namespace
{
/// The 4 m room (0.25 m elements) with a closed 1 m box on its floor, faces outwards, and a
/// `size` lamp facing down at `height` inside it: the box's bottom lies on the floor.
SceneMesh LampShutInABox(double size, double height)
{
  SceneMesh mesh = Box(4.0, 16, 2, { 0.7, 0.7, 0.7 }, [](int) { return -1; });
  int patch = 1000;
  const Vec3 X{ 1, 0, 0 }, Y{ 0, 1, 0 }, Z{ 0, 0, 1 }, O{ 1, 1, 0 };
  const Vec3 rho{ 0.7, 0.7, 0.7 };
  AddGrid(mesh, O, Y, X, 4, 2, rho, -1, patch);                 // bottom, facing down onto the floor
  AddGrid(mesh, O + Z, X, Y, 4, 2, rho, -1, patch);             // top
  AddGrid(mesh, O, X, Z, 4, 2, rho, -1, patch);                 // y = 1
  AddGrid(mesh, O + Y, Z, X, 4, 2, rho, -1, patch);             // y = 2
  AddGrid(mesh, O, Z, Y, 4, 2, rho, -1, patch);                 // x = 1
  AddGrid(mesh, O + X, Y, Z, 4, 2, rho, -1, patch);             // x = 2
  const Vec3 corner{ 1.5 - size / 2, 1.5 - size / 2, height };
  AddGrid(mesh, corner, Y * size, X * size, 1, 1, rho, 0, patch); // the lamp, facing down
  return mesh;
}
} // namespace

TEST(HardCases, ALampShutInABoxOnTheFloorLightsNothingAndTheLedgerCloses)
{
  // The box's bottom lies on the floor, so rays from the lamp pass between them to the
  // floor under the box (its 16 elements took up to 0.016 of a small lamp's light; with a
  // 0.9 m lamp 0.1 m up, nearly all of it). No surface outside the lamp takes any light,
  // and what the rays brought there is booked as escaped, so the ledger closes.
  for (const auto& lamp : { std::pair<double, double>{ 0.3, 0.9 }, { 0.9, 0.1 }, { 0.9, 0.5 } })
  {
    const SceneMesh mesh = LampShutInABox(lamp.first, lamp.second);
    const Solution s = SolveOne(mesh, Converged(1e-4));
    double lit = 0;
    for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
    {
      lit = std::max(lit, mesh.LightId[e] < 0 ? s.Radiosity[e].x : 0.0);
    }
    EXPECT_EQ(lit, 0.0) << "lamp " << lamp.first << " m at " << lamp.second << " m";
    const SolverStatistics& t = s.Statistics;
    EXPECT_NEAR(radiosity_test::AbsorbedPower(mesh, s) + t.EscapedPower + t.UnshotPower, t.EmittedPower,
      1e-9 * t.EmittedPower) << "lamp " << lamp.first << " m at " << lamp.second << " m";
  }
}
