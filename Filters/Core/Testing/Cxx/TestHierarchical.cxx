// The hierarchical solver method against closed forms, against progressive refinement on
// the same mesh, and against its own invariants (light tagging, the ledger, threads).
#include "FurnishedRoom.h"
#include "Geometry/PointAverages.h"
#include "Solve/LightSolutions.h"
#include "SceneBuilders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace radiosity;
using radiosity_test::AddGrid;
using radiosity_test::Box;
using radiosity_test::Converged;
using radiosity_test::RelativeDifference;

namespace
{
SolverOptions Hierarchical(double threshold = 1e-6)
{
  SolverOptions o = Converged(threshold);
  o.SolverMethod = SolverMethod::Hierarchical;
  return o;
}

SceneMesh Room(double patch, double element)
{
  SceneMesh mesh;
  const std::string error = radiosity_scenes::MeshRoom(radiosity_scenes::FurnishedRoom(), patch, element, mesh);
  EXPECT_TRUE(error.empty()) << error;
  return mesh;
}

Solution SolveRoom(const SceneMesh& mesh, const SolverOptions& options, SolutionMode mode = SolutionMode::LightTagged)
{
  const RadiositySolver solver(mesh);
  EXPECT_TRUE(solver.Error().empty()) << solver.Error();
  return SolveLights(solver, mesh, LightGrouping::OnePerLight(8), {}, mode, options);
}

} // namespace

TEST(Hierarchical, FurnaceGivesOneOverOneMinusRho)
{
  // Closed box, every face emitting 1: B = 1 / (1 - rho). After the emitters' first shots
  // all transport runs over links, most of them patch links.
  for (double rho : { 0.5, 0.9 })
  {
    SceneMesh box = Box(2.0, 24, 4, { rho, rho, rho }, [](int) { return 0; });
    RadiositySolver solver(box);
    const Solution s = SolveLights(solver, box, LightGrouping::OnePerLight(1), {}, SolutionMode::LightTagged, Hierarchical(1e-7));
    ASSERT_TRUE(s.Statistics.Converged);
    EXPECT_EQ(s.Statistics.SolverMethod, SolverMethod::Hierarchical);
    EXPECT_GT(s.Statistics.PatchLinks, 0);
    // The mean within 0.5 %; single elements within 1 % (the corner interpolation's shape).
    const double expected = 1.0 / (1.0 - rho);
    double mean = 0;
    for (const Vec3& b : s.Radiosity)
    {
      EXPECT_NEAR(b.x, expected, 1e-2 * expected);
      mean += b.x / s.Radiosity.size();
    }
    EXPECT_NEAR(mean, expected, 5e-3 * expected);
  }
}

