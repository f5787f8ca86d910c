// Several processes solving one scene together (SolverOptions::Group), played here by
// threads with a sum over them as MPI_Allreduce would do it: every rank must get the
// serial answer, whatever the number of ranks and the method, and stop where the others do.
#include "CurvedRoom.h"
#include "FurnishedRoom.h"
#include "Solve/LightSolutions.h"
#include "SceneBuilders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <thread>

using namespace radiosity;
using radiosity_test::Converged;

namespace
{
/// An allreduce over threads: each rank's values wait in its own slot, and the last to
/// arrive adds them in rank order, so the sums do not depend on who came first.
class ThreadRanks
{
public:
  explicit ThreadRanks(int ranks)
    : Slots(ranks)
  {
  }

  ProcessGroup Group(int rank)
  {
    ProcessGroup group;
    group.Rank = rank;
    group.Ranks = static_cast<int>(Slots.size());
    group.SumAll = [this, rank](double* values, size_t count) { Sum(rank, values, count); };
    return group;
  }

  long long Rounds() const { return Generation; }

private:
  void Sum(int rank, double* values, size_t count)
  {
    std::unique_lock<std::mutex> lock(Mutex);
    Slots[rank].assign(values, values + count);
    const long long round = Generation;
    if (++Arrived == static_cast<int>(Slots.size()))
    {
      Result.assign(count, 0.0);
      for (const std::vector<double>& slot : Slots)
      {
        EXPECT_EQ(slot.size(), count) << "the ranks called the sum with different counts";
        for (size_t i = 0; i < std::min(count, slot.size()); ++i)
        {
          Result[i] += slot[i];
        }
      }
      Arrived = 0;
      ++Generation;
      Changed.notify_all();
    }
    else
    {
      Changed.wait(lock, [&] { return Generation != round; });
    }
    std::copy(Result.begin(), Result.end(), values);
  }

  std::mutex Mutex;
  std::condition_variable Changed;
  std::vector<std::vector<double>> Slots;
  std::vector<double> Result;
  int Arrived = 0;
  long long Generation = 0;
};

/// Solves `mesh` (with `lights` lights) on `ranks` threads as ranks, each with its own
/// solver (as each MPI rank prepares the whole scene); `tweak` may change a rank's options.
std::vector<Solution> SolveOnRanks(const SceneMesh& mesh, int ranks, const SolverOptions& options,
  const std::function<void(int, SolverOptions&)>& tweak = nullptr, int lights = 8, long long* rounds = nullptr,
  const std::vector<PointLight>& points = {})
{
  ThreadRanks group(ranks);
  std::vector<Solution> results(ranks);
  std::vector<std::thread> threads;
  for (int r = 0; r < ranks; ++r)
  {
    threads.emplace_back([&, r] {
      SolverOptions mine = options;
      mine.Group = group.Group(r);
      mine.Threads = 1;
      if (tweak)
      {
        tweak(r, mine);
      }
      const RadiositySolver solver(mesh, mine.Threads, mine.Group); // the ranks share its probes too
      results[r] =
        SolveLights(solver, mesh, LightGrouping::OnePerLight(lights), {}, SolutionMode::LightTagged, mine, points);
    });
  }
  for (std::thread& t : threads)
  {
    t.join();
  }
  if (rounds)
  {
    *rounds = group.Rounds();
  }
  return results;
}

SceneMesh Room()
{
  SceneMesh mesh;
  const std::string error = radiosity_scenes::MeshRoom(radiosity_scenes::FurnishedRoom(), 1.0, 0.25, mesh);
  EXPECT_TRUE(error.empty()) << error;
  return mesh;
}

/// The largest |a - b| over every value, relative to the largest value of b.
double LargestDifference(const std::vector<Vec3>& a, const std::vector<Vec3>& b)
{
  EXPECT_EQ(a.size(), b.size());
  double most = 0, peak = 0;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i)
  {
    most = std::max({ most, std::fabs(a[i].x - b[i].x), std::fabs(a[i].y - b[i].y), std::fabs(a[i].z - b[i].z) });
    peak = std::max({ peak, b[i].x, b[i].y, b[i].z });
  }
  return peak > 0 ? most / peak : most;
}

