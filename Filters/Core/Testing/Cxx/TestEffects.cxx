// Simulate only what the scene calls for: for scenes built to trigger each effect, Auto
// gives the same answer as On and does less (counted work), and a scene that needs an
// effect never loses it.
#include "Solve/Effects.h"
#include "SceneBuilders.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace radiosity;
using radiosity_test::AddGrid;
using radiosity_test::Box;

namespace
{
SolverOptions With(EffectMode mode, double threshold = 1e-6)
{
  SolverOptions o;
  o.MaximumShots = 100000;
  o.ConvergenceThreshold = threshold;
  o.Visibility = o.Interreflection = o.Color = o.ConvergedLights = mode;
  return o;
}

double MaxDifference(const std::vector<Vec3>& a, const std::vector<Vec3>& b)
{
  double worst = 0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      worst = std::max(worst, std::fabs(a[i][c] - b[i][c]));
    }
  }
  return worst;
}

/// A convex room lit by part of its own ceiling (no lamp hanging in the room).
SceneMesh ConvexRoom(const Vec3& rho)
{
  return Box(2.0, 8, 2, rho, [](int face) { return face == 1 ? 0 : -1; });
}

Solution Solve(const SceneMesh& mesh, const SolverOptions& o, int lights = 1)
{
  RadiositySolver solver(mesh);
  return SolveLights(solver, mesh, LightGrouping::OnePerLight(lights), {}, SolutionMode::LightTagged, o);
}
} // namespace

TEST(Effects, ConvexRoomNeedsNoShadowRays)
{
  const SceneMesh room = ConvexRoom({ 0.6, 0.5, 0.4 });
  const Solution autoRun = Solve(room, With(EffectMode::Auto));
  const Solution onRun = Solve(room, With(EffectMode::On));
  EXPECT_EQ(autoRun.Statistics.BlockingSurfaces, 0);
  EXPECT_EQ(autoRun.Statistics.RayCount, 0);
  EXPECT_GT(autoRun.Statistics.RaysSkipped, 0);
  EXPECT_GT(onRun.Statistics.RayCount, 0);
  // Every ray On casts is unblocked, so the answers are the same to rounding.
  EXPECT_LT(MaxDifference(autoRun.Radiosity, onRun.Radiosity), 1e-12);
}

TEST(Effects, OneOccluderTurnsVisibilityBackOn)
{
  SceneMesh room = ConvexRoom({ 0.6, 0.5, 0.4 });
  int patch = 1000;
  // A plate hanging under the lit ceiling casts a shadow on the floor.
  AddGrid(room, { 0.6, 0.6, 1.0 }, { 0.8, 0, 0 }, { 0, 0.8, 0 }, 2, 2, { 0.3, 0.3, 0.3 }, -1, patch); // faces +z
  AddGrid(room, { 0.6, 0.6, 0.999 }, { 0, 0.8, 0 }, { 0.8, 0, 0 }, 2, 2, { 0.3, 0.3, 0.3 }, -1, patch); // faces -z
  const Solution autoRun = Solve(room, With(EffectMode::Auto));
  const Solution onRun = Solve(room, With(EffectMode::On));
  const Solution offRun = Solve(room, With(EffectMode::Off));
  EXPECT_GT(autoRun.Statistics.BlockingSurfaces, 0);
  EXPECT_GT(autoRun.Statistics.RayCount, 0);
  EXPECT_LT(autoRun.Statistics.RayCount, onRun.Statistics.RayCount);
  EXPECT_LT(MaxDifference(autoRun.Radiosity, onRun.Radiosity), 1e-12);
  // The shadow is real: ignoring visibility changes the floor by a lot.
  EXPECT_GT(MaxDifference(offRun.Radiosity, onRun.Radiosity), 0.05);
}

TEST(Effects, BlackSceneShootsEachLightOnce)
{
  const SceneMesh room = ConvexRoom({ 0, 0, 0 });
  const Solution autoRun = Solve(room, With(EffectMode::Auto));
  const Solution onRun = Solve(room, With(EffectMode::On));
  const int lightPatches = 16; // the lit face: 8 x 8 elements, patches of 2 x 2
  EXPECT_EQ(autoRun.Statistics.Shots, lightPatches);
  EXPECT_LT(MaxDifference(autoRun.Radiosity, onRun.Radiosity), 1e-12);
  const auto rows = DescribeEffects(room, With(EffectMode::Auto), autoRun, LightGrouping::OnePerLight(1), 1,
    SolutionMode::LightTagged);
  EXPECT_EQ(rows[1].Effect, "Interreflection");
  EXPECT_FALSE(rows[1].Simulated);
}

