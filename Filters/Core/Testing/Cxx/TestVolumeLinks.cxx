// The patch tree over a scene and the hierarchical links it makes: regions passed over
// because the shooter cannot see them, and far regions in view linked whole. Checked
// against progressive refinement (every element, every shot) on two rooms joined by a door.
#include "Solve/LightSolutions.h"
#include "Solve/PatchTree.h"
#include "SceneBuilders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace radiosity;

namespace
{
/// Adds the rectangle origin + [0,1]u + [0,1]v as an n x n grid facing along `normal`.
void Face(SceneMesh& mesh, const Vec3& origin, Vec3 u, Vec3 v, const Vec3& normal, int n, int light, int& patch)
{
  if (Dot(Cross(u, v), normal) < 0)
  {
    std::swap(u, v);
  }
  radiosity_test::AddGrid(mesh, origin, u, v, n, 2, { 0.7, 0.7, 0.7 }, light, patch);
}

/// Rooms A (x < 0.95) and B (x > 1.05) of a 2 x 1 x 1 box, a 0.1 thick wall between them
/// with a door 0.2 wide and 0.5 high; a lamp under A's ceiling. Light reaches B only through
/// the door, and the wall's sides and B's far walls stand well beyond the lamp's room.
SceneMesh TwoRooms()
{
  SceneMesh mesh;
  int patch = 0;
  const Vec3 X{ 1, 0, 0 }, Y{ 0, 1, 0 }, Z{ 0, 0, 1 };
  Face(mesh, {}, X * 2, Y, Z, 24, -1, patch);
  Face(mesh, Z, X * 2, Y, Z * -1, 24, -1, patch);
  Face(mesh, {}, X * 2, Z, Y, 24, -1, patch);
  Face(mesh, Y, X * 2, Z, Y * -1, 24, -1, patch);
  Face(mesh, {}, Y, Z, X, 12, -1, patch);
  Face(mesh, X * 2, Y, Z, X * -1, 12, -1, patch);
  const double pieces[3][4] = { { 0, 0.4, 0, 1 }, { 0.6, 1, 0, 1 }, { 0.4, 0.6, 0.5, 1 } };
  for (const auto& p : pieces)
  {
    for (double x : { 0.95, 1.05 })
    {
      Face(mesh, { x, p[0], p[2] }, Y * (p[1] - p[0]), Z * (p[3] - p[2]), X * (x < 1 ? -1.0 : 1.0), 6, -1, patch);
    }
  }
  Face(mesh, { 0.95, 0.4, 0 }, X * 0.1, Z * 0.5, Y, 2, -1, patch);
  Face(mesh, { 0.95, 0.6, 0 }, X * 0.1, Z * 0.5, Y * -1, 2, -1, patch);
  Face(mesh, { 0.95, 0.4, 0.5 }, X * 0.1, Y * 0.2, Z * -1, 2, -1, patch);
  Face(mesh, { 0.35, 0.4, 0.999 }, X * 0.2, Y * 0.2, Z * -1, 2, 0, patch);
  return mesh;
}

Solution SolveTwoRooms(const SceneMesh& mesh, SolverMethod method)
{
  SolverOptions o = radiosity_test::Converged(1e-3);
  o.SolverMethod = method;
  o.FormFactorSamples = 16;
  const RadiositySolver solver(mesh);
  EXPECT_TRUE(solver.Error().empty()) << solver.Error();
  return SolveLights(solver, mesh, LightGrouping::OnePerLight(1), {}, SolutionMode::LightTagged, o);
}

/// sum |a - b| A / sum b A over the elements with x in [lo, hi].
double MeanDifference(const SceneMesh& mesh, const Solution& a, const Solution& b, double lo, double hi)
{
  const SceneGeometry g(mesh);
  double diff = 0, sum = 0;
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    if (mesh.LightId[e] < 0 && g.Centroid[e].x >= lo && g.Centroid[e].x <= hi)
    {
      diff += std::fabs(a.Radiosity[e].x - b.Radiosity[e].x) * g.Area[e];
      sum += b.Radiosity[e].x * g.Area[e];
    }
  }
  return diff / sum;
}
} // namespace

TEST(VolumeLinks, TwoRoomsThroughADoorMatchProgressiveRefinement)
{
  const SceneMesh mesh = TwoRooms();
  const Solution linked = SolveTwoRooms(mesh, SolverMethod::Hierarchical);
  const Solution every = SolveTwoRooms(mesh, SolverMethod::ProgressiveRefinement);
  EXPECT_GT(linked.Statistics.VolumeLinks, 0);
  const double all = MeanDifference(mesh, linked, every, 0, 2);
  const double lit = MeanDifference(mesh, linked, every, 0, 0.95);
  const double beyond = MeanDifference(mesh, linked, every, 1.05, 2);
  std::printf("hierarchical vs progressive: %.2f %% in all, %.2f %% in the lamp's room, %.2f %% beyond the door; "
              "%lld volume links\n",
    100 * all, 100 * lit, 100 * beyond, linked.Statistics.VolumeLinks);
  EXPECT_LT(all, 0.01);
  EXPECT_LT(beyond, 0.03);
}

TEST(VolumeLinks, TreeIsTheSameUnderRotationScaleAndPlacement)
{
  const SceneMesh mesh = TwoRooms();
  SceneMesh moved = mesh;
  const double c = std::cos(0.7), s = std::sin(0.7);
  for (Vec3& p : moved.Points)
  {
    p = Vec3{ c * p.x - s * p.y, s * p.x + c * p.y, p.z } * 1000.0 + Vec3{ 2500, -40, 7 };
  }
  const SceneGeometry g(mesh), h(moved);
  const Visibility rays(mesh), movedRays(moved);
  const WorkerPool pool(1);
  const ShooterFormFactors f(mesh, g, rays, pool), k(moved, h, movedRays, pool);
  const PatchTree a(g, f), b(h, k);
  EXPECT_EQ(a.Patches(), b.Patches());
  ASSERT_EQ(a.Nodes().size(), b.Nodes().size());
  for (size_t n = 0; n < a.Nodes().size(); ++n)
  {
    EXPECT_EQ(a.Nodes()[n].Count, b.Nodes()[n].Count);
    EXPECT_NEAR(a.Nodes()[n].Radius * 1000, b.Nodes()[n].Radius, 1e-6 * b.Nodes()[n].Radius);
  }
}

TEST(VolumeLinks, EveryPatchIsInOneFrontierSubtree)
{
  const SceneMesh mesh = TwoRooms();
  const SceneGeometry g(mesh);
  const Visibility rays(mesh);
  const WorkerPool pool(1);
  const ShooterFormFactors f(mesh, g, rays, pool);
  const PatchTree tree(g, f, 8, 64);
  std::vector<int> seen(g.PatchElements.size(), 0);
  for (int n : tree.Frontier())
  {
    const PatchTree::Node& node = tree.Nodes()[n];
    for (int i = node.First; i < node.First + node.Count; ++i)
    {
      ++seen[tree.Patches()[i]];
    }
  }
  for (int count : seen)
  {
    ASSERT_EQ(count, 1);
  }
  EXPECT_GE(tree.Frontier().size(), 64u);
}
