// The clustered method against closed forms, against progressive refinement with every
// element its own patch (the paper scene and the Cornell box: Python.TestClustered) (the exact transport of the same elements, which patch-level
// shooting only approximates), and against its own invariants (light tagging, the
// ledger, threads, a stop that keeps a valid result).
#include "CurvedRoom.h"
#include "FurnishedRoom.h"
#include "Solve/ElementTree.h"
#include "Solve/LightSolutions.h"
#include "SceneBuilders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

using namespace radiosity;
using radiosity_test::Box;
using radiosity_test::Converged;
using radiosity_test::RelativeDifference;

namespace
{
SolverOptions Options(SolverMethod method, double threshold)
{
  SolverOptions o = Converged(threshold);
  o.SolverMethod = method;
  return o;
}

Solution Solve(const SceneMesh& mesh, int lights, const SolverOptions& options,
  SolutionMode mode = SolutionMode::LightTagged)
{
  const RadiositySolver solver(mesh);
  EXPECT_TRUE(solver.Error().empty()) << solver.Error();
  return SolveLights(solver, mesh, LightGrouping::OnePerLight(lights), {}, mode, options);
}

/// Progressive refinement with every element its own shooter.
Solution Reference(SceneMesh mesh, int lights, int samples = 4)
{
  mesh.PatchId.clear();
  SolverOptions o = Options(SolverMethod::ProgressiveRefinement, 1e-4);
  o.FormFactorSamples = samples;
  return Solve(mesh, lights, o);
}

/// What the clustered method's sums take for `lights` in RGB: 23 floats a lane per tree
/// node (a tree of 2n - 1 nodes over n elements), 7 doubles a lane per element.
double SumsBytes(const SceneMesh& mesh, int lights)
{
  const double lanes = 3.0 * lights, elements = mesh.NumberOfPolygons();
  return (2 * elements - 1) * (23 * lanes * sizeof(float) + 3 * sizeof(double)) + elements * 7 * lanes * sizeof(double);
}

SceneMesh FurnishedRoom(double patch, double element)
{
  SceneMesh mesh;
  const std::string error = radiosity_scenes::MeshRoom(radiosity_scenes::FurnishedRoom(), patch, element, mesh);
  EXPECT_TRUE(error.empty()) << error;
  return mesh;
}

SceneMesh SphereRoom(int lamps, int triangles, double patch, double element)
{
  SceneMesh mesh;
  EXPECT_EQ(radiosity_scenes::MeshByMaterial(radiosity_scenes::CurvedRoom(lamps, 1, triangles), patch, element, 30, mesh), "");
  return mesh;
}
} // namespace

TEST(Clustered, FurnaceGivesOneOverOneMinusRho)
{
  // Closed box, every face emitting 1: B = 1 / (1 - rho) everywhere, here through cluster
  // links of every size (the receiver normalization makes a closed view sum to one).
  for (double rho : { 0.5, 0.9 })
  {
    SceneMesh box = Box(2.0, 24, 4, { rho, rho, rho }, [](int) { return 0; });
    const Solution s = Solve(box, 1, Options(SolverMethod::Clustered, 1e-7));
    ASSERT_TRUE(s.Statistics.Converged);
    EXPECT_EQ(s.Statistics.SolverMethod, SolverMethod::Clustered);
    EXPECT_GT(s.Statistics.VolumeLinks, 2 * s.Statistics.ElementLinks); // element pairs far apart count as element links
    // Bouncing would take log(1e-7) / log(rho) gathers (153 at 0.9); the linear solve far fewer.
    const int gathers = s.Statistics.Shots - static_cast<int>(SceneGeometry(box).PatchElements.size()); // each patch emits
    std::printf("furnace at rho %.1f: %d gathers\n", rho, gathers);
    EXPECT_LT(gathers, 0.5 * std::log(1e-7) / std::log(rho));
    const double expected = 1.0 / (1.0 - rho);
    double mean = 0, worst = 0;
    for (const Vec3& b : s.Radiosity)
    {
      mean += b.x / s.Radiosity.size();
      worst = std::max(worst, std::fabs(b.x - expected) / expected);
    }
    EXPECT_NEAR(mean, expected, 5e-3 * expected);
    EXPECT_LT(worst, 0.01);
  }
}