TEST(Effects, GreySceneSolvesOneChannel)
{
  const SceneMesh grey = ConvexRoom({ 0.6, 0.6, 0.6 });
  const Solution autoRun = Solve(grey, With(EffectMode::Auto));
  const Solution onRun = Solve(grey, With(EffectMode::On));
  EXPECT_TRUE(autoRun.Statistics.SingleChannel);
  EXPECT_FALSE(onRun.Statistics.SingleChannel);
  EXPECT_LT(MaxDifference(autoRun.Radiosity, onRun.Radiosity), 1e-12);
  // Colored reflectance keeps all three channels.
  EXPECT_FALSE(Solve(ConvexRoom({ 0.6, 0.5, 0.6 }), With(EffectMode::Auto)).Statistics.SingleChannel);
}

TEST(Effects, ConvergedLightsStopBeingShot)
{
  // A large lamp and a tiny one: the tiny one converges long before the large one.
  SceneMesh room = Box(2.0, 8, 2, { 0.7, 0.7, 0.7 }, [](int face) { return face == 1 ? 0 : -1; });
  int patch = 1000;
  AddGrid(room, { 0.9, 0.9, 0.001 }, { 0.05, 0, 0 }, { 0, 0.05, 0 }, 1, 1, { 0.7, 0.7, 0.7 }, 1, patch);
  const Solution autoRun = Solve(room, With(EffectMode::Auto, 1e-6), 2);
  const Solution onRun = Solve(room, With(EffectMode::On, 1e-6), 2);
  EXPECT_GT(autoRun.Statistics.DistributionsSkipped, 0);
  EXPECT_EQ(onRun.Statistics.DistributionsSkipped, 0);
  double peak = 0;
  for (const Vec3& b : onRun.Radiosity)
  {
    peak = std::max(peak, b.x);
  }
  // Skipped energy is below the threshold of its light: the outputs agree to about it.
  EXPECT_LT(MaxDifference(autoRun.Radiosity, onRun.Radiosity), 1e-5 * peak);
}

TEST(Effects, StaticLightsShareOneSolution)
{
  LightGrouping g;
  ASSERT_EQ(GroupLights(4, {}, { 1, 0, 1, 1 }, EffectMode::Auto, g), "");
  EXPECT_EQ(g.Solutions, 2);
  EXPECT_EQ(g.SolutionOfLight, (std::vector<int>{ 0, 1, 0, 0 }));
  ASSERT_EQ(GroupLights(4, {}, { 1, 0, 1, 1 }, EffectMode::On, g), "");
  EXPECT_EQ(g.Solutions, 4);
  ASSERT_EQ(GroupLights(4, {}, {}, EffectMode::Off, g), "");
  EXPECT_EQ(g.Solutions, 1);
  ASSERT_EQ(GroupLights(4, {}, { 0, 1, 0, 0 }, EffectMode::Auto, g), "");
  EXPECT_EQ(g.Solutions, 4); // one static light: nothing to merge
  EXPECT_NE(GroupLights(4, {}, { 1, 1 }, EffectMode::Auto, g), "");
  // Explicit banks win over the flags.
  ASSERT_EQ(GroupLights(3, { 0, 0, 1 }, { 0, 0, 0 }, EffectMode::On, g), "");
  EXPECT_EQ(g.Solutions, 2);
}

TEST(Effects, DirectOnlyStaysDirectWithSeveralLights)
{
  // Interreflection off: radiosity is emission plus first bounce, i.e. exactly the direct
  // part, for every light, also after some lights stop being shot.
  SceneMesh room = Box(2.0, 8, 2, { 0.7, 0.6, 0.5 }, [](int face) { return face == 1 ? 0 : -1; });
  int patch = 1000;
  AddGrid(room, { 0.9, 0.9, 0.001 }, { 0.05, 0, 0 }, { 0, 0.05, 0 }, 1, 1, { 0.7, 0.7, 0.7 }, 1, patch);
  SolverOptions o = With(EffectMode::Auto, 1e-6);
  o.Interreflection = EffectMode::Off;
  o.SeparateDirect = true;
  const Solution s = Solve(room, o, 2);
  ASSERT_EQ(s.Direct.size(), s.Radiosity.size());
  EXPECT_LT(MaxDifference(s.Direct, s.Radiosity), 1e-15);
}
