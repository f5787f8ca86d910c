// The final gather at the mesh's points: closed forms, no leaks through a wall at any
// method, light tagging kept exact, and the same bits on any number of threads.
#include "Geometry/FormFactor.h"
#include "Solve/FinalGather.h"
#include "Solve/LightSolutions.h"
#include "Solve/PatchBasis.h"
#include "Relight/MovingLights.h"
#include "SceneBuilders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

using namespace radiosity;
using radiosity_test::TwoRooms;
using radiosity_test::AddGrid;
using radiosity_test::Box;
using radiosity_test::Converged;

namespace
{
SolverOptions Gathering(int rays = 64, double threshold = 1e-7)
{
  SolverOptions o = Converged(threshold);
  o.Gather.Rays = rays;
  return o;
}

Solution SolveTagged(const SceneMesh& mesh, const SolverOptions& o, int lights)
{
  const RadiositySolver solver(mesh);
  return SolveLights(solver, mesh, LightGrouping::OnePerLight(lights), {}, SolutionMode::LightTagged, o);
}

/// The point of `mesh` nearest to `x`.
int PointAt(const SceneMesh& mesh, const Vec3& x)
{
  int best = 0;
  for (size_t p = 0; p < mesh.Points.size(); ++p)
  {
    if (Norm(mesh.Points[p] - x) < Norm(mesh.Points[best] - x))
    {
      best = static_cast<int>(p);
    }
  }
  return best;
}

} // namespace

TEST(FinalGather, PointUnderASquareLampTakesLambertsFormula)
{
  // A unit lamp 1 m over a floor vertex, nothing else that reflects: the vertex's value is
  // rho * F(dA -> square) exactly (REFERENCES.md: 0.2394565 centred under a unit square).
  SceneMesh mesh;
  int patch = 0;
  AddGrid(mesh, { -1, -1, 0 }, { 2, 0, 0 }, { 0, 2, 0 }, 8, 2, { 0.5, 0.5, 0.5 }, -1, patch);
  AddGrid(mesh, { -0.5, -0.5, 1 }, { 0, 1, 0 }, { 1, 0, 0 }, 2, 1, { 0, 0, 0 }, 0, patch);
  const Solution s = SolveTagged(mesh, Gathering(), 1);
  ASSERT_EQ(s.PointRadiosity.size(), mesh.Points.size());
  const int centre = PointAt(mesh, { 0, 0, 0 });
  EXPECT_NEAR(s.PointRadiosity[centre].x, 0.5 * 0.2394565, 1e-6);
  // The corner of a 1 x 1 rectangle at height 1 (REFERENCES.md: 0.138532), under the lamp's corner.
  const int corner = PointAt(mesh, { 0.5, 0.5, 0 });
  EXPECT_NEAR(s.PointRadiosity[corner].x, 0.5 * 0.138532, 1e-6);
  // Where the floor is evaluated, the element solution is only its means: a point under
  // the lamp's centre is brighter than the element mean there.
  EXPECT_GT(s.PointRadiosity[centre].x, 0);
}

TEST(FinalGather, FurnaceGivesTheClosedFormAtEveryPoint)
{
  // A closed box emitting 1 everywhere at rho 0.5: B = E / (1 - rho) = 2 at every point.
  const SceneMesh mesh = Box(1.0, 4, 2, { 0.5, 0.5, 0.5 }, [](int) { return 0; });
  const Solution s = SolveTagged(mesh, Gathering(64, 1e-9), 1);
  ASSERT_EQ(s.PointRadiosity.size(), mesh.Points.size());
  for (size_t p = 0; p < mesh.Points.size(); ++p)
  {
    EXPECT_NEAR(s.PointRadiosity[p].x, 2.0, 2e-3) << "point " << p;
  }
}