TEST(Clustered, SphereRoomEqualsProgressiveRefinement)
{
  // A 600-triangle sphere in face clusters: mixed-orientation clusters link whole.
  const SceneMesh mesh = SphereRoom(3, 600, 0.5, 0.5);
  const Solution a = Solve(mesh, 3, Options(SolverMethod::Clustered, 1e-4)), b = Reference(mesh, 3);
  for (double d : RelativeDifference(mesh, a, b))
  {
    std::printf("clustered vs progressive, sphere room: %.3f %%\n", 100 * d);
    EXPECT_LT(d, 0.01);
  }
}

TEST(Clustered, WiderSeparationComesCloserToProgressiveRefinement)
{
  // The separation at which groups of elements exchange light whole is the method's
  // accuracy knob: farther means more, smaller links, and less of the far-field error.
  const int lamps = 8;
  const SceneMesh mesh = FurnishedRoom(1.2, 0.4);
  const Solution reference = Reference(mesh, lamps);
  double previous = 1, links = 0;
  for (double separation : { 2.5, 4.0, 8.0 })
  {
    SolverOptions o = Options(SolverMethod::Clustered, 1e-4);
    o.Clustered.Separation = separation;
    const Solution s = Solve(mesh, lamps, o);
    double mean = 0;
    for (double d : RelativeDifference(mesh, s, reference))
    {
      mean += d / lamps;
    }
    const double made = static_cast<double>(s.Statistics.VolumeLinks + s.Statistics.ElementLinks);
    std::printf("separation %.1f: %.3f %% from progressive refinement, %.0f links\n", separation, 100 * mean, made);
    EXPECT_LT(mean, previous);
    EXPECT_GT(made, links);
    previous = mean, links = made;
  }
}

TEST(Clustered, AGroupingOfTooFewLightsIsAnError)
{
  // The furnished room has 8 lamps: a grouping of 3 wrote past its end before.
  const SceneMesh mesh = FurnishedRoom(2.0, 1.0);
  const RadiositySolver solver(mesh);
  try
  {
    SolveLights(solver, mesh, LightGrouping::OnePerLight(3), {}, SolutionMode::LightTagged,
      Options(SolverMethod::Clustered, 1e-3));
    FAIL() << "no error";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("the grouping covers 3 lights"), std::string::npos) << e.what();
  }
}

TEST(Clustered, SeparationBelowTwoIsAnError)
{
  for (double separation : { 1.5, std::nan(""), -4.0 })
  {
    SolverOptions o = Options(SolverMethod::Clustered, 1e-3);
    o.Clustered.Separation = separation;
    EXPECT_NE(OptionsProblem(o).find("ClusterSeparation is"), std::string::npos) << separation;
  }
  EXPECT_EQ(OptionsProblem(Options(SolverMethod::Clustered, 1e-3)), "");
}

TEST(Clustered, TaggedEqualsCombinedAndTheLedgerCloses)
{
  // The links do not depend on the lights: the sum of the k unit solutions is one solve
  // with every lamp on. Emitted = absorbed + escaped + unshot, absorbed from the output.
  const SceneMesh mesh = FurnishedRoom(0.6, 0.3);
  const Solution tagged = Solve(mesh, 8, Options(SolverMethod::Clustered, 1e-7));
  const Solution combined = Solve(mesh, 8, Options(SolverMethod::Clustered, 1e-7), SolutionMode::StandardCombined);
  EXPECT_LT(radiosity_test::TaggedMinusCombined(tagged, combined), 1e-5);
  const SolverStatistics& t = tagged.Statistics;
  const double absorbed = radiosity_test::AbsorbedPower(mesh, tagged);
  EXPECT_NEAR(absorbed + t.EscapedPower + t.UnshotPower, t.EmittedPower, 1e-9 * t.EmittedPower);
  EXPECT_LT(std::fabs(t.EscapedPower), 0.05 * t.EmittedPower);
}

TEST(Clustered, SameResultOnAnyNumberOfThreads)
{
  const SceneMesh mesh = SphereRoom(3, 4000, 0.5, 0.25);
  SolverOptions one = Options(SolverMethod::Clustered, 1e-4), three = one;
  one.Threads = 1;
  three.Threads = 3;
  const Solution a = Solve(mesh, 3, one), b = Solve(mesh, 3, three);
  ASSERT_EQ(a.Radiosity.size(), b.Radiosity.size());
  for (size_t i = 0; i < a.Radiosity.size(); ++i)
  {
    ASSERT_EQ(a.Radiosity[i].x, b.Radiosity[i].x) << i;
    ASSERT_EQ(a.Radiosity[i].z, b.Radiosity[i].z) << i;
  }
}

