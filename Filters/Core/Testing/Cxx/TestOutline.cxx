// A meshed lamp's outline: interior edges cancel, T-junctions split, straight runs join,
// and Lambert's formula over it equals the closed form for the whole square
// (shared/REFERENCES.md: a point centred 1 m under a unit square, F = 0.2394565).
#include "Geometry/FormFactor.h"
#include "Geometry/Outline.h"
#include "SceneBuilders.h"

#include <gtest/gtest.h>

using radiosity::SceneMesh;
using radiosity::Vec3;
using radiosity_test::AddGrid;
using radiosity_test::AllPolygons;

namespace
{
/// A unit square at z = 1 facing down, meshed n x n.
SceneMesh MeshedLamp(int n)
{
  SceneMesh mesh;
  int patch = 0;
  AddGrid(mesh, { -0.5, 0.5, 1 }, { 1, 0, 0 }, { 0, -1, 0 }, n, n, { 0, 0, 0 }, 0, patch);
  return mesh;
}

double FactorUnder(const std::vector<Vec3>& outline)
{
  return radiosity::EdgeSetFormFactor({ 0, 0, 0 }, { 0, 0, 1 }, outline.data(), static_cast<int>(outline.size() / 2));
}
} // namespace

TEST(Outline, MeshedSquareIsFourSegments)
{
  for (int n : { 1, 3, 16 })
  {
    const SceneMesh lamp = MeshedLamp(n);
    const std::vector<Vec3> outline = radiosity::PolygonSetOutline(lamp, AllPolygons(lamp));
    EXPECT_EQ(outline.size(), 8u) << n << " x " << n << " elements";
    EXPECT_NEAR(FactorUnder(outline), 0.2394565, 1e-7) << n;
  }
}

TEST(Outline, TJunctionStillCloses)
{
  // Two elements side by side; the left one cut in two across the shared edge's length, so
  // the right one's edge runs through a point the left pieces have and it does not.
  SceneMesh mesh;
  mesh.Points = { { -0.5, 0.5, 1 }, { 0, 0.5, 1 }, { 0.5, 0.5, 1 }, { -0.5, -0.5, 1 }, { 0, -0.5, 1 },
    { 0.5, -0.5, 1 }, { -0.5, 0, 1 }, { 0, 0, 1 } };
  for (const std::vector<int>& polygon : { std::vector<int>{ 0, 1, 7, 6 }, std::vector<int>{ 6, 7, 4, 3 },
         std::vector<int>{ 1, 2, 5, 4 } })
  {
    mesh.AddPolygon(polygon);
    mesh.Reflectance.push_back({ 0, 0, 0 });
    mesh.LightId.push_back(0);
    mesh.PatchId.push_back(0);
  }
  const std::vector<Vec3> outline = radiosity::PolygonSetOutline(mesh, AllPolygons(mesh));
  EXPECT_EQ(outline.size(), 8u);
  EXPECT_NEAR(FactorUnder(outline), 0.2394565, 1e-7);
}

TEST(Outline, TwoPiecesKeepBothLoops)
{
  SceneMesh mesh = MeshedLamp(2);
  int patch = 1;
  AddGrid(mesh, { 2, 0.5, 1 }, { 1, 0, 0 }, { 0, -1, 0 }, 2, 2, { 0, 0, 0 }, 0, patch);
  const std::vector<Vec3> outline = radiosity::PolygonSetOutline(mesh, AllPolygons(mesh));
  EXPECT_EQ(outline.size(), 16u);
  std::vector<Vec3> scratch;
  const std::vector<Vec3> second = { { 2, 0.5, 1 }, { 3, 0.5, 1 }, { 3, -0.5, 1 }, { 2, -0.5, 1 } };
  const double expected =
    0.2394565 + radiosity::PointToPolygonFormFactor({ 0, 0, 0 }, { 0, 0, 1 }, second.data(), 4, scratch);
  EXPECT_NEAR(FactorUnder(outline), expected, 1e-7);
}