/// `tolerance`: relative, for the sums whose order differs between one process and several.
void ExpectSerialAnswer(SolverMethod method, int ranks, bool direct, const SceneMesh& mesh = Room(), int lights = 8,
  double tolerance = 1e-9, const std::vector<PointLight>& points = {})
{
  SolverOptions options = Converged(1e-4);
  options.SolverMethod = method;
  options.SeparateDirect = direct;
  options.AmbientTerm = direct;
  options.Threads = 1;
  const RadiositySolver serial(mesh);
  const Solution one =
    SolveLights(serial, mesh, LightGrouping::OnePerLight(lights), {}, SolutionMode::LightTagged, options, points);
  const std::vector<Solution> many = SolveOnRanks(mesh, ranks, options, nullptr, lights, nullptr, points);
  for (int r = 0; r < ranks; ++r)
  {
    const SolverStatistics& s = many[r].Statistics;
    EXPECT_EQ(s.Shots, one.Statistics.Shots) << "rank " << r;
    EXPECT_EQ(s.Converged, one.Statistics.Converged);
    EXPECT_EQ(s.Ranks, ranks);
    EXPECT_GT(s.CollectiveBytes, 0);
    // Only the order of a few sums differs from one process (the conservation scale).
    EXPECT_LT(LargestDifference(many[r].Radiosity, one.Radiosity), tolerance) << "rank " << r;
    EXPECT_LT(LargestDifference(many[r].Direct, one.Direct), tolerance) << "rank " << r;
    EXPECT_NEAR(s.RayCount, one.Statistics.RayCount, 1e-6 * one.Statistics.RayCount);
    EXPECT_NEAR(s.ReceivedPower, one.Statistics.ReceivedPower, tolerance * one.Statistics.ReceivedPower);
    // The convergence table, every shot, as one process has it; the lights converge at
    // different shots, so the shooter is also chosen again after one drops out.
    ASSERT_EQ(s.RemainingPerSolution.size(), one.Statistics.RemainingPerSolution.size());
    ASSERT_EQ(s.TimeHistory.size(), static_cast<size_t>(s.Shots));
    for (size_t i = 0; i < s.RemainingPerSolution.size(); ++i)
    {
      EXPECT_NEAR(s.RemainingPerSolution[i], one.Statistics.RemainingPerSolution[i], tolerance) << "entry " << i;
    }
    EXPECT_NEAR(s.EscapedPower, one.Statistics.EscapedPower, tolerance * one.Statistics.EmittedPower);
    // The ambient term is what is left to travel: against the radiosity it is added to
    // (the clustered method's remainder is a residual, summed from terms of both signs).
    double peak = 1e-30;
    for (const Vec3& b : one.Radiosity)
    {
      peak = std::max({ peak, b.x, b.y, b.z });
    }
    for (int m = 0; m < lights + static_cast<int>(points.size()); ++m)
    {
      EXPECT_NEAR(many[r].Ambient[m].x, one.Ambient[m].x, tolerance * peak);
    }
  }
}
} // namespace

TEST(Distributed, ProgressiveOnTwoRanksGivesTheSerialAnswer)
{
  ExpectSerialAnswer(SolverMethod::ProgressiveRefinement, 2, false);
}

TEST(Distributed, HierarchicalOnThreeRanksGivesTheSerialAnswerWithDirectAndAmbient)
{
  ExpectSerialAnswer(SolverMethod::Hierarchical, 3, true);
}

TEST(Distributed, ClusteredOnThreeRanksGivesTheSerialAnswerWithDirectAndAmbient)
{
  // Each rank links its share of the node pairs; the bounce's node sums meet in one sum.
  // They are floats: summed in another order, they round differently (about 1e-7).
  ExpectSerialAnswer(SolverMethod::Clustered, 3, true, Room(), 8, 1e-6);
}

TEST(Distributed, ClusteredWithPointLightsOnTwoRanksGivesTheSerialAnswer)
{
  // The point lights' reflected light starts on every rank's own elements and travels the
  // links with the lamps' (counted once, not once per rank).
  std::vector<PointLight> points(2);
  points[0].Position = { 1.5, 1.2, 2.2 };
  points[1].Position = { 3.0, 2.5, 1.0 };
  points[1].Aim = { 1, 0, 0 };
  ExpectSerialAnswer(SolverMethod::Clustered, 2, true, Room(), 8, 1e-6, points);
}

TEST(Distributed, FaceClustersOnTwoRanksGiveTheSerialAnswer)
{
  // Cluster receivers linked node by node, element links shared element by element.
  SceneMesh mesh;
  ASSERT_EQ(radiosity_scenes::MeshByMaterial(radiosity_scenes::CurvedRoom(3, 1, 4000), 0.5, 0.25, 30, mesh), "");
  ExpectSerialAnswer(SolverMethod::Hierarchical, 2, true, mesh, 3);
}

TEST(Distributed, SharesAreEvenAndCoverEveryPatchOnce)
{
  const SceneMesh mesh = Room();
  const SceneGeometry g(mesh);
  const int ranks = 3;
  std::vector<int> owners(g.PatchElements.size(), 0);
  std::vector<size_t> elements(ranks, 0);
  for (int r = 0; r < ranks; ++r)
  {
    const std::vector<char> owned = OwnedPatches(g, r, ranks);
    for (size_t p = 0; p < owned.size(); ++p)
    {
      owners[p] += owned[p];
      elements[r] += owned[p] ? g.PatchElements[p].size() : 0;
    }
  }
  EXPECT_TRUE(std::all_of(owners.begin(), owners.end(), [](int n) { return n == 1; }));
  const auto [least, most] = std::minmax_element(elements.begin(), elements.end());
  EXPECT_LT(static_cast<double>(*most - *least), 0.01 * static_cast<double>(g.Normal.size()));
}