TEST(Clustered, SameResultWhereverTheSceneIsTurnedOrMoved)
{
  // The tree's splits (in space and by facing) are judged to quanta (of the scene's size,
  // of unit normals), so turning and moving the scene builds the same tree and draws the
  // same rays; Embree's float arithmetic and the rays' lift off the surfaces (from the
  // axis-aligned box) differ. Scaled by 1,000, the tree is the same too.
  const SceneMesh mesh = SphereRoom(3, 4000, 0.5, 0.25);
  SceneMesh moved = mesh;
  const Vec3 axis = Normalized(Vec3{ 0.3, 0.8, 0.2 });
  const double angle = 37 * Pi / 180, c = std::cos(angle), s = std::sin(angle);
  for (Vec3& p : moved.Points)
  {
    // Rodrigues' rotation, then a shift far from the origin.
    const Vec3 turned = p * c + Cross(axis, p) * s + axis * (Dot(axis, p) * (1 - c));
    p = turned + Vec3{ 1e3, -300, 500 };
  }
  SceneMesh scaled = mesh;
  for (Vec3& p : scaled.Points)
  {
    p = p * 1000.0;
  }
  const SceneGeometry g(mesh), h(moved), k(scaled);
  const ElementTree built(mesh, g), turned(moved, h), large(scaled, k);
  ASSERT_EQ(built.Nodes().size(), turned.Nodes().size());
  EXPECT_EQ(built.Elements(), turned.Elements());
  EXPECT_EQ(built.Elements(), large.Elements());
  int byFacing = 0;
  for (size_t n = 0; n < built.Nodes().size(); ++n)
  {
    const ElementTree::Node &x = built.Nodes()[n], &y = turned.Nodes()[n];
    ASSERT_EQ(x.Left, y.Left) << n;
    ASSERT_EQ(x.Count, y.Count) << n;
    byFacing += x.Left >= 0 && built.Nodes()[x.Left].Count != x.Count / 2 ? 1 : 0;
  }
  EXPECT_GT(byFacing, 0); // the room's walls and the sphere's sides part by facing
  const SolverOptions options = Options(SolverMethod::Clustered, 1e-4);
  const Solution a = Solve(mesh, 3, options), b = Solve(moved, 3, options);
  ASSERT_EQ(a.Solutions, 3);
  // A ray grazing an edge may fall the other way in float: a few links differ.
  ASSERT_GT(a.Statistics.VolumeLinks, 0);
  EXPECT_NEAR(static_cast<double>(b.Statistics.VolumeLinks) / a.Statistics.VolumeLinks, 1.0, 1e-3);
  for (double d : RelativeDifference(mesh, b, a))
  {
    std::printf("clustered, turned and moved against as built: %.4f %%\n", 100 * d);
    EXPECT_LT(d, 1e-3);
  }
}

TEST(Clustered, AStoppedSolveKeepsTheDirectLightAndBooksTheRest)
{
  // Aborted at the first bounce: the direct light (emission and its first bounce, per
  // element with shadow rays) is all there, what was not carried is unshot, the ledger holds.
  const SceneMesh mesh = FurnishedRoom(0.6, 0.3);
  SolverOptions full = Options(SolverMethod::Clustered, 1e-4);
  full.SeparateDirect = true;
  SolverOptions stopped = full;
  int calls = 0;
  stopped.Progress = [&](double) { return ++calls <= 9; }; // 8 lamps shoot, then the links start
  const Solution a = Solve(mesh, 8, full), b = Solve(mesh, 8, stopped);
  EXPECT_TRUE(b.Statistics.Aborted);
  EXPECT_FALSE(b.Statistics.Converged);
  for (size_t i = 0; i < a.Direct.size(); ++i)
  {
    ASSERT_NEAR(b.Radiosity[i].x, a.Direct[i].x, 1e-12 + 1e-9 * a.Direct[i].x) << i;
  }
  const SolverStatistics& t = b.Statistics;
  EXPECT_GT(t.UnshotPower, 0.1 * t.EmittedPower);
  EXPECT_NEAR(radiosity_test::AbsorbedPower(mesh, b) + t.EscapedPower + t.UnshotPower, t.EmittedPower, 1e-9 * t.EmittedPower);
}

