// The light-tagged solver against closed forms, the standard method and invariants.
#include "Solve/LightSolutions.h"
#include "SceneBuilders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace radiosity;
using radiosity_test::AddGrid;
using radiosity_test::Box;
using radiosity_test::Converged;

TEST(Solver, BoxBuilderFacesInward)
{
  SceneMesh box = Box(1.0, 2, 1, { 0.5, 0.5, 0.5 }, [](int) { return -1; });
  SceneGeometry g(box);
  for (size_t e = 0; e < g.Normal.size(); ++e)
  {
    EXPECT_GT(Dot(g.Normal[e], Vec3{ 0.5, 0.5, 0.5 } - g.Centroid[e]), 0) << e;
  }
}

TEST(Solver, FurnaceGivesOneOverOneMinusRho)
{
  // Closed box, every face emitting 1, uniform rho: B = 1 / (1 - rho) everywhere. Point
  // collocation alone met this to 1e-6 (a point's analytic factors to a closed box sum to
  // exactly 1) while shooting 0.1 % more or less power than each patch had; each shot now
  // delivers exactly its power in a closed scene, which costs the per-element
  // exactness: measured within 0.06 %.
  for (double rho : { 0.3, 0.5, 0.9 })
  {
    SceneMesh box = Box(2.0, 6, 2, { rho, rho, rho }, [](int) { return 0; });
    RadiositySolver solver(box);
    ASSERT_TRUE(solver.Error().empty()) << solver.Error();
    // Progressive refinement's bound (Auto takes the links here, held to 0.5 % in
    // Hierarchical.FurnaceGivesOneOverOneMinusRho).
    SolverOptions o = Converged(1e-9);
    o.SolverMethod = SolverMethod::ProgressiveRefinement;
    Solution s = SolveLights(solver, box, LightGrouping::OnePerLight(1), {}, SolutionMode::LightTagged, o);
    ASSERT_TRUE(s.Statistics.Converged);
    const double expected = 1.0 / (1.0 - rho);
    for (const Vec3& b : s.Radiosity)
    {
      EXPECT_NEAR(b.x, expected, 1e-3 * expected);
      EXPECT_NEAR(b.y, expected, 1e-3 * expected);
      EXPECT_NEAR(b.z, expected, 1e-3 * expected);
    }
  }
}

