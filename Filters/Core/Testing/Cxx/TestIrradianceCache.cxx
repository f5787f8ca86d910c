// The final gather's irradiance cache: a record's reach and weights against the rules
// worked by hand, records placed the same on any thread count and covering every point, and
// the cached gather against gathering at every point (no leak through a wall, the furnace
// exact, the room's values within the gather's own noise).
#include "Base/WorkerPool.h"
#include "Geometry/FormFactor.h"
#include "Solve/FinalGather.h"
#include "Solve/IrradianceCache.h"
#include "Solve/LightSolutions.h"
#include "SceneBuilders.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace radiosity;
using radiosity_test::AddGrid;
using radiosity_test::Box;
using radiosity_test::Converged;
using radiosity_test::TwoRooms;

namespace
{
/// A 3 m room of reflectance 0.6 with a 0.5 m lamp under its ceiling, `n` elements a side.
SceneMesh LampRoom(int n)
{
  SceneMesh mesh = Box(3.0, n, 4, { 0.6, 0.6, 0.6 }, [](int) { return -1; });
  int patch = 1000;
  AddGrid(mesh, { 1.25, 1.25, 2.9 }, { 0, 0.5, 0 }, { 0.5, 0, 0 }, 2, 1, { 0, 0, 0 }, 0, patch);
  return mesh;
}

Solution Solve(const SceneMesh& mesh, double cache, int rays, int threads = 0)
{
  SolverOptions o = Converged(1e-6);
  // The clustered method's far links leave up to 3e-6 behind a wall (TestFinalGather).
  o.SolverMethod = SolverMethod::Hierarchical;
  o.Gather.Rays = rays;
  o.Gather.CacheAccuracy = cache;
  o.Threads = threads;
  const RadiositySolver solver(mesh);
  return SolveLights(solver, mesh, LightGrouping::OnePerLight(1), {}, SolutionMode::LightTagged, o);
}

/// Every point of a 40 x 40 grid on the plane z = 0, facing up.
void Plane(std::vector<Vec3>& origins, std::vector<Vec3>& normals)
{
  for (int j = 0; j < 40; ++j)
  {
    for (int i = 0; i < 40; ++i)
    {
      origins.push_back({ 0.05 * i, 0.05 * j, 0 });
      normals.push_back({ 0, 0, 1 });
    }
  }
}
/// A wall 1 m high at x = d, 2 km wide, of radiosity 1: its form factor from a point at the
/// origin facing `normal` (Lambert's closed form).
double WallFactor(double d, const Vec3& normal)
{
  const Vec3 wall[4] = { { d, -1000, 0 }, { d, 1000, 0 }, { d, 1000, 1 }, { d, -1000, 1 } };
  return PointToPolygonFormFactor({ 0, 0, 0 }, normal, wall, 4);
}

/// The gather's stratified rays from the origin, facing up, against that wall.
StratifiedRays RaysAtWall(double d, int side)
{
  StratifiedRays rays;
  rays.Reset(side, 1);
  rays.T = { 1, 0, 0 };
  rays.B = { 0, 1, 0 };
  for (int i = 0; i < side; ++i)
  {
    for (int j = 0; j < side; ++j)
    {
      // Jittered as the gather's are, by a fixed pattern.
      const double u = (i + 0.5 + 0.3 * std::sin(7.0 * i + 3.0 * j)) / side;
      const double phi = 2 * M_PI * (j + 0.5 + 0.3 * std::cos(5.0 * i + 11.0 * j)) / side;
      const Vec3 dir{ std::sqrt(u) * std::cos(phi), std::sqrt(u) * std::sin(phi), std::sqrt(1 - u) };
      const size_t cell = static_cast<size_t>(i) * side + j;
      rays.U[cell] = u;
      rays.SetPhi(cell, std::cos(phi), std::sin(phi));
      const double t = dir.x > 0 ? d / dir.x : -1;
      if (t > 0 && t * dir.z <= 1 && std::abs(t * dir.y) <= 1000)
      {
        rays.Distance[cell] = t;
        rays.Values[cell] = { 1, 1, 1 };
      }
    }
  }
  return rays;
}
} // namespace

TEST(IrradianceCache, GradientsMatchTheClosedFormBesideAWall)
{
  // Ward & Heckbert's gradients from 64 x 64 rays against Lambert's formula differentiated:
  // moving towards the wall and turning towards it. Both are estimates from the rays, 3.6 %
  // and 5.0 % off here (the turn weighs rays by tan theta, largest at the wall's foot).
  const double d = 1.0, h = 1e-4;
  const StratifiedRays rays = RaysAtWall(d, 64);
  Vec3 translation[3], rotation[3];
  IrradianceGradients(rays, translation, rotation);
  const double towards = (WallFactor(d - h, { 0, 0, 1 }) - WallFactor(d + h, { 0, 0, 1 })) / (2 * h);
  const double tilt = (WallFactor(d, { std::sin(h), 0, std::cos(h) }) - WallFactor(d, { -std::sin(h), 0, std::cos(h) })) /
    (2 * h);
  std::printf("towards the wall %.5f (closed form %.5f); turning to it %.5f (closed form %.5f)\n", translation[0].x,
    towards, rotation[0].y, tilt);
  EXPECT_NEAR(translation[0].x, towards, 0.06 * towards);
  EXPECT_NEAR(translation[0].y, 0.0, 0.02 * towards);
  // Turning the normal by e towards +x: record normal x n = (0, sin e, 0).
  EXPECT_NEAR(rotation[0].y, tilt, 0.08 * tilt);
  EXPECT_NEAR(rotation[0].x, 0.0, 0.02 * tilt);
}