TEST(Clustered, LinksThatWouldNotFitStopTheSolveWithTheDirectLightAndSayWhy)
{
  // The same room under a memory limit that holds the sums but far from what its links
  // take: the build stops once a tenth of it shows the whole would not fit, with the direct
  // light and the reason.
  const SceneMesh mesh = FurnishedRoom(0.6, 0.3);
  SolverOptions full = Options(SolverMethod::Clustered, 1e-4);
  full.SeparateDirect = true;
  SolverOptions capped = full;
  const Solution a = Solve(mesh, 8, full);
  capped.Clustered.MemoryLimit = SumsBytes(mesh, 8) + 0.1 * a.Statistics.LinkBytes;
  const Solution b = Solve(mesh, 8, capped);
  const SolverStatistics& t = b.Statistics;
  EXPECT_TRUE(a.Statistics.OutOfMemory.empty()) << a.Statistics.OutOfMemory;
  EXPECT_NE(t.OutOfMemory.find("the clustered method's links"), std::string::npos) << t.OutOfMemory;
  EXPECT_NE(t.OutOfMemory.find("MemoryLimit"), std::string::npos) << t.OutOfMemory;
  EXPECT_FALSE(t.Converged);
  EXPECT_FALSE(t.Aborted);
  EXPECT_LT(t.VolumeLinks, a.Statistics.VolumeLinks / 2); // stopped early in the build
  for (size_t i = 0; i < a.Direct.size(); ++i)
  {
    ASSERT_NEAR(b.Radiosity[i].x, a.Direct[i].x, 1e-12 + 1e-9 * a.Direct[i].x) << i;
  }
  EXPECT_NEAR(radiosity_test::AbsorbedPower(mesh, b) + t.EscapedPower + t.UnshotPower, t.EmittedPower, 1e-9 * t.EmittedPower);
  capped.Clustered.MemoryLimit = 10 * a.Statistics.LinkBytes; // room to spare: the same answer
  EXPECT_EQ(Solve(mesh, 8, capped).Radiosity[7].x, a.Radiosity[7].x);
}

TEST(Clustered, SumsThatWouldNotFitStopTheSolveBeforeItsLinks)
{
  // The gathering's sums per tree node (8 lights x RGB x 23 floats a node) are known before
  // any link is: under a limit below them, the solve says so at once, keeps the direct
  // light and books the rest; under one that holds them but not the links beside them,
  // the build stops early and names both.
  const SceneMesh mesh = FurnishedRoom(0.6, 0.3);
  SolverOptions full = Options(SolverMethod::Clustered, 1e-4);
  full.SeparateDirect = true;
  const Solution a = Solve(mesh, 8, full);
  const double sums = SumsBytes(mesh, 8);
  std::printf("links %.2f MB, sums %.2f MB\n", a.Statistics.LinkBytes / 1e6, sums / 1e6);
  SolverOptions capped = full;
  capped.Clustered.MemoryLimit = 0.5 * sums;
  const Solution b = Solve(mesh, 8, capped);
  const SolverStatistics& t = b.Statistics;
  EXPECT_NE(t.OutOfMemory.find("the clustered method's sums needs about"), std::string::npos) << t.OutOfMemory;
  EXPECT_EQ(t.VolumeLinks, 0);
  EXPECT_FALSE(t.Converged);
  for (size_t i = 0; i < a.Direct.size(); ++i)
  {
    ASSERT_NEAR(b.Radiosity[i].x, a.Direct[i].x, 1e-12 + 1e-9 * a.Direct[i].x) << i;
  }
  EXPECT_NEAR(radiosity_test::AbsorbedPower(mesh, b) + t.EscapedPower + t.UnshotPower, t.EmittedPower, 1e-9 * t.EmittedPower);
  capped.Clustered.MemoryLimit = 1.1 * sums + 0.5 * a.Statistics.LinkBytes; // the sums fit, not the links beside them
  const SolverStatistics& u = Solve(mesh, 8, capped).Statistics;
  EXPECT_NE(u.OutOfMemory.find("the clustered method's links and sums needs about"), std::string::npos) << u.OutOfMemory;
  EXPECT_LT(u.VolumeLinks, a.Statistics.VolumeLinks / 2);
}