TEST(Solver, SingleBounceBetweenOpposedSquaresMatchesHowell)
{
  // Unit emitter facing a unit receiver at gap 1 (rho_emitter = 0): the receiver's
  // area-mean radiosity is rho * F(receiver -> emitter) = rho * 0.199825 (Howell C-11).
  SceneMesh mesh;
  int patch = 0;
  AddGrid(mesh, { 0, 0, 1 }, { 0, 1, 0 }, { 1, 0, 0 }, 1, 1, { 0, 0, 0 }, 0, patch); // faces -z
  const int n = 32;
  AddGrid(mesh, { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, n, n, { 0.5, 0.5, 0.5 }, -1, patch);
  RadiositySolver solver(mesh);
  Solution s = SolveLights(solver, mesh, LightGrouping::OnePerLight(1), {}, SolutionMode::LightTagged, Converged());
  double mean = 0;
  for (int e = 1; e < mesh.NumberOfPolygons(); ++e)
  {
    mean += s.Radiosity[e].x / (n * n);
  }
  EXPECT_NEAR(mean, 0.5 * 0.199825, 2e-4 * 0.1);
}

TEST(Solver, OccluderBlocksDirectLight)
{
  // A large black plate between a small emitter and a receiver: no direct light arrives.
  SceneMesh mesh;
  int patch = 0;
  AddGrid(mesh, { 0.4, 0.4, 2 }, { 0, 0.2, 0 }, { 0.2, 0, 0 }, 1, 1, { 0, 0, 0 }, 0, patch);
  AddGrid(mesh, { -5, -5, 1 }, { 10, 0, 0 }, { 0, 10, 0 }, 2, 1, { 0, 0, 0 }, -1, patch);
  AddGrid(mesh, { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, 4, 4, { 0.8, 0.8, 0.8 }, -1, patch);
  RadiositySolver solver(mesh);
  Solution s = SolveLights(solver, mesh, LightGrouping::OnePerLight(1), {}, SolutionMode::LightTagged, Converged());
  for (int e = 1 + 4; e < mesh.NumberOfPolygons(); ++e)
  {
    EXPECT_EQ(s.Radiosity[e].x, 0.0) << e;
  }
  // Without the plate the receiver is lit.
  SceneMesh open;
  patch = 0;
  AddGrid(open, { 0.4, 0.4, 2 }, { 0, 0.2, 0 }, { 0.2, 0, 0 }, 1, 1, { 0, 0, 0 }, 0, patch);
  AddGrid(open, { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, 4, 4, { 0.8, 0.8, 0.8 }, -1, patch);
  RadiositySolver openSolver(open);
  Solution lit = SolveLights(openSolver, open, LightGrouping::OnePerLight(1), {}, SolutionMode::LightTagged, Converged());
  EXPECT_GT(lit.Radiosity[5].x, 1e-3);
}

namespace
{
/// An open box (no lid) with two occluding walls and three colored lights.
SceneMesh ThreeLightScene(std::vector<Vec3>& colors)
{
  SceneMesh mesh = Box(4.0, 8, 2, { 0.6, 0.5, 0.4 }, [](int) { return -1; });
  int patch = 1000;
  AddGrid(mesh, { 1, 0.5, 3.9 }, { 0, 0.4, 0 }, { 0.4, 0, 0 }, 1, 1, { 0.7, 0.7, 0.7 }, 0, patch);
  AddGrid(mesh, { 3, 3, 3.9 }, { 0, 0.4, 0 }, { 0.4, 0, 0 }, 1, 1, { 0.7, 0.7, 0.7 }, 1, patch);
  AddGrid(mesh, { 0.1, 2, 1 }, { 0, 0, 0.4 }, { 0, 0.4, 0 }, 1, 1, { 0.7, 0.7, 0.7 }, 2, patch);
  AddGrid(mesh, { 2, 0, 0 }, { 0, 0, 2 }, { 0, 3, 0 }, 4, 2, { 0.2, 0.8, 0.3 }, -1, patch); // partition
  colors.assign(mesh.NumberOfPolygons(), Vec3());
  const Vec3 palette[3] = { { 1.0, 0.8, 0.6 }, { 0.2, 0.4, 1.5 }, { 3.0, 0.1, 0.1 } };
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    if (mesh.LightId[e] >= 0)
    {
      colors[e] = palette[mesh.LightId[e]];
    }
  }
  return mesh;
}
}

TEST(Solver, TaggedRelitEqualsStandardCombined)
{
  std::vector<Vec3> colors;
  SceneMesh mesh = ThreeLightScene(colors);
  int k = 0;
  ASSERT_EQ(ValidateScene(mesh, k), "");
  ASSERT_EQ(k, 3);
  RadiositySolver solver(mesh);
  const Solution tagged = SolveLights(solver, mesh, LightGrouping::OnePerLight(k), colors, SolutionMode::LightTagged, Converged(1e-9));
  const Solution combined = SolveLights(solver, mesh, LightGrouping::OnePerLight(k), colors, SolutionMode::StandardCombined, Converged(1e-9));
  ASSERT_TRUE(tagged.Statistics.Converged && combined.Statistics.Converged);
  const Vec3 palette[3] = { { 1.0, 0.8, 0.6 }, { 0.2, 0.4, 1.5 }, { 3.0, 0.1, 0.1 } };
  double worst = 0, peak = 0;
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    Vec3 relit;
    for (int m = 0; m < k; ++m)
    {
      const Vec3& b = tagged.Radiosity[e * k + m];
      relit += Vec3{ b.x * palette[m].x, b.y * palette[m].y, b.z * palette[m].z };
    }
    for (int c = 0; c < 3; ++c)
    {
      worst = std::max(worst, std::fabs(relit[c] - combined.Radiosity[e][c]));
      peak = std::max(peak, combined.Radiosity[e][c]);
    }
  }
  EXPECT_LT(worst, 1e-6 * peak);
  EXPECT_GT(peak, 0.5); // the comparison is not between two zeros
}

TEST(Solver, SeparateEqualsTagged)
{
  std::vector<Vec3> colors;
  SceneMesh mesh = ThreeLightScene(colors);
  RadiositySolver solver(mesh);
  const Solution tagged = SolveLights(solver, mesh, LightGrouping::OnePerLight(3), colors, SolutionMode::LightTagged, Converged(1e-9));
  const Solution separate = SolveLights(solver, mesh, LightGrouping::OnePerLight(3), colors, SolutionMode::StandardSeparate, Converged(1e-9));
  ASSERT_EQ(tagged.Radiosity.size(), separate.Radiosity.size());
  for (size_t i = 0; i < tagged.Radiosity.size(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(tagged.Radiosity[i][c], separate.Radiosity[i][c], 1e-7) << i;
    }
  }
  // The point of light tagging: one form-factor pass per shot instead of one per light.
  EXPECT_LT(tagged.Statistics.FormFactorCount, separate.Statistics.FormFactorCount);
}

TEST(Solver, EnergyArrivesInClosedBox)
{
  // In a closed box everything shot arrives somewhere: received / shot -> 1, up to the
  // centroid quadrature of the receivers (a few per mille at 8 x 8 elements per face).
  SceneMesh box = Box(1.0, 8, 2, { 0.7, 0.7, 0.7 }, [](int f) { return f == 1 ? 0 : -1; });
  RadiositySolver solver(box);
  Solution s = SolveLights(solver, box, LightGrouping::OnePerLight(1), {}, SolutionMode::LightTagged, Converged(1e-6));
  EXPECT_NEAR(s.Statistics.ReceivedPower / s.Statistics.ShotPower, 1.0, 0.01);
}

TEST(Solver, ResultDoesNotDependOnThreads)
{
  std::vector<Vec3> colors;
  SceneMesh mesh = ThreeLightScene(colors);
  RadiositySolver solver(mesh);
  SolverOptions one = Converged(1e-4), many = Converged(1e-4);
  one.Threads = 1;
  many.Threads = 4;
  const Solution a = SolveLights(solver, mesh, LightGrouping::OnePerLight(3), colors, SolutionMode::LightTagged, one);
  const Solution b = SolveLights(solver, mesh, LightGrouping::OnePerLight(3), colors, SolutionMode::LightTagged, many);
  ASSERT_EQ(a.Radiosity.size(), b.Radiosity.size());
  for (size_t i = 0; i < a.Radiosity.size(); ++i)
  {
    EXPECT_EQ(a.Radiosity[i].x, b.Radiosity[i].x);
  }
}

TEST(Solver, AbortKeepsValidPartialResult)
{
  SceneMesh box = Box(1.0, 4, 2, { 0.9, 0.9, 0.9 }, [](int f) { return f == 1 ? 0 : -1; });
  RadiositySolver solver(box);
  SolverOptions o = Converged();
  int calls = 0;
  o.Progress = [&](double) { return ++calls <= 3; };
  Solution s = SolveLights(solver, box, LightGrouping::OnePerLight(1), {}, SolutionMode::LightTagged, o);
  EXPECT_TRUE(s.Statistics.Aborted);
  EXPECT_EQ(s.Statistics.Shots, 3);
  for (const Vec3& b : s.Radiosity)
  {
    EXPECT_TRUE(std::isfinite(b.x) && b.x >= 0);
  }
}

TEST(Validation, NamesTheProblem)
{
  auto scene = [] { return Box(1.0, 1, 1, { 0.5, 0.5, 0.5 }, [](int f) { return f == 0 ? 0 : -1; }); };
  int k = 0;
  SceneMesh ok = scene();
  EXPECT_EQ(ValidateScene(ok, k), "");
  EXPECT_EQ(k, 1);

  SceneMesh nan = scene();
  nan.Reflectance[2].y = std::nan("");
  EXPECT_NE(ValidateScene(nan, k).find("Reflectance of cell 2"), std::string::npos);

  SceneMesh high = scene();
  high.Reflectance[3].x = 1.5;
  EXPECT_NE(ValidateScene(high, k).find("[0, 1]"), std::string::npos);

  SceneMesh gap = scene();
  gap.LightId[0] = 1;
  EXPECT_NE(ValidateScene(gap, k).find("gap"), std::string::npos);

  SceneMesh dark = scene();
  dark.LightId[0] = -1;
  EXPECT_NE(ValidateScene(dark, k).find("no lights"), std::string::npos);

  SceneMesh flat = scene();
  flat.Points[flat.Polygon(4)[2]] = flat.Points[flat.Polygon(4)[1]];
  flat.Points[flat.Polygon(4)[3]] = flat.Points[flat.Polygon(4)[0]];
  EXPECT_NE(ValidateScene(flat, k).find("zero area"), std::string::npos);

  SceneMesh empty;
  EXPECT_NE(ValidateScene(empty, k).find("no polygons"), std::string::npos);
}

TEST(Solver, AmbientTermFixesTheFurnaceAfterOneSweep)
{
  // rho = 0.99: after each patch has shot once, B is far from 1/(1-rho) = 100; the ambient
  // term accounts for the unshot energy and brings it within 1 % (Cohen et al. 1988).
  SceneMesh box = Box(1.0, 8, 2, { 0.99, 0.99, 0.99 }, [](int) { return 0; }); // 96 patches
  RadiositySolver solver(box);
  SolverOptions o = Converged();
  o.MaximumShots = static_cast<int>(solver.Geometry().PatchElements.size());
  const Solution plain = SolveLights(solver, box, LightGrouping::OnePerLight(1), {}, SolutionMode::LightTagged, o);
  o.AmbientTerm = true;
  const Solution ambient = SolveLights(solver, box, LightGrouping::OnePerLight(1), {}, SolutionMode::LightTagged, o);
  double plainError = 0, ambientError = 0;
  for (size_t e = 0; e < plain.Radiosity.size(); ++e)
  {
    plainError = std::max(plainError, std::fabs(plain.Radiosity[e].x - 100.0) / 100.0);
    ambientError = std::max(ambientError, std::fabs(ambient.Radiosity[e].x - 100.0) / 100.0);
  }
  EXPECT_GT(plainError, 0.9);
  EXPECT_LT(ambientError, 0.01);
}

TEST(Solver, DirectPartIsEmissionPlusFirstBounce)
{
  // One light patch: its first (and only emitting) shot is everything direct. A solve
  // stopped after that shot is therefore the direct part of the converged solve.
  SceneMesh mesh = Box(2.0, 6, 2, { 0.6, 0.5, 0.4 }, [](int) { return -1; });
  int patch = 1000;
  AddGrid(mesh, { 0.8, 0.8, 1.9 }, { 0, 0.4, 0 }, { 0.4, 0, 0 }, 2, 2, { 0.7, 0.7, 0.7 }, 0, patch);
  RadiositySolver solver(mesh);
  SolverOptions o = Converged(1e-6);
  o.SeparateDirect = true;
  const Solution full = SolveLights(solver, mesh, LightGrouping::OnePerLight(1), {}, SolutionMode::LightTagged, o);
  o.MaximumShots = 1;
  const Solution first = SolveLights(solver, mesh, LightGrouping::OnePerLight(1), {}, SolutionMode::LightTagged, o);
  double indirect = 0;
  for (size_t e = 0; e < full.Radiosity.size(); ++e)
  {
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(full.Direct[e][c], first.Radiosity[e][c], 1e-12);
      EXPECT_LE(full.Direct[e][c], full.Radiosity[e][c] + 1e-12);
      indirect += full.Radiosity[e][c] - full.Direct[e][c];
    }
  }
  EXPECT_GT(indirect, 0.1);
}