TEST(Distributed, AnAbortOnOneRankStopsEveryRankAtTheSameShot)
{
  const SceneMesh mesh = Room();
  SolverOptions options = Converged(1e-6);
  options.SolverMethod = SolverMethod::Hierarchical;
  std::atomic<int> calls{ 0 };
  const std::vector<Solution> results = SolveOnRanks(mesh, 2, options, [&](int rank, SolverOptions& o) {
    if (rank == 1)
    {
      o.Progress = [&](double) { return ++calls < 40; }; // rank 1 alone aborts at its 40th check
    }
  });
  for (const Solution& s : results)
  {
    EXPECT_TRUE(s.Statistics.Aborted);
    EXPECT_FALSE(s.Statistics.Converged);
    EXPECT_EQ(s.Statistics.Shots, 39);
  }
  EXPECT_EQ(LargestDifference(results[0].Radiosity, results[1].Radiosity), 0.0);
}

TEST(Distributed, ATimeBudgetReachedOnOneRankStopsEveryRank)
{
  const SceneMesh mesh = Room();
  SolverOptions options = Converged(1e-6);
  options.SolverMethod = SolverMethod::ProgressiveRefinement;
  const std::vector<Solution> results = SolveOnRanks(mesh, 2, options, [](int rank, SolverOptions& o) {
    o.TimeBudget = rank == 0 ? 1e-9 : 0; // rank 0 is out of time at once, rank 1 has none
  });
  for (const Solution& s : results)
  {
    EXPECT_TRUE(s.Statistics.OutOfTime);
    EXPECT_EQ(s.Statistics.Shots, 0);
  }
}

TEST(Distributed, ARankWithNoPatchesJoinsAndGetsTheWhole)
{
  // More ranks than patches: the last ones receive for nothing and still get the answer.
  SceneMesh mesh = radiosity_test::Box(1.0, 1, 1, { 0.5, 0.5, 0.5 }, [](int face) { return face == 5 ? 0 : -1; });
  SolverOptions options = Converged(1e-6);
  options.SolverMethod = SolverMethod::ProgressiveRefinement;
  const RadiositySolver serial(mesh);
  const int lights = 1;
  const Solution one =
    SolveLights(serial, mesh, LightGrouping::OnePerLight(lights), {}, SolutionMode::LightTagged, options);
  const std::vector<Solution> results = SolveOnRanks(mesh, 8, options, nullptr, lights);
  for (const Solution& s : results)
  {
    EXPECT_LT(LargestDifference(s.Radiosity, one.Radiosity), 1e-12);
  }
}

TEST(Distributed, AFailureOnOneRankStopsEveryRank)
{
  // Memory differs from rank to rank: a check that fails on one must stop all before the
  // solve's first sum, or the others would wait there for ever.
  ThreadRanks group(3);
  std::vector<std::string> verdicts(3), quiet(3);
  std::vector<std::thread> threads;
  for (int r = 0; r < 3; ++r)
  {
    threads.emplace_back([&, r] {
      const ProcessGroup mine = group.Group(r);
      verdicts[r] = AgreeOnFailure(mine, r == 1 ? "needs 9 GB" : "", "has too little memory");
      quiet[r] = AgreeOnFailure(mine, "", "has too little memory");
    });
  }
  for (std::thread& t : threads)
  {
    t.join();
  }
  EXPECT_EQ(verdicts[0], "another rank has too little memory");
  EXPECT_EQ(verdicts[1], "needs 9 GB");
  EXPECT_EQ(verdicts[2], "another rank has too little memory");
  EXPECT_EQ(quiet, std::vector<std::string>(3));
}

TEST(Distributed, TheFinalGatherSharedOverRanksGivesTheSerialAnswer)
{
  // Each rank gathers every other point (and element of the sweep, and record of the
  // irradiance cache) and the ranks sum: the points are the serial ones, and the rays cast
  // over all ranks are the serial count.
  const SceneMesh mesh = Room();
  SolverOptions options = Converged(1e-4);
  options.Gather.Rays = 16;
  options.Threads = 1;
  const RadiositySolver serial(mesh);
  const Solution one = SolveLights(serial, mesh, LightGrouping::OnePerLight(8), {}, SolutionMode::LightTagged, options);
  ASSERT_FALSE(one.PointRadiosity.empty());
  long long gathering = 0, plain = 0;
  const std::vector<Solution> many = SolveOnRanks(mesh, 2, options, nullptr, 8, &gathering);
  SolverOptions without = options;
  without.Gather.Rays = 0;
  SolveOnRanks(mesh, 2, without, nullptr, 8, &plain);
  EXPECT_GT(gathering, plain + 2) << "the ranks share the gather's points and sum them";
  for (int r = 0; r < 2; ++r)
  {
    EXPECT_LT(LargestDifference(many[r].PointRadiosity, one.PointRadiosity), 1e-7) << "rank " << r;
    EXPECT_LT(LargestDifference(many[r].Radiosity, one.Radiosity), 1e-7) << "rank " << r;
    EXPECT_EQ(many[r].GatherRays, one.GatherRays) << "rank " << r;
    EXPECT_EQ(many[r].GatherRecords, one.GatherRecords) << "rank " << r;
  }
  EXPECT_GT(one.GatherRecords, 0);
  EXPECT_LT(one.GatherRecords, one.GatherPoints) << "the cache shared no gather";
}
