// Transport never creates energy, and in a closed scene it loses none: the hard room
// (a 0.2 m lamp under the ceiling of a closed unit room, 0.5 m elements) where a point
// rule near the lamp once delivered 113.6 % of its power, and a closed room at rho = 0.999
// (with the ambient term asked for, and at the defaults).
#include "Solve/LightSolutions.h"
#include "Solve/SolverMethods.h"
#include "SceneBuilders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace radiosity;
using radiosity_test::AddGrid;
using radiosity_test::Box;
using radiosity_test::Converged;

namespace
{
SceneMesh LampRoom(double rho)
{
  SceneMesh mesh = Box(1.0, 2, 1, { rho, rho, rho }, [](int) { return -1; });
  int patch = 100;
  AddGrid(mesh, { 0.4, 0.4, 0.95 }, { 0, 0.2, 0 }, { 0.2, 0, 0 }, 1, 1, { rho, rho, rho }, 0, patch); // faces -z
  return mesh;
}

/// Power the surfaces reflect in total, from the output: sum of A (B - E).
double ReflectedPower(const SceneMesh& mesh, const Solution& s)
{
  const SceneGeometry g(mesh);
  double reflected = 0;
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    const double emitted = mesh.LightId[e] == 0 ? 1.0 : 0.0;
    reflected += (s.Radiosity[e].x - emitted) * g.Area[e];
  }
  return reflected;
}
} // namespace

TEST(Conservation, FirstShotNeverDeliversMoreThanItsPower)
{
  const SceneMesh mesh = LampRoom(0.5);
  const RadiositySolver solver(mesh);
  for (SolverMethod method : { SolverMethod::ProgressiveRefinement, SolverMethod::Hierarchical })
  {
    for (FormFactorMethod factors : { FormFactorMethod::Analytic, FormFactorMethod::Hemicube, FormFactorMethod::MonteCarlo })
    {
      if (method == SolverMethod::Hierarchical && factors != FormFactorMethod::Analytic)
      {
        continue;
      }
      SolverOptions options = Converged(0);
      options.SolverMethod = method;
      options.FormFactorMethod = factors;
      options.MaximumShots = 1;
      const Solution s = SolveLights(solver, mesh, LightGrouping::OnePerLight(1), {}, SolutionMode::LightTagged, options);
      const double lampPower = 3 * 0.04; // the statistics sum the three channels
      const double delivered = s.Statistics.ReceivedPower / lampPower;
      std::printf("method %d, factors %d: first shot delivers %.4f %% of the lamp's power\n", static_cast<int>(method),
        static_cast<int>(factors), 100 * delivered);
      EXPECT_LE(delivered, 1.0 + 1e-9);
      EXPECT_GT(delivered, 0.97);
    }
  }
}

TEST(Conservation, ClosedRoomAtRhoNearOneReachesTheClosedForm)
{
  // A closed unit room whose ceiling is the lamp (no back face anywhere to absorb light),
  // every surface reflecting 0.999: the surfaces reflect rho / (1 - rho) = 999 times the
  // lamp's power in all. The ambient term carries what is still unshot at the threshold.
  const double rho = 0.999;
  const SceneMesh mesh = Box(1.0, 4, 2, { rho, rho, rho }, [](int face) { return face == 1 ? 0 : -1; });
  const RadiositySolver solver(mesh);
  for (SolverMethod method : { SolverMethod::ProgressiveRefinement, SolverMethod::Hierarchical })
  {
    SolverOptions options = Converged(1e-3);
    options.SolverMethod = method;
    options.AmbientTerm = true;
    const Solution s = SolveLights(solver, mesh, LightGrouping::OnePerLight(1), {}, SolutionMode::LightTagged, options);
    const double got = ReflectedPower(mesh, s);
    std::printf("method %d: reflected %.2f x the lamp's power (closed form %.0f), %d shots\n", static_cast<int>(method),
      got, rho / (1 - rho), s.Statistics.Shots);
    EXPECT_NEAR(got / (rho / (1 - rho)), 1.0, 0.01);
  }
}

TEST(Conservation, ClosedRoomAtRhoOneHasNoFiniteSolutionAndSaysSo)
{
  // Every surface reflecting all the light of a closed room: the light never leaves, and a
  // shooting method ran to its shot cap. An opening, or a reflectance below 1, gives a sum.
  const auto lamp = [](int face) { return face == 1 ? 0 : -1; };
  const SceneMesh closed = Box(1.0, 4, 2, { 0.5, 1.0, 0.5 }, lamp);
  const RadiositySolver solver(closed);
  const std::string said = NoFiniteSolution(closed, solver.Geometry(), solver.Rays());
  EXPECT_NE(said.find("all of the green light and the scene is closed"), std::string::npos) << said;
  SceneMesh open = closed; // without the face at x = 1 (its 16 polygons are the last)
  open.Offsets.resize(open.Offsets.size() - 16);
  open.Connectivity.resize(open.Offsets.back());
  for (std::vector<int>* perPolygon : { &open.LightId, &open.PatchId })
  {
    perPolygon->resize(open.NumberOfPolygons());
  }
  open.Reflectance.resize(open.NumberOfPolygons());
  const RadiositySolver opened(open);
  EXPECT_EQ(NoFiniteSolution(open, opened.Geometry(), opened.Rays()), "");
  const SceneMesh below = Box(1.0, 4, 2, { 0.999, 0.999, 0.999 }, lamp);
  const RadiositySolver dimmer(below);
  EXPECT_EQ(NoFiniteSolution(below, dimmer.Geometry(), dimmer.Rays()), "");
}