TEST(FinalGather, EachSweepTakesUpWhatTheElementSolutionLostByTheReflectance)
{
  // The furnace again (B = 2), gathered over an element solution that lost every bounce
  // (B = E = 1): sweep n gives 1 + rho * B(n-1), so 1.5, 1.75, 1.875. A later sweep reuses
  // the first one's direct light: the same bits, and without cosine rays no rays at all.
  const SceneMesh mesh = Box(1.0, 4, 2, { 0.5, 0.5, 0.5 }, [](int) { return 0; });
  const RadiositySolver solver(mesh);
  const std::vector<Vec3> emission = SolutionEmission(mesh, LightGrouping::OnePerLight(1), {});
  auto sweep = [&](int sweeps, int rays) {
    GatherSettings settings;
    settings.Sweeps = sweeps;
    settings.SweepRays = rays;
    return GatherAtPoints(mesh, solver.Geometry(), solver.Rays(), emission, emission, 1, settings, 1);
  };
  const GatheredPoints one = sweep(1, 16);
  for (int n = 1; n <= 3; ++n)
  {
    const GatheredPoints swept = sweep(n, 16);
    ASSERT_EQ(swept.Cells.size(), emission.size());
    for (size_t e = 0; e < swept.Cells.size(); ++e)
    {
      EXPECT_NEAR(swept.Cells[e].x, 2.0 - std::pow(0.5, n), 1e-3) << "sweep " << n << ", element " << e;
      EXPECT_EQ(swept.CellsDirect[e].x, one.CellsDirect[e].x) << "sweep " << n << ", element " << e;
    }
  }
  EXPECT_EQ(sweep(3, 0).Rays, sweep(1, 0).Rays);
}

/// What may reach the second room: nothing, but for the clustered method, whose far links
/// deliver to every element of a node alike and so to a node's elements behind the wall,
/// and a sweep's rays from a cell there read it (at the default separation, 3, measured up
/// to 2.0e-5 on the cells here and 1.9e-6 at the points, which read those cells, against
/// 0.05-0.2 in the lit room; at separation 4, 3.1e-6 on the cells).
double Leak(SolverMethod method)
{
  return method == SolverMethod::Clustered ? 3e-5 : 0.0;
}

TEST(FinalGather, NoLightReachesTheRoomBehindAWallAtAnyMethod)
{
  const SceneMesh mesh = TwoRooms(10);
  for (SolverMethod method : { SolverMethod::ProgressiveRefinement, SolverMethod::Hierarchical, SolverMethod::Clustered })
  {
    SolverOptions o = Gathering(64, 1e-6);
    o.SolverMethod = method;
    const Solution s = SolveTagged(mesh, o, 1);
    ASSERT_EQ(s.PointRadiosity.size(), mesh.Points.size());
    double lit = 0;
    for (size_t p = 0; p < mesh.Points.size(); ++p)
    {
      const double x = mesh.Points[p].x;
      if (x > 1.2 + 1e-9)
      {
        EXPECT_LE(s.PointRadiosity[p].x, Leak(method)) << "point " << p << " at x " << x << ", method " << int(method);
      }
      lit += x < 1.0 ? s.PointRadiosity[p].x : 0.0;
    }
    for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
    {
      const int* ids = mesh.Polygon(e);
      if (mesh.Points[ids[0]].x > 1.2 - 1e-9 && mesh.Points[ids[2]].x > 1.2 - 1e-9)
      {
        EXPECT_LE(s.Radiosity[e].x, Leak(method)) << "element " << e << ", method " << int(method);
      }
    }
    EXPECT_GT(lit, 0.0);
  }
}