TEST(Clustered, HundredThousandTriangleSphereRoomSolves)
{
  const int lamps = 1; // the links are the cost to test; each light adds to the bounces only
  const SceneMesh mesh = SphereRoom(lamps, 100000, 0.5, 0.1);
  ASSERT_GT(mesh.NumberOfPolygons(), 50000);
  const Solution s = Solve(mesh, lamps, Options(SolverMethod::Clustered, 1e-3));
  const SolverStatistics& st = s.Statistics;
  EXPECT_TRUE(st.Converged);
  EXPECT_NEAR(st.EmittedPower, radiosity_test::AbsorbedPower(mesh, s) + st.EscapedPower + st.UnshotPower, 1e-6 * st.EmittedPower);
}

TEST(Clustered, AutoPicksItWhereItsEstimatedCostIsLower)
{
  // 21,600 patches of one element each: every polygon would be a shooter (about 47 s of
  // links against about 2 s of clusters by Auto's estimate). A box of as many elements in 600
  // patches stays hierarchical. (A budget of nothing: only the choice counts.)
  SolverOptions automatic = Converged(1e-3);
  automatic.TimeBudget = 1e-9;
  const SceneMesh tiny = Box(2.0, 60, 1, { 0.5, 0.5, 0.5 }, [](int f) { return f == 1 ? 0 : -1; });
  const Solution a = Solve(tiny, 1, automatic);
  EXPECT_EQ(a.Statistics.SolverMethod, SolverMethod::Clustered);
  EXPECT_NE(a.Statistics.MethodReason.find("21600 patches, about"), std::string::npos) << a.Statistics.MethodReason;
  const SceneMesh large = Box(2.0, 60, 6, { 0.5, 0.5, 0.5 }, [](int f) { return f == 1 ? 0 : -1; });
  EXPECT_EQ(Solve(large, 1, automatic).Statistics.SolverMethod, SolverMethod::Hierarchical);
  SolverOptions basis = automatic; // the moving-light basis: every patch a solution, no node sums for them
  basis.Hierarchical.DirectToElements = false;
  EXPECT_EQ(Solve(tiny, 1, basis).Statistics.SolverMethod, SolverMethod::Hierarchical);
}

TEST(Clustered, ABoxTurnedEveryWayBehindAWallReceivesNothing)
{
  // A box's faces turn every way, so of the points drawn on it for a link's rays most do
  // not face the other end. A link whose draws all missed used to pass as fully visible:
  // the lamp's room lit the box through the wall.
  SceneMesh mesh = radiosity_test::TwoRooms(10);
  const int first = mesh.NumberOfPolygons();
  int patch = 1 + *std::max_element(mesh.PatchId.begin(), mesh.PatchId.end());
  const Vec3 o{ 1.5, 0.35, 0.05 }, X{ 0.3, 0, 0 }, Y{ 0, 0.3, 0 }, Z{ 0, 0, 0.3 }, grey{ 0.6, 0.6, 0.6 };
  // Each (origin, u, v) with u x v pointing out of the box.
  radiosity_test::AddGrid(mesh, o, Y, X, 2, 2, grey, -1, patch);
  radiosity_test::AddGrid(mesh, o + Z, X, Y, 2, 2, grey, -1, patch);
  radiosity_test::AddGrid(mesh, o, X, Z, 2, 2, grey, -1, patch);
  radiosity_test::AddGrid(mesh, o + Y, Z, X, 2, 2, grey, -1, patch);
  radiosity_test::AddGrid(mesh, o, Z, Y, 2, 2, grey, -1, patch);
  radiosity_test::AddGrid(mesh, o + X, Y, Z, 2, 2, grey, -1, patch);
  // One ray a link, where a pair's draws miss most often: 1.1e-4 before; the far links'
  // own spill to a node's elements behind the wall stays (TestFinalGather's 1e-5).
  SolverOptions options = Options(SolverMethod::Clustered, 1e-6);
  options.FormFactorSamples = 1;
  const Solution s = Solve(mesh, 1, options);
  double box = 0, lit = 0;
  for (int e = first; e < mesh.NumberOfPolygons(); ++e)
  {
    box = std::max(box, s.Radiosity[e].x);
  }
  for (int e = 0; e < first; ++e)
  {
    const bool lampRoom = mesh.LightId[e] < 0 && mesh.Points[mesh.Polygon(e)[0]].x < 1.0;
    lit = lampRoom ? std::max(lit, s.Radiosity[e].x) : lit;
  }
  std::printf("the box behind the wall %.3g, the lamp's room up to %.3g\n", box, lit);
  EXPECT_LE(box, 1e-5);
  EXPECT_GT(lit, 0.01);
}