TEST(Hierarchical, HowellPairsThroughPatchLinks)
{
  // Unit emitter of 4 x 4 patches and a unit receiver (rho 0.5) of 8 x 8 patches, 32 x 32
  // elements, with the emitter's shots sent over links too: the receiver's area-mean radiosity is
  // rho * F(receiver -> emitter). Howell C-11 (parallel, gap 1) 0.199825; C-14
  // (perpendicular, sharing an edge) 0.200044.
  struct Case
  {
    Vec3 origin, u, v;
    double expected;
  };
  const Case cases[] = { { { 0, 0, 1 }, { 0, 1, 0 }, { 1, 0, 0 }, 0.199825 },
    { { 0, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, 0.200044 } };
  for (const Case& c : cases)
  {
    SceneMesh mesh;
    int patch = 0;
    AddGrid(mesh, c.origin, c.u, c.v, 4, 1, { 0, 0, 0 }, 0, patch);
    AddGrid(mesh, { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, 32, 4, { 0.5, 0.5, 0.5 }, -1, patch);
    SolverOptions options = Hierarchical();
    options.Hierarchical.DirectToElements = false;
    RadiositySolver solver(mesh);
    const Solution s = SolveLights(solver, mesh, LightGrouping::OnePerLight(1), {}, SolutionMode::LightTagged, options);
    EXPECT_GT(s.Statistics.PatchLinks, 0);
    double mean = 0;
    for (int e = 16; e < mesh.NumberOfPolygons(); ++e)
    {
      mean += s.Radiosity[e].x / (32 * 32);
    }
    EXPECT_NEAR(mean, 0.5 * c.expected, 0.02 * 0.5 * c.expected);
  }
}

TEST(Hierarchical, EqualsProgressiveRefinementOnTheSameMesh)
{
  // Furnished room, 8 lamps, 9 elements a patch: every light within 1 % (area-weighted mean).
  const SceneMesh mesh = Room(0.9, 0.3);
  // 16 shadow rays: with 4, the two methods' different visibility sampling (per element
  // and shot, per patch pair) alone differs by about 1 %; the bias between them is 0.1 %.
  const Solution fine = SolveRoom(mesh, [] {
    SolverOptions o = Converged(1e-4);
    o.SolverMethod = SolverMethod::ProgressiveRefinement;
    o.FormFactorSamples = 16;
    return o;
  }());
  SolverOptions options = Hierarchical(1e-4);
  options.FormFactorSamples = 16;
  const Solution linked = SolveRoom(mesh, options);
  EXPECT_LT(linked.Statistics.FormFactorCount, fine.Statistics.FormFactorCount / 5);
  for (double d : RelativeDifference(mesh, linked, fine))
  {
    std::printf("hierarchical vs progressive: %.3f %%\n", 100 * d);
    EXPECT_LT(d, 0.01);
  }
}

TEST(Hierarchical, TaggedRelitEqualsCombined)
{
  // The links do not depend on which light shoots, so the sum of the k unit solutions
  // equals one solve with every lamp on, up to the convergence threshold.
  const SceneMesh mesh = Room(0.6, 0.3);
  const Solution tagged = SolveRoom(mesh, Hierarchical(1e-7));
  const Solution combined = SolveRoom(mesh, Hierarchical(1e-7), SolutionMode::StandardCombined);
  EXPECT_LT(radiosity_test::TaggedMinusCombined(tagged, combined), 1e-5);
}

TEST(Hierarchical, EnergyLedgerCloses)
{
  // Emitted = absorbed + escaped + unshot, absorbed recomputed from the output radiosity.
  const SceneMesh mesh = Room(0.6, 0.3);
  const Solution s = SolveRoom(mesh, Hierarchical(1e-3));
  const double absorbed = radiosity_test::AbsorbedPower(mesh, s);
  const SolverStatistics& t = s.Statistics;
  EXPECT_NEAR(absorbed + t.EscapedPower + t.UnshotPower, t.EmittedPower, 1e-9 * t.EmittedPower);
  EXPECT_LT(std::fabs(t.EscapedPower), 0.05 * t.EmittedPower);
}

TEST(Hierarchical, SameResultOnAnyNumberOfThreads)
{
  const SceneMesh mesh = Room(0.6, 0.3);
  SolverOptions one = Hierarchical(1e-3), two = Hierarchical(1e-3);
  one.Threads = 1;
  two.Threads = 2;
  const Solution a = SolveRoom(mesh, one), b = SolveRoom(mesh, two);
  ASSERT_EQ(a.Radiosity.size(), b.Radiosity.size());
  for (size_t i = 0; i < a.Radiosity.size(); ++i)
  {
    ASSERT_EQ(a.Radiosity[i].x, b.Radiosity[i].x) << i;
    ASSERT_EQ(a.Radiosity[i].z, b.Radiosity[i].z) << i;
  }
}

TEST(Hierarchical, AutoPicksByScaleAndReportsTheCap)
{
  // Auto: progressive on a scene of a few elements, hierarchical from 5,000 element-patch
  // pairs (the furnished room); a capped run says so.
  const SceneMesh small = radiosity_test::Box(1.0, 4, 2, { 0.5, 0.5, 0.5 }, [](int f) { return f == 1 ? 0 : -1; });
  SolverOptions automatic = Converged(1e-3);
  automatic.MaximumShots = 50;
  const RadiositySolver smallSolver(small);
  const Solution s = SolveLights(smallSolver, small, LightGrouping::OnePerLight(1), {}, SolutionMode::LightTagged, automatic);
  EXPECT_EQ(s.Statistics.SolverMethod, SolverMethod::ProgressiveRefinement) << s.Statistics.MethodReason;
  EXPECT_FALSE(s.Statistics.Converged);
  EXPECT_EQ(s.Statistics.Shots, 50);
  const SceneMesh large = Room(0.6, 0.3);
  const Solution l = SolveRoom(large, automatic);
  EXPECT_EQ(l.Statistics.SolverMethod, SolverMethod::Hierarchical);
  EXPECT_FALSE(l.Statistics.Converged);
  EXPECT_EQ(l.Statistics.Shots, 50);
}

TEST(Hierarchical, HundredThousandElementsConverge)
{
  // A 100k-element room converges at the defaults; the result stays physical: finite,
  // non-negative, and the ledger closes.
  const SceneMesh mesh = Room(0.4, 0.04);
  ASSERT_GE(mesh.NumberOfPolygons(), 90000);
  SolverOptions defaults;
  defaults.MaximumShots = 1000000;
  const Solution s = SolveRoom(mesh, defaults);
  EXPECT_EQ(s.Statistics.SolverMethod, SolverMethod::Hierarchical) << s.Statistics.MethodReason;
  EXPECT_TRUE(s.Statistics.Converged);
  for (const Vec3& b : s.Radiosity)
  {
    ASSERT_TRUE(std::isfinite(b.x) && b.x >= 0 && b.z >= 0);
  }
  const SolverStatistics& t = s.Statistics;
  EXPECT_LT(t.UnshotPower, 1e-3 * t.EmittedPower);
  EXPECT_LT(std::fabs(t.EscapedPower), 0.05 * t.EmittedPower);
}

TEST(Hierarchical, PatchesStraddlingAFootprintKeepTheirEnergy)
{
  // A furnace (every surface emits 1, rho 0.5) with a block standing on the floor, open at
  // the bottom; floor patches straddle its footprint. Every element that can see out has
  // B = 1 / (1 - rho) = 2, with either method: the floor under the block is enclosed and
  // neither shoots nor takes a share of its patch's energy. Measured: mean 1.989 and 1.1 %
  // of the power lost (1.973 and 2.7 % before enclosed elements left their patches); what
  // remains is shadow rays weighting a partly hidden shooter by area, not by form factor.
  SceneMesh mesh = Box(2.0, 8, 2, { 0.5, 0.5, 0.5 }, [](int) { return 0; });
  int patch = 1000;
  const Vec3 rho{ 0.5, 0.5, 0.5 }, lo{ 0.25, 0.25, 0 };
  const double s = 0.5;
  AddGrid(mesh, lo + Vec3{ 0, 0, s }, { s, 0, 0 }, { 0, s, 0 }, 2, 2, rho, 0, patch);  // top, +z
  AddGrid(mesh, lo, { s, 0, 0 }, { 0, 0, s }, 2, 2, rho, 0, patch);                    // y = 0.25, -y
  AddGrid(mesh, lo + Vec3{ 0, s, 0 }, { 0, 0, s }, { s, 0, 0 }, 2, 2, rho, 0, patch);  // y = 0.75, +y
  AddGrid(mesh, lo, { 0, 0, s }, { 0, s, 0 }, 2, 2, rho, 0, patch);                    // x = 0.25, -x
  AddGrid(mesh, lo + Vec3{ s, 0, 0 }, { 0, s, 0 }, { 0, 0, s }, 2, 2, rho, 0, patch);  // x = 0.75, +x
  for (SolverMethod method : { SolverMethod::ProgressiveRefinement, SolverMethod::Hierarchical })
  {
    SolverOptions options = Converged(1e-6);
    options.SolverMethod = method;
    options.FormFactorSamples = 64;
    const RadiositySolver solver(mesh);
    const Solution sol = SolveLights(solver, mesh, LightGrouping::OnePerLight(1), {}, SolutionMode::LightTagged, options);
    const SceneGeometry& g = solver.Geometry();
    int enclosed = 0;
    double mean = 0, area = 0;
    for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
    {
      enclosed += g.Enclosed[e];
      if (!g.Enclosed[e])
      {
        mean += sol.Radiosity[e].x * g.Area[e];
        area += g.Area[e];
      }
    }
    EXPECT_EQ(enclosed, 4) << "the floor elements under the block";
    EXPECT_NEAR(mean / area, 2.0, 0.015) << static_cast<int>(method);
    EXPECT_LT(std::fabs(sol.Statistics.EscapedPower), 0.015 * sol.Statistics.EmittedPower) << static_cast<int>(method);
  }
}

TEST(Hierarchical, CeilingAboveALampsBackIsShelteredNotBlurred)
{
  // A lamp 1 cm under the ceiling of a 2 m box, facing down: the ceiling above its back
  // sees almost nothing, the ceiling just beside it is lit like the rest. Ceiling patches
  // (0.5 m) straddle the lamp's outline. Patch links must not spread one visibility over
  // the whole patch, nor vertex averages carry the dark part across the outline. Measured
  // against progressive refinement (which shoots every element): 0.5 % in the ring beside
  // the lamp (10.5 % too dark when patch links landed on the sheltered part as well).
  SceneMesh mesh = Box(2.0, 20, 5, { 0.6, 0.6, 0.6 }, [](int) { return -1; });
  int patch = 1000;
  const Vec3 lo{ 0.8, 0.8, 1.99 };
  AddGrid(mesh, lo, { 0, 0.4, 0 }, { 0.4, 0, 0 }, 2, 2, { 0.5, 0.5, 0.5 }, 0, patch); // faces -z
  const int lampFirst = mesh.NumberOfPolygons() - 4;
  std::vector<Solution> solutions;
  const RadiositySolver solver(mesh);
  const SceneGeometry& g = solver.Geometry();
  for (SolverMethod method : { SolverMethod::ProgressiveRefinement, SolverMethod::Hierarchical })
  {
    SolverOptions options = Converged(1e-5);
    options.SolverMethod = method;
    options.FormFactorSamples = 16;
    solutions.push_back(SolveLights(solver, mesh, LightGrouping::OnePerLight(1), {}, SolutionMode::LightTagged, options));
  }
  double ring = 0, difference = 0;
  int above = 0, sheltered = 0, farAway = 0, farSheltered = 0;
  for (int e = 0; e < lampFirst; ++e)
  {
    const Vec3& c = g.Centroid[e];
    if (g.Normal[e].z > -0.5)
    {
      continue; // the ceiling only
    }
    const double outside = std::max(std::fabs(c.x - 1.0), std::fabs(c.y - 1.0)) - 0.2; // from the lamp's outline
    if (outside < -0.06)
    {
      ++above;
      sheltered += g.Sheltered[e];
    }
    else if (outside > 0 && outside < 0.15)
    {
      ring += solutions[0].Radiosity[e].x;
      difference += solutions[1].Radiosity[e].x - solutions[0].Radiosity[e].x;
    }
    else if (outside > 0.3)
    {
      ++farAway;
      farSheltered += g.Sheltered[e];
    }
  }
  EXPECT_EQ(sheltered, above) << "every ceiling element well inside the lamp's outline";
  EXPECT_EQ(farSheltered, 0) << farAway << " ceiling elements away from the lamp";
  std::printf("ring beside the lamp: hierarchical vs progressive %+.2f %%\n", 100 * difference / ring);
  EXPECT_LT(std::fabs(difference / ring), 0.02);
  // Vertices on the outline show the lit side, not its mean with the dark one.
  const std::vector<Vec3> points = AverageToPoints(mesh, g, solutions[0].Radiosity, 1);
  double onOutline = 0, besideOutline = 0;
  for (int e = 0; e < lampFirst; ++e)
  {
    const Vec3& c = g.Centroid[e];
    const double outside = std::max(std::fabs(c.x - 1.0), std::fabs(c.y - 1.0)) - 0.2;
    for (int v = 0; g.Normal[e].z < -0.5 && outside > 0 && outside < 0.1 && v < mesh.PolygonSize(e); ++v)
    {
      const Vec3& p = mesh.Points[mesh.Polygon(e)[v]];
      if (std::fabs(std::max(std::fabs(p.x - 1.0), std::fabs(p.y - 1.0)) - 0.2) < 1e-9)
      {
        onOutline += points[mesh.Polygon(e)[v]].x;
        besideOutline += solutions[0].Radiosity[e].x;
      }
    }
  }
  ASSERT_GT(besideOutline, 0);
  std::printf("outline vertices / elements beside them: %.3f\n", onOutline / besideOutline);
  EXPECT_GT(onOutline / besideOutline, 0.9) << "outline vertices against the elements beside them";
}

TEST(Hierarchical, StandardSeparateReportsTheMethodThatRan)
{
  // One hierarchical solve per light: the statistics say hierarchical, with the links of
  // every solve and the cap in force, and the solutions match the one-pass light tagging.
  const SceneMesh mesh = Room(0.6, 0.3);
  const Solution separate = SolveRoom(mesh, Hierarchical(1e-4), SolutionMode::StandardSeparate);
  const Solution tagged = SolveRoom(mesh, Hierarchical(1e-4));
  const SolverStatistics& s = separate.Statistics;
  EXPECT_EQ(s.SolverMethod, SolverMethod::Hierarchical);
  EXPECT_EQ(s.MethodReason, tagged.Statistics.MethodReason);
  EXPECT_EQ(s.ShotCap, tagged.Statistics.ShotCap);
  EXPECT_TRUE(s.Converged);
  EXPECT_GT(s.PatchLinks, tagged.Statistics.PatchLinks); // rebuilt for each of the 8 solves
  EXPECT_GT(s.LinkBytes, 0);
  for (double d : RelativeDifference(mesh, separate, tagged))
  {
    EXPECT_LT(d, 0.01);
  }
}