TEST(Solver, BankEqualsEmissionWeightedSumOfItsLights)
{
  // Linearity: a bank's solution is its lights' unit solutions weighted by their colors.
  std::vector<Vec3> colors;
  SceneMesh mesh = ThreeLightScene(colors);
  RadiositySolver solver(mesh);
  LightGrouping banks;
  ASSERT_EQ(LightGrouping::FromBanks({ 0, 1, 0 }, 3, banks), "");
  const Solution banked = SolveLights(solver, mesh, banks, colors, SolutionMode::LightTagged, Converged(1e-9));
  const Solution single = SolveLights(solver, mesh, LightGrouping::OnePerLight(3), colors, SolutionMode::LightTagged, Converged(1e-9));
  const Vec3 palette[3] = { { 1.0, 0.8, 0.6 }, { 0.2, 0.4, 1.5 }, { 3.0, 0.1, 0.1 } };
  ASSERT_EQ(banked.Solutions, 2);
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    const Vec3& l0 = single.Radiosity[e * 3 + 0];
    const Vec3& l2 = single.Radiosity[e * 3 + 2];
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(banked.Radiosity[e * 2 + 0][c], palette[0][c] * l0[c] + palette[2][c] * l2[c], 1e-6);
      EXPECT_NEAR(banked.Radiosity[e * 2 + 1][c], single.Radiosity[e * 3 + 1][c], 1e-6);
    }
  }
  // The relight's default colors: a lone light's own, a bank white (its colors are in it).
  const std::vector<Vec3> bankDefaults = DefaultColors(mesh, banks, colors);
  const std::vector<Vec3> loneDefaults = DefaultColors(mesh, LightGrouping::OnePerLight(3), colors);
  ASSERT_EQ(bankDefaults.size(), 2u);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(bankDefaults[0][c], 1.0, 1e-12);
    EXPECT_NEAR(bankDefaults[1][c], palette[1][c], 1e-12);
    for (int l = 0; l < 3; ++l)
    {
      EXPECT_NEAR(loneDefaults[l][c], palette[l][c], 1e-12);
    }
  }
  LightGrouping bad;
  EXPECT_NE(LightGrouping::FromBanks({ 0, 2, 0 }, 3, bad), "");
  EXPECT_NE(LightGrouping::FromBanks({ 0, 1 }, 3, bad), "");
}