TEST(IrradianceCache, ReachIsAFractionOfTheHarmonicMeanAtMostTheNearestHit)
{
  const double far = 1e9;
  // Four rays hitting at 1, 1, 2 and 4: the harmonic mean 4 / 2.75.
  const double inverse = 1 + 1 + 0.5 + 0.25;
  EXPECT_NEAR(RecordReach(0.5, inverse, 4, 1.0, far), 0.5 * 4 / 2.75, 1e-12);
  EXPECT_NEAR(RecordReach(0.5, inverse, 4, 0.5, far), 0.5, 1e-12);
  // Eight rays, four of them missing: the misses went infinitely far.
  EXPECT_NEAR(RecordReach(0.3, inverse, 8, 10.0, far), 0.3 * 8 / 2.75, 1e-12);
  EXPECT_EQ(RecordReach(0.0, inverse, 4, 1.0, far), 0.0);
  // Every ray missing (a roof under the sky): the largest reach, not every point facing up.
  EXPECT_EQ(RecordReach(0.3, 0.0, 8, std::numeric_limits<double>::infinity(), 2.5), 2.5);
  EXPECT_NEAR(LargestReach(30.0), 1.5, 1e-12);
}

TEST(IrradianceCache, WeightsFallToZeroAtTheReachAndAtTwentyDegrees)
{
  const IrradianceCache cache({ { 0, { 0, 0, 0 }, { 0, 0, 1 }, 1.0 } });
  std::vector<std::pair<int, double>> w;
  EXPECT_NEAR(cache.Weights({ 0.5, 0, 0 }, { 0, 0, 1 }, w), 0.5, 1e-12);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(cache.Weights({ 1.01, 0, 0 }, { 0, 0, 1 }, w), 0.0);
  EXPECT_TRUE(w.empty());
  auto tilted = [](double degrees) { return Vec3{ std::sin(degrees * M_PI / 180), 0, std::cos(degrees * M_PI / 180) }; };
  EXPECT_EQ(cache.Weights({ 0.1, 0, 0 }, tilted(25), w), 0.0);
  // At 10 degrees: 1 - sqrt((1 - cos 10) / (1 - cos 20)) = 0.49813..., more than the distance's 0.9.
  EXPECT_NEAR(cache.Weights({ 0.1, 0, 0 }, tilted(10), w),
    1 - std::sqrt((1 - std::cos(10 * M_PI / 180)) / (1 - std::cos(20 * M_PI / 180))), 1e-12);
}

TEST(IrradianceCache, ARecordAboveThePointIsNotRead)
{
  // A table top 0.7 m over a floor point, both facing up, well within the record's reach.
  const IrradianceCache cache({ { 0, { 0, 0, 0.7 }, { 0, 0, 1 }, 2.0 } });
  std::vector<std::pair<int, double>> w;
  EXPECT_EQ(cache.Weights({ 0.1, 0, 0 }, { 0, 0, 1 }, w), 0.0);
  // The other way round, the floor's record under the table top is behind it: read.
  const IrradianceCache floor({ { 0, { 0, 0, 0 }, { 0, 0, 1 }, 2.0 } });
  EXPECT_GT(floor.Weights({ 0.1, 0, 0.05 }, { 0, 0, 1 }, w), 0.0);
  // A record of no reach (it saw mostly back faces) is read by no one.
  const IrradianceCache hidden({ { 0, { 0, 0, 0 }, { 0, 0, 1 }, 0.0 } });
  EXPECT_EQ(hidden.Weights({ 0, 0, 0 }, { 0, 0, 1 }, w), 0.0);
}

TEST(IrradianceCache, RecordsCoverEveryPointTheSameOnAnyThreadCount)
{
  std::vector<Vec3> origins, normals;
  Plane(origins, normals);
  auto place = [&](int threads) {
    const WorkerPool pool(threads);
    return PlaceRecords(origins, normals,
      [&](const std::vector<int>& list) {
        std::vector<CacheRecord> out;
        for (int q : list)
        {
          // Reach shrinking towards the edge x = 0, as a wall's would.
          out.push_back({ q, origins[q], normals[q], 0.05 + 0.2 * origins[q].x });
        }
        return out;
      },
      [&](int count, const std::function<void(int, int)>& body) { pool.For(count, 16, body); });
  };
  const std::vector<CacheRecord> one = place(1), two = place(2);
  ASSERT_EQ(one.size(), two.size());
  for (size_t i = 0; i < one.size(); ++i)
  {
    EXPECT_EQ(one[i].Point, two[i].Point);
  }
  EXPECT_LT(one.size(), origins.size() / 3) << "the cache shares little";
  std::vector<char> own(origins.size(), 0);
  for (const CacheRecord& r : one)
  {
    own[r.Point] = 1;
  }
  const IrradianceCache cache(one);
  std::vector<std::pair<int, double>> w;
  for (size_t q = 0; q < origins.size(); ++q)
  {
    EXPECT_TRUE(own[q] || cache.Weights(origins[q], normals[q], w) >= 0.2) << "point " << q << " is not covered";
  }
}