TEST(FinalGather, TaggedSumIsTheCombinedAndLinear)
{
  // Two lamps over a floor in an open box: the gather of the combined solve equals the
  // sum of the tagged ones at every point; the gather is linear in the solution.
  SceneMesh mesh = Box(2.0, 6, 2, { 0.6, 0.5, 0.4 }, [](int f) { return f == 1 ? 0 : (f == 4 ? 1 : -1); });
  const RadiositySolver solver(mesh);
  const SolverOptions o = Gathering(64, 1e-9);
  const Solution tagged =
    SolveLights(solver, mesh, LightGrouping::OnePerLight(2), {}, SolutionMode::LightTagged, o);
  const Solution combined =
    SolveLights(solver, mesh, LightGrouping::OnePerLight(2), {}, SolutionMode::StandardCombined, o);
  double peak = 0, worst = 0;
  for (size_t p = 0; p < mesh.Points.size(); ++p)
  {
    const double sum = tagged.PointRadiosity[2 * p].y + tagged.PointRadiosity[2 * p + 1].y;
    peak = std::max(peak, combined.PointRadiosity[p].y);
    worst = std::max(worst, std::fabs(sum - combined.PointRadiosity[p].y));
  }
  EXPECT_LT(worst, 1e-6 * peak);
  std::vector<Vec3> emission(mesh.NumberOfPolygons()), doubled(mesh.NumberOfPolygons());
  std::vector<Vec3> solved = tagged.Radiosity, twice(tagged.Radiosity.size());
  const std::vector<Vec3> e2 = SolutionEmission(mesh, LightGrouping::OnePerLight(2), {});
  std::vector<Vec3> e2x(e2.size()), b2x(e2.size());
  const Solution plain = SolveLights(solver, mesh, LightGrouping::OnePerLight(2), {}, SolutionMode::LightTagged,
    Converged(1e-9));
  for (size_t i = 0; i < e2.size(); ++i)
  {
    e2x[i] = e2[i] * 2.5;
    b2x[i] = plain.Radiosity[i] * 2.5;
  }
  const GatheredPoints one = GatherAtPoints(mesh, solver.Geometry(), solver.Rays(), e2, plain.Radiosity, 2, o.Gather);
  const GatheredPoints two = GatherAtPoints(mesh, solver.Geometry(), solver.Rays(), e2x, b2x, 2, o.Gather);
  for (size_t i = 0; i < one.Radiosity.size(); ++i)
  {
    EXPECT_NEAR(two.Radiosity[i].x, 2.5 * one.Radiosity[i].x, 1e-9 * (1 + one.Radiosity[i].x));
  }
}

TEST(FinalGather, SameBitsOnOneAndTwoThreads)
{
  const SceneMesh mesh = TwoRooms(5);
  const RadiositySolver solver(mesh);
  const std::vector<Vec3> emission = SolutionEmission(mesh, LightGrouping::OnePerLight(1), {});
  const Solution s = solver.Solve(emission, 1, Converged(1e-6));
  GatherSettings settings;
  const GatheredPoints one = GatherAtPoints(mesh, solver.Geometry(), solver.Rays(), emission, s.Radiosity, 1, settings, 1);
  const GatheredPoints two = GatherAtPoints(mesh, solver.Geometry(), solver.Rays(), emission, s.Radiosity, 1, settings, 2);
  ASSERT_EQ(one.Radiosity.size(), two.Radiosity.size());
  for (size_t i = 0; i < one.Radiosity.size(); ++i)
  {
    EXPECT_EQ(one.Radiosity[i].x, two.Radiosity[i].x) << i;
    EXPECT_EQ(one.Direct[i].x, two.Direct[i].x) << i;
  }
  EXPECT_EQ(one.Rays, two.Rays);
}

TEST(FinalGather, AStoppedGatherKeepsTheElementSolution)
{
  const SceneMesh mesh = TwoRooms(5);
  SolverOptions o = Gathering();
  int calls = 0;
  o.Progress = [&calls](double) { return ++calls < 3; };
  const Solution s = SolveTagged(mesh, o, 1);
  EXPECT_TRUE(s.PointRadiosity.empty());
  EXPECT_TRUE(s.Statistics.Aborted);
}

TEST(FinalGather, ClosedRoomNearRhoOneAtTheDefaultsTakesTheClosedForm)
{
  // A closed 4 m room of uniform rho, one ceiling element emitting: light only leaves by
  // absorption, so sum A B = sum A E / (1 - rho) exactly, whatever the view factors. At the
  // defaults the shot cap stops rho = 0.999 long before it converges (the ambient term takes
  // up the rest); the gathered answer must still hold the closed form.
  for (double rho : { 0.99, 0.999 })
  {
    SceneMesh mesh = Box(4.0, 8, 2, { rho, rho, rho }, [](int) { return -1; });
    mesh.LightId[64 + 27] = 0; // a ceiling element near the middle
    SolverOptions o; // the defaults: Auto, threshold 1e-3, the automatic shot cap
    o.Gather.Rays = 64;
    const Solution s = SolveTagged(mesh, o, 1);
    const SceneGeometry g(mesh);
    double power = 0, emitted = 0, pointsMean = 0;
    for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
    {
      power += s.Radiosity[e].x * g.Area[e];
      emitted += (mesh.LightId[e] == 0 ? 1.0 : 0.0) * g.Area[e];
    }
    const double exact = emitted / (1 - rho);
    EXPECT_NEAR(power / exact, 1.0, 0.01) << "rho " << rho << ", " << s.Statistics.Shots << " shots";
    for (const Vec3& b : s.PointRadiosity)
    {
      pointsMean += b.x / s.PointRadiosity.size();
    }
    // Far from the lamp the light is nearly even: the points' mean holds it too.
    EXPECT_NEAR(pointsMean * 96.0 / exact, 1.0, 0.02) << "rho " << rho;
  }
}