TEST(Solver, TimeBudgetStopsWithValidResult)
{
  SceneMesh box = Box(1.0, 16, 1, { 0.9, 0.9, 0.9 }, [](int f) { return f == 1 ? 0 : -1; });
  RadiositySolver solver(box);
  SolverOptions o = Converged(0.0);
  o.TimeBudget = 0.05;
  const Solution s = SolveLights(solver, box, LightGrouping::OnePerLight(1), {}, SolutionMode::LightTagged, o);
  EXPECT_TRUE(s.Statistics.OutOfTime);
  EXPECT_FALSE(s.Statistics.Converged);
  EXPECT_EQ(s.Statistics.TimeHistory.size(), static_cast<size_t>(s.Statistics.Shots));
  for (const Vec3& b : s.Radiosity)
  {
    EXPECT_TRUE(std::isfinite(b.x) && b.x >= 0);
  }
}

TEST(Solver, StatisticsAppendTakesInEveryField)
{
  // StandardSeparate adds up its solves with Append: each field counted, the last one's,
  // all of them, any of them or the most held at once, as its comment says. The size check
  // fails when a field is added, so that it is merged in Append and checked here too.
  // The size is that of this project's platform (x86-64, libstdc++); elsewhere it is skipped.
  static_assert(sizeof(void*) != 8 || sizeof(std::string) != 32 || sizeof(SolverStatistics) == 368,
    "SolverStatistics changed: merge the new field in SolverStatistics::Append and check it below");
  auto run = [](int k) {
    SolverStatistics s;
    s.Shots = 10 * k;
    s.ShotCap = 100 * k;
    s.Converged = k == 2; // the last run's alone would be true: all of them are not
    s.Aborted = k == 2;
    s.OutOfTime = k == 2;
    s.AmbientAtCap = k == 1;
    s.OutOfMemory = k == 1 ? "links would not fit" : "";
    s.RayCount = 1000 * k;
    s.RaysSkipped = 20 * k;
    s.PairsUnblockable = 30 * k;
    s.DistributionsSkipped = 40 * k;
    s.SingleChannel = k == 2;
    s.BlockingSurfaces = 5 * k;
    s.FormFactorCount = 50 * k;
    s.SolverMethod = k == 1 ? SolverMethod::ProgressiveRefinement : SolverMethod::Hierarchical;
    s.MethodReason = "reason " + std::to_string(k);
    s.FaceClusters = 6 * k;
    s.PatchLinks = 70 * k;
    s.ElementLinks = 80 * k;
    s.VolumeLinks = 90 * k;
    s.LinkBytes = k == 1 ? 5000.0 : 3000.0;
    s.ShotPower = 1.5 * k;
    s.ReceivedPower = 2.5 * k;
    s.EmittedPower = 3.5 * k;
    s.EscapedPower = 0.5 * k;
    s.UnshotPower = 0.25 * k;
    s.Ranks = 2 * k;
    s.Collectives = 7 * k;
    s.CollectiveBytes = 8.0 * k;
    s.ShotCollectiveBytes = 4.0 * k;
    s.CollectiveSeconds = 0.125 * k;
    s.ReceivingElements = 11 * k;
    s.OwnRays = 600 * k;
    s.TimeHistory.assign(k, 1.0);
    s.RemainingHistory.assign(k, 0.5);
    s.RemainingPerSolution.assign(k, 0.25);
    s.Took("links", 1.0 * k);
    s.Took(k == 1 ? "direct light" : "final gather", 0.5 * k);
    s.Took("links", 0.25);
    return s;
  };
  SolverStatistics all = SolverStatistics::Sequence();
  all.Append(run(1));
  all.Append(run(2));
  EXPECT_EQ(all.Shots, 30);
  EXPECT_EQ(all.ShotCap, 200);
  EXPECT_FALSE(all.Converged);
  EXPECT_TRUE(all.Aborted);
  EXPECT_TRUE(all.OutOfTime);
  EXPECT_TRUE(all.AmbientAtCap);
  EXPECT_EQ(all.OutOfMemory, "links would not fit");
  EXPECT_EQ(all.RayCount, 3000);
  EXPECT_EQ(all.RaysSkipped, 60);
  EXPECT_EQ(all.PairsUnblockable, 90);
  EXPECT_EQ(all.DistributionsSkipped, 120);
  EXPECT_FALSE(all.SingleChannel);
  EXPECT_EQ(all.BlockingSurfaces, 10);
  EXPECT_EQ(all.FormFactorCount, 150);
  EXPECT_EQ(all.SolverMethod, SolverMethod::Hierarchical);
  EXPECT_EQ(all.MethodReason, "reason 2");
  EXPECT_EQ(all.FaceClusters, 12);
  EXPECT_EQ(all.PatchLinks, 210);
  EXPECT_EQ(all.ElementLinks, 240);
  EXPECT_EQ(all.VolumeLinks, 270);
  EXPECT_EQ(all.LinkBytes, 5000.0);
  EXPECT_DOUBLE_EQ(all.ShotPower, 4.5);
  EXPECT_DOUBLE_EQ(all.ReceivedPower, 7.5);
  EXPECT_DOUBLE_EQ(all.EmittedPower, 10.5);
  EXPECT_DOUBLE_EQ(all.EscapedPower, 1.5);
  EXPECT_DOUBLE_EQ(all.UnshotPower, 0.75);
  EXPECT_EQ(all.Ranks, 4);
  EXPECT_EQ(all.Collectives, 21);
  EXPECT_DOUBLE_EQ(all.CollectiveBytes, 24.0);
  EXPECT_DOUBLE_EQ(all.ShotCollectiveBytes, 12.0);
  EXPECT_DOUBLE_EQ(all.CollectiveSeconds, 0.375);
  EXPECT_EQ(all.ReceivingElements, 22);
  EXPECT_EQ(all.OwnRays, 1800);
  // Steps add up by name, in the order each first ran.
  ASSERT_EQ(all.Steps.size(), 3u);
  EXPECT_EQ(all.Steps[0].Name, "links");
  EXPECT_DOUBLE_EQ(all.Steps[0].Seconds, 3.5);
  EXPECT_EQ(all.Steps[1].Name, "direct light");
  EXPECT_DOUBLE_EQ(all.Steps[1].Seconds, 0.5);
  EXPECT_EQ(all.Steps[2].Name, "final gather");
  EXPECT_DOUBLE_EQ(all.Steps[2].Seconds, 1.0);
  // The histories are the caller's, weighted by each solution's power.
  EXPECT_TRUE(all.TimeHistory.empty() && all.RemainingHistory.empty() && all.RemainingPerSolution.empty());
}