TEST(IrradianceCache, NoLightReachesTheRoomBehindAWall)
{
  const SceneMesh mesh = TwoRooms(20);
  const Solution s = Solve(mesh, 0.5, 64);
  ASSERT_EQ(s.PointRadiosity.size(), mesh.Points.size());
  EXPECT_GT(s.GatherRecords, 0);
  EXPECT_LT(s.GatherRecords, s.GatherPoints) << "every point gathered: the cache was not tried";
  for (size_t p = 0; p < mesh.Points.size(); ++p)
  {
    if (mesh.Points[p].x > 1.2 + 1e-9)
    {
      EXPECT_EQ(s.PointRadiosity[p].x, 0.0) << "point " << p;
    }
  }
}

TEST(IrradianceCache, ARecordUnderTheSkyDoesNotReachTheFloorUnderItsRoof)
{
  // The lamp room under a 60 m roof open to the sky: the roof's records meet nothing, and
  // reached every point facing up, the floor inside too (the Duplex's floors came out a
  // third dark), until a reach had a largest value.
  SceneMesh mesh = LampRoom(12);
  int patch = 2000;
  AddGrid(mesh, { -28.5, -28.5, 3.2 }, { 60, 0, 0 }, { 0, 60, 0 }, 30, 3, { 0.5, 0.5, 0.5 }, -1, patch);
  const Solution every = Solve(mesh, 0.0, 64), cached = Solve(mesh, 0.15, 64);
  double floorEvery = 0, floorCached = 0;
  for (size_t p = 0; p < mesh.Points.size(); ++p)
  {
    const Vec3& x = mesh.Points[p];
    if (x.z == 0 && x.x > 0 && x.x < 3 && x.y > 0 && x.y < 3)
    {
      floorEvery += every.PointRadiosity[p].x;
      floorCached += cached.PointRadiosity[p].x;
    }
  }
  EXPECT_GT(floorEvery, 0.0);
  EXPECT_NEAR(floorCached / floorEvery, 1.0, 0.02);
}

TEST(IrradianceCache, FurnaceIsExactAtEveryPoint)
{
  // A closed box emitting 1 everywhere at rho 0.5: B = 2 at every point, records or not.
  const SceneMesh mesh = Box(1.0, 16, 4, { 0.5, 0.5, 0.5 }, [](int) { return 0; });
  const Solution s = Solve(mesh, 0.3, 64);
  EXPECT_LT(s.GatherRecords, s.GatherPoints);
  for (size_t p = 0; p < mesh.Points.size(); ++p)
  {
    EXPECT_NEAR(s.PointRadiosity[p].x, 2.0, 2e-3) << "point " << p;
  }
}

TEST(IrradianceCache, AgreesWithGatheringAtEveryPointAndSameBitsOnAnyThreads)
{
  const SceneMesh mesh = LampRoom(24);
  const Solution every = Solve(mesh, 0.0, 1024), cached = Solve(mesh, 0.3, 1024, 1), again = Solve(mesh, 0.3, 1024, 2);
  ASSERT_EQ(cached.PointRadiosity.size(), every.PointRadiosity.size());
  ASSERT_EQ(again.PointRadiosity.size(), cached.PointRadiosity.size());
  for (size_t p = 0; p < cached.PointRadiosity.size(); ++p)
  {
    ASSERT_EQ(cached.PointRadiosity[p].x, again.PointRadiosity[p].x) << "point " << p;
  }
  double sumEvery = 0, sumCached = 0, apart = 0;
  for (size_t p = 0; p < every.PointRadiosity.size(); ++p)
  {
    sumEvery += every.PointRadiosity[p].x;
    sumCached += cached.PointRadiosity[p].x;
    apart += std::abs(cached.PointRadiosity[p].x - every.PointRadiosity[p].x);
  }
  std::printf("records %d of %d points; mean %.6f cached, %.6f every point; mean |difference| %.3f %%\n",
    cached.GatherRecords, cached.GatherPoints, sumCached / every.PointRadiosity.size(),
    sumEvery / every.PointRadiosity.size(), 100 * apart / sumEvery);
  EXPECT_LT(cached.GatherRecords, cached.GatherPoints / 2);
  EXPECT_NEAR(sumCached / sumEvery, 1.0, 0.01);
  EXPECT_LT(apart / sumEvery, 0.02);
}