TEST(FinalGather, ConvexCornersOfAWeldedBlockAreNotDark)
{
  // A block whose faces share their corner points (a curved or welded CAD solid meshed
  // as it came): each corner's elements lie on three planes and their centre inside the
  // block. The corner must start its rays outside, not inside the solid.
  SceneMesh mesh = Box(4.0, 4, 2, { 0.5, 0.5, 0.5 }, [](int f) { return f == 1 ? 0 : -1; });
  const int base = static_cast<int>(mesh.Points.size());
  for (int c = 0; c < 8; ++c)
  {
    mesh.Points.push_back({ 1.5 + (c & 1), 1.5 + ((c >> 1) & 1), (c >> 2) & 1 ? 1.0 : 0.0 });
  }
  const int faces[5][4] = { { 4, 5, 7, 6 }, { 0, 4, 6, 2 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 }, { 1, 3, 7, 5 } };
  int patch = 1000;
  for (const auto& face : faces) // top, and four sides facing out (the bottom stands on the floor)
  {
    mesh.AddPolygon({ base + face[0], base + face[1], base + face[2], base + face[3] });
    mesh.Reflectance.push_back({ 0.5, 0.5, 0.5 });
    mesh.LightId.push_back(-1);
    mesh.PatchId.push_back(patch++);
  }
  const Solution s = SolveTagged(mesh, Gathering(64, 1e-6), 1);
  const int top = mesh.NumberOfPolygons() - 5;
  ASSERT_GT(s.Radiosity[top].x, 0.0);
  for (int c = 4; c < 8; ++c) // the top corners
  {
    EXPECT_GT(s.PointRadiosity[base + c].x, 0.3 * s.Radiosity[top].x) << "corner " << c;
  }
}

TEST(FinalGather, AMovingLightDoesNotReachTheRoomBehindAWall)
{
  // The moving-light path (paper 2.4): direct light shot per frame with shadow rays, the
  // patch basis carrying its interreflection. A light in the first room leaves every
  // element of the second exactly dark.
  const SceneMesh mesh = TwoRooms(5);
  const RadiositySolver solver(mesh);
  MovingLightShader shader(mesh, solver.Prepared(), nullptr);
  ASSERT_TRUE(shader.Error().empty()) << shader.Error();
  MovingLight light;
  light.Position = { 0.5, 0.5, 0.6 };
  light.Intensity = 1.0;
  const WorkerPool pool(0);
  std::vector<Vec3> direct;
  shader.Direct({ light }, pool, direct);
  SolverStatistics stats;
  PatchBasis basis;
  const std::string error =
    SolvePatchBasis(solver, mesh, Converged(1e-6), BasisLevel::Elements, stats, basis);
  ASSERT_TRUE(error.empty()) << error;
  std::vector<Vec3> result;
  AddBasisInterreflection(solver.Geometry(), direct, View(basis), pool, result);
  double lit = 0;
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    const int* ids = mesh.Polygon(e);
    if (mesh.Points[ids[0]].x > 1.2 - 1e-9 && mesh.Points[ids[2]].x > 1.2 - 1e-9)
    {
      EXPECT_EQ(result[e].x, 0.0) << "element " << e;
    }
    lit += result[e].x;
  }
  EXPECT_GT(lit, 0.0);
}