TEST(Conservation, ClosedRoomAtRhoNearOneReachesTheClosedFormAtTheDefaults)
{
  // The same room with every option at its default: the solver's own shot cap stops each
  // shooting method long before the threshold (light makes ~7,000 sweeps), and what is
  // left goes into the ambient term, which the user is told. A cap the user sets keeps it
  // out. The clustered method solves the interreflection as one linear system and gets
  // there on its own.
  const double rho = 0.999;
  const SceneMesh mesh = Box(1.0, 4, 2, { rho, rho, rho }, [](int face) { return face == 1 ? 0 : -1; });
  const RadiositySolver solver(mesh);
  SolverOptions defaults;
  defaults.SolverMethod = SolverMethod::Clustered;
  const Solution linear = SolveLights(solver, mesh, LightGrouping::OnePerLight(1), {}, SolutionMode::LightTagged, defaults);
  EXPECT_TRUE(linear.Statistics.Converged);
  EXPECT_FALSE(linear.Statistics.AmbientAtCap);
  EXPECT_LT(linear.Statistics.Shots, 100);
  EXPECT_NEAR(ReflectedPower(mesh, linear) / (rho / (1 - rho)), 1.0, 0.01);
  for (SolverMethod method : { SolverMethod::ProgressiveRefinement, SolverMethod::Hierarchical })
  {
    SolverOptions options;
    options.SolverMethod = method;
    const Solution s = SolveLights(solver, mesh, LightGrouping::OnePerLight(1), {}, SolutionMode::LightTagged, options);
    const double got = ReflectedPower(mesh, s);
    std::printf("method %d: reflected %.2f x the lamp's power (closed form %.0f), %d shots\n", static_cast<int>(method),
      got, rho / (1 - rho), s.Statistics.Shots);
    EXPECT_FALSE(s.Statistics.Converged);
    EXPECT_TRUE(s.Statistics.AmbientAtCap);
    EXPECT_NEAR(got / (rho / (1 - rho)), 1.0, 0.01);
    options.MaximumShots = s.Statistics.ShotCap;
    const Solution capped = SolveLights(solver, mesh, LightGrouping::OnePerLight(1), {}, SolutionMode::LightTagged, options);
    EXPECT_FALSE(capped.Statistics.AmbientAtCap);
    EXPECT_LT(ReflectedPower(mesh, capped), 0.99 * got); // short of the closed form without it
  }
}

TEST(Conservation, LampRoomAtRhoNearOneNeverGains)
{
  // The lamp room at rho = 0.999 diverged (unshot 2e22 times its start). Its lamp's back
  // absorbs what reaches it, so there is no closed form, only bounds: unshot energy never
  // rises, and the surfaces reflect less than rho / (1 - rho) times the lamp's power.
  const double rho = 0.999;
  const SceneMesh mesh = LampRoom(rho);
  const RadiositySolver solver(mesh);
  for (SolverMethod method : { SolverMethod::ProgressiveRefinement, SolverMethod::Hierarchical })
  {
    SolverOptions options = Converged(1e-3);
    options.SolverMethod = method;
    const Solution s = SolveLights(solver, mesh, LightGrouping::OnePerLight(1), {}, SolutionMode::LightTagged, options);
    EXPECT_TRUE(s.Statistics.Converged);
    EXPECT_LT(ReflectedPower(mesh, s) / 0.04, rho / (1 - rho));
    const std::vector<double>& history = s.Statistics.RemainingHistory;
    for (size_t i = 1; i < history.size(); ++i)
    {
      ASSERT_LE(history[i], history[i - 1] * (1 + 1e-12)) << "unshot energy rose at shot " << i;
    }
  }
}

TEST(Conservation, EveryMethodOfTheTableRunsAsItselfAndLosesNoLight)
{
  // Each row of SolverMethodTable() (a new method is one more row): asked for by name it
  // runs, says so (Statistics.SolverMethod: the default names progressive refinement), converges,
  // and in the closed lamp room the surfaces absorb what the lamp emits, no more (a little
  // less: what reaches the lamp's back, which neither reflects nor absorbs, is lost), the
  // clustered method to its tolerance (below).
  const SceneMesh mesh = LampRoom(0.5);
  const RadiositySolver solver(mesh);
  for (const MethodEntry& entry : SolverMethodTable())
  {
    SolverOptions options = Converged(1e-6);
    options.SolverMethod = entry.Method;
    const Solution s = SolveLights(solver, mesh, LightGrouping::OnePerLight(1), {}, SolutionMode::LightTagged, options);
    const double absorbed = radiosity_test::AbsorbedPower(mesh, s) / (3 * 0.04); // three channels summed
    std::printf("%s: absorbed %.5f of the lamp's power\n", entry.Name, absorbed);
    EXPECT_EQ(s.Statistics.SolverMethod, entry.Method) << entry.Name;
    EXPECT_TRUE(s.Statistics.Converged) << entry.Name;
    // The clustered method scales each element's view of a closed scene to exactly one (its
    // furnace holds to 0.5 %): it may hand back, to that much, what the lamp's back takes.
    EXPECT_LE(absorbed, entry.Method == SolverMethod::Clustered ? 1.005 : 1.0 + 1e-6) << entry.Name;
    EXPECT_GT(absorbed, 0.95) << entry.Name;
  }
}
