// Auto's cost model: the near pairs it counts before choosing a method.
#include "CurvedRoom.h"
#include "SceneBuilders.h"
#include "Solve/MethodCost.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace radiosity;

namespace
{
double Radius(const SceneMesh& mesh, const SceneGeometry& g, int e)
{
  double r = 0;
  for (int i = 0; i < mesh.PolygonSize(e); ++i)
  {
    r = std::max(r, Norm(mesh.Points[mesh.Polygon(e)[i]] - g.Centroid[e]));
  }
  return r;
}

/// Every ordered pair checked, no grid: closer than `separation` times the radii, each
/// rising in front of the other's plane (a tilted one by its radius, a parallel one by its
/// centroid).
double BruteForceNearPairs(const SceneMesh& mesh, double separation)
{
  const SceneGeometry g(mesh);
  const int n = mesh.NumberOfPolygons();
  std::vector<double> r(n);
  for (int e = 0; e < n; ++e)
  {
    r[e] = Radius(mesh, g, e);
  }
  auto inFront = [&](int a, int b) {
    const bool parallel = std::abs(Dot(g.Normal[a], g.Normal[b])) > 1 - 1e-9;
    return Dot(g.Centroid[b] - g.Centroid[a], g.Normal[a]) + (parallel ? 0.0 : r[b]) > 1e-9 * (r[a] + r[b]);
  };
  double pairs = 0;
  for (int a = 0; a < n; ++a)
  {
    for (int b = 0; b < n; ++b)
    {
      const bool near = a != b && Norm(g.Centroid[b] - g.Centroid[a]) <= separation * (r[a] + r[b]);
      pairs += near && inFront(a, b) && inFront(b, a) ? 1 : 0;
    }
  }
  return pairs;
}

SceneMesh SphereRoom(int triangles)
{
  SceneMesh mesh;
  EXPECT_EQ(radiosity_scenes::MeshByMaterial(radiosity_scenes::CurvedRoom(1, 1, triangles), 0.5, 0.25, 30, mesh), "");
  return mesh;
}
} // namespace

TEST(MethodCost, NearPairsOfASmallSceneAreEveryPairCounted)
{
  // Under 4,000 elements every element is sampled: the grid must find exactly the pairs
  // that checking all of them finds.
  const SceneMesh box = radiosity_test::Box(2.0, 20, 4, { 0.5, 0.5, 0.5 }, [](int) { return -1; });
  const double counted = BruteForceNearPairs(box, 4.0);
  EXPECT_GT(counted, 10000);
  EXPECT_EQ(EstimateNearPairs(box, SceneGeometry(box), 4.0), counted);
  EXPECT_EQ(EstimateNearPairs(box, SceneGeometry(box), 8.0), BruteForceNearPairs(box, 8.0));
}

TEST(MethodCost, NearPairsOfALargerSceneAreEstimatedFromASample)
{
  const SceneMesh room = SphereRoom(13000);
  ASSERT_GT(room.NumberOfPolygons(), 8000);
  const double counted = BruteForceNearPairs(room, 4.0);
  EXPECT_NEAR(EstimateNearPairs(room, SceneGeometry(room), 4.0), counted, 0.05 * counted);
}

TEST(MethodCost, NearPairsDoNotDependOnPlacement)
{
  const SceneMesh box = radiosity_test::Box(2.0, 20, 4, { 0.5, 0.5, 0.5 }, [](int) { return -1; });
  SceneMesh moved = box;
  const double c = std::cos(0.6), s = std::sin(0.6);
  for (Vec3& p : moved.Points)
  {
    p = Vec3{ c * p.x - s * p.z, p.y, s * p.x + c * p.z } + Vec3{ 1e4, -3e3, 5e3 };
  }
  EXPECT_EQ(EstimateNearPairs(moved, SceneGeometry(moved), 4.0), EstimateNearPairs(box, SceneGeometry(box), 4.0));
}