TEST(FinalGather, CornersAtOnePlaceOnOneSurfaceAreGatheredOnce)
{
  // A floor of triangles each holding its own corners (as a curved model's tessellation
  // comes): the corners at one place take one value. At the floor's centre it is Lambert's
  // value under the lamp, taken a quarter of the way into the first corner's own triangle
  // (about 4 cm off the centre there: within 2 %).
  SceneMesh mesh;
  const int n = 4;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const Vec3 a{ -1 + 0.5 * i, -1 + 0.5 * j, 0 }, b = a + Vec3{ 0.5, 0, 0 }, c = a + Vec3{ 0.5, 0.5, 0 },
                 d = a + Vec3{ 0, 0.5, 0 };
      for (const auto& tri : { std::array<Vec3, 3>{ a, b, c }, std::array<Vec3, 3>{ a, c, d } })
      {
        const int base = static_cast<int>(mesh.Points.size());
        mesh.Points.insert(mesh.Points.end(), tri.begin(), tri.end());
        mesh.AddPolygon({ base, base + 1, base + 2 });
        mesh.Reflectance.push_back({ 0.5, 0.5, 0.5 });
        mesh.LightId.push_back(-1);
      }
    }
  }
  int patch = 0;
  mesh.PatchId.resize(mesh.NumberOfPolygons());
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    mesh.PatchId[e] = patch++;
  }
  AddGrid(mesh, { -0.5, -0.5, 1 }, { 0, 1, 0 }, { 1, 0, 0 }, 1, 1, { 0, 0, 0 }, 0, patch);
  const Solution s = SolveTagged(mesh, Gathering(), 1);
  ASSERT_EQ(s.PointRadiosity.size(), mesh.Points.size());
  int atCentre = 0;
  for (size_t p = 0; p < mesh.Points.size(); ++p)
  {
    for (size_t q = 0; q < p; ++q)
    {
      if (mesh.Points[p].x == mesh.Points[q].x && mesh.Points[p].y == mesh.Points[q].y && mesh.Points[p].z == mesh.Points[q].z)
      {
        EXPECT_EQ(s.PointRadiosity[p].x, s.PointRadiosity[q].x) << p << " and " << q;
      }
    }
    if (Norm(mesh.Points[p]) == 0)
    {
      ++atCentre;
      EXPECT_NEAR(s.PointRadiosity[p].x, 0.5 * 0.2394565, 0.02 * 0.5 * 0.2394565);
    }
  }
  EXPECT_EQ(atCentre, 6); // six triangles meet at the floor's centre
}

TEST(FinalGather, ATimeBudgetSpentByTheSolveSkipsTheGather)
{
  // A budget no solve fits in: the solve stops at it, and the gather does not add its own
  // time after it (the points show their elements' mean, and the effects say why).
  const SceneMesh mesh = TwoRooms(5);
  SolverOptions o = Gathering();
  o.TimeBudget = 1e-9;
  const Solution s = SolveTagged(mesh, o, 1);
  EXPECT_TRUE(s.PointRadiosity.empty());
  EXPECT_TRUE(s.GatherOutOfTime);
  EXPECT_FALSE(s.Statistics.Aborted);
  const auto row = std::find_if(s.Effects.begin(), s.Effects.end(), [](const EffectDecision& e) { return e.Effect == "FinalGather"; });
  ASSERT_NE(row, s.Effects.end());
  EXPECT_FALSE(row->Simulated);
  EXPECT_NE(row->Reason.find("TimeBudget"), std::string::npos) << row->Reason;
}

TEST(FinalGather, ItsOwnBudgetLeavesThePointsTheSweptElements)
{
  // The gather given less time than its sweep took: the points take no rays, the elements
  // keep the sweep's values; given all the time it needs: every ray asked for.
  const SceneMesh mesh = TwoRooms(5);
  const RadiositySolver solver(mesh);
  const LightGrouping lights = LightGrouping::OnePerLight(1);
  const Solution solved = SolveLights(solver, mesh, lights, {}, SolutionMode::LightTagged, Converged(1e-7));
  const std::vector<Vec3> emission = SolutionEmission(mesh, lights, {});
  GatherSettings settings;
  settings.Rays = 64;
  for (double budget : { 1e-9, 1e6 })
  {
    settings.TimeBudget = budget;
    const GatheredPoints points = GatherAtPoints(
      mesh, solver.Geometry(), solver.Rays(), emission, solved.Radiosity, 1, settings, 1, {}, true);
    EXPECT_EQ(points.OutOfTime, budget < 1);
    EXPECT_EQ(points.Radiosity.empty(), budget < 1);
    EXPECT_EQ(points.Cells.size(), solved.Radiosity.size());
    EXPECT_EQ(points.PointRays, budget < 1 ? 0 : 64);
  }
}
