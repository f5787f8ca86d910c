// Finer elements near lamps (Mesh/LampGrading.h): where they are made, where not, that a
// graded quad's grid has no T-junctions, and that the counter counts what the mesher makes.
#include "Mesh/Mesher.h"
#include "Geometry/Polygon.h"

#include <gtest/gtest.h>

#include <map>
#include <utility>

using namespace radiosity;

namespace
{
/// A 4 x 4 floor facing up; a 0.2 m lamp 0.1 m over its middle facing down; a ceiling just
/// over the lamp facing down (behind it); a triangular wall standing on the floor 0.5 m
/// from the lamp, facing it. Polygon 1 is the lamp.
struct LampOverFloor
{
  std::vector<Vec3> Points = { { 0, 0, 0 }, { 0, 0, 4 }, { 4, 0, 4 }, { 4, 0, 0 }, // floor
    { 1.9, 0.1, 1.9 }, { 2.1, 0.1, 1.9 }, { 2.1, 0.1, 2.1 }, { 1.9, 0.1, 2.1 },      // lamp
    { 0, 0.12, 0 }, { 4, 0.12, 0 }, { 4, 0.12, 4 }, { 0, 0.12, 4 },                  // ceiling
    { 2.5, 0, 1 }, { 2.5, 0, 3 }, { 2.5, 1, 2 } };                                   // wall
  std::vector<int> Offsets = { 0, 4, 8, 12, 15 };
  std::vector<int> Connectivity = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14 };
  std::vector<int> Keys = { 0, 1, 2, 3 };

  MesherOptions Options(double grading) const
  {
    MesherOptions o;
    o.PatchSize = 1;
    o.ElementSize = 0.25;
    o.Lamps = { 0, 1, 0, 0 };
    o.LampGrading = grading;
    return o;
  }
};

std::vector<Vec3> Loop(const MeshedPolygons& m, size_t e)
{
  std::vector<Vec3> loop;
  for (int k = m.Offsets[e]; k < m.Offsets[e + 1]; ++k)
  {
    loop.push_back(m.Points[m.Connectivity[k]]);
  }
  return loop;
}

double LongestEdge(const std::vector<Vec3>& loop)
{
  double longest = 0;
  for (size_t k = 0; k < loop.size(); ++k)
  {
    longest = std::max(longest, Norm(loop[(k + 1) % loop.size()] - loop[k]));
  }
  return longest;
}

/// The longest edge of the source polygon's element whose centroid is nearest `p`.
double EdgeNear(const MeshedPolygons& m, int source, const Vec3& p)
{
  double best = 1e300, edge = 0;
  for (size_t e = 0; e + 1 < m.Offsets.size(); ++e)
  {
    const std::vector<Vec3> loop = Loop(m, e);
    const double d = Norm(PolygonCentroid(loop.data(), static_cast<int>(loop.size())) - p);
    if (m.SourcePolygon[e] == source && d < best)
    {
      best = d;
      edge = LongestEdge(loop);
    }
  }
  return edge;
}

int ElementsOf(const MeshedPolygons& m, int source)
{
  return static_cast<int>(std::count(m.SourcePolygon.begin(), m.SourcePolygon.end(), source));
}
} // namespace

TEST(LampGrading, FloorUnderALampIsFinerByItAndNowhereElse)
{
  const LampOverFloor scene;
  MeshedPolygons uniform, graded;
  ASSERT_EQ(MeshPolygons(scene.Points, scene.Offsets, scene.Connectivity, scene.Keys, scene.Options(0), uniform), "");
  ASSERT_EQ(MeshPolygons(scene.Points, scene.Offsets, scene.Connectivity, scene.Keys, scene.Options(0.35), graded), "");
  EXPECT_EQ(ElementsOf(uniform, 0), 256);
  // The two middle patch columns and rows (under the lamp's rim) take a quarter of the
  // element size, the outer ones (0.86 m from the rim: 0.3 m wanted) keep it: 4 + 16 + 16
  // + 4 lines each way.
  EXPECT_EQ(ElementsOf(graded, 0), 40 * 40);
  EXPECT_NEAR(EdgeNear(graded, 0, { 2, 0, 2 }), 0.0625, 1e-9);
  EXPECT_NEAR(EdgeNear(graded, 0, { 0.1, 0, 0.1 }), 0.25, 1e-9);
  // The ceiling is behind the lamp and the lamp on its own plane: neither is graded.
  EXPECT_EQ(ElementsOf(graded, 2), ElementsOf(uniform, 2));
  EXPECT_EQ(ElementsOf(graded, 1), ElementsOf(uniform, 1));
  // The wall 0.5 m off, 0.36 m from the lamp's rim, facing the lamp, is (its whole
  // lattice: 0.126 m wanted, eight elements a patch edge instead of four).
  EXPECT_EQ(ElementsOf(uniform, 3), 64);
  EXPECT_EQ(ElementsOf(graded, 3), 256);
  double area = 0;
  for (size_t e = 0; e + 1 < graded.Offsets.size(); ++e)
  {
    const std::vector<Vec3> loop = Loop(graded, e);
    area += graded.SourcePolygon[e] == 0 ? PolygonArea(loop.data(), static_cast<int>(loop.size())) : 0.0;
  }
  EXPECT_NEAR(area, 16.0, 1e-9);
}

TEST(LampGrading, AGradedQuadHasNoTJunctions)
{
  const LampOverFloor scene;
  MeshedPolygons graded;
  std::vector<int> offsets = { 0, 4, 8 }, connectivity = { 0, 1, 2, 3, 4, 5, 6, 7 };
  MesherOptions o = scene.Options(0.35);
  o.Lamps = { 0, 1 };
  ASSERT_EQ(MeshPolygons(scene.Points, offsets, connectivity, { 0, 1 }, o, graded), "");
  // Every edge inside the floor is shared by two elements: only the 4 x 40 outline's edges
  // are used once (a T-junction would leave a long edge and two short ones unshared).
  std::map<std::pair<int, int>, int> uses;
  for (size_t e = 0; e + 1 < graded.Offsets.size(); ++e)
  {
    for (int k = graded.Offsets[e]; k < graded.Offsets[e + 1] && graded.SourcePolygon[e] == 0; ++k)
    {
      const int a = graded.Connectivity[k];
      const int b = graded.Connectivity[k + 1 < graded.Offsets[e + 1] ? k + 1 : graded.Offsets[e]];
      ++uses[std::minmax(a, b)];
    }
  }
  int once = 0;
  for (const auto& edge : uses)
  {
    once += edge.second == 1 ? 1 : 0;
  }
  EXPECT_EQ(once, 4 * 40);
}

TEST(LampGrading, TheCounterCountsTheGradedMesh)
{
  const LampOverFloor scene;
  for (double grading : { 0.0, 0.2, 0.35, 1.0 })
  {
    const MesherOptions o = scene.Options(grading);
    MeshedPolygons m;
    ASSERT_EQ(MeshPolygons(scene.Points, scene.Offsets, scene.Connectivity, scene.Keys, o, m), "");
    const ElementCounter count(scene.Points, scene.Offsets, scene.Connectivity, scene.Keys, o);
    EXPECT_EQ(count(o.PatchSize, o.ElementSize), static_cast<double>(m.SourcePolygon.size())) << "grading " << grading;
  }
}

TEST(LampGrading, ScaleDoesNotChangeTheMesh)
{
  const LampOverFloor scene;
  LampOverFloor scaled;
  for (Vec3& p : scaled.Points)
  {
    p = p * 1000.0 + Vec3{ 5e4, -2e3, 7e4 }; // millimetres, far from the origin
  }
  MesherOptions o = scaled.Options(0.35);
  o.PatchSize *= 1000, o.ElementSize *= 1000;
  MeshedPolygons metres, millimetres;
  ASSERT_EQ(MeshPolygons(scene.Points, scene.Offsets, scene.Connectivity, scene.Keys, scene.Options(0.35), metres), "");
  ASSERT_EQ(MeshPolygons(scaled.Points, scaled.Offsets, scaled.Connectivity, scaled.Keys, o, millimetres), "");
  EXPECT_EQ(metres.SourcePolygon, millimetres.SourcePolygon);
}

TEST(LampGrading, LampsThemselvesAreNotGraded)
{
  // A floor that emits too (a furnace's walls are all lamps: each would make the others fine).
  const LampOverFloor scene;
  MesherOptions o = scene.Options(0.35);
  o.Lamps = { 1, 1, 0, 0 };
  MeshedPolygons m;
  ASSERT_EQ(MeshPolygons(scene.Points, scene.Offsets, scene.Connectivity, scene.Keys, o, m), "");
  EXPECT_EQ(ElementsOf(m, 0), 256);
  EXPECT_GE(ElementsOf(m, 3), 256); // the wall still is (by both)
  const ElementCounter count(scene.Points, scene.Offsets, scene.Connectivity, scene.Keys, o);
  EXPECT_EQ(count(o.PatchSize, o.ElementSize), static_cast<double>(m.SourcePolygon.size()));
}

TEST(LampGrading, ABudgetLeavesTheGradingOutFirst)
{
  const LampOverFloor scene;
  MesherOptions o = scene.Options(0.35);
  MeshedPolygons uniform;
  ASSERT_EQ(MeshPolygons(scene.Points, scene.Offsets, scene.Connectivity, scene.Keys, scene.Options(0), uniform), "");
  o.ElementBudget = static_cast<double>(uniform.SourcePolygon.size());
  std::string said;
  o.Warning = [&](const std::string& message) { said += message; };
  MeshedPolygons m;
  ASSERT_EQ(MeshPolygons(scene.Points, scene.Offsets, scene.Connectivity, scene.Keys, o, m), "");
  EXPECT_EQ(m.SourcePolygon.size(), uniform.SourcePolygon.size());
  EXPECT_EQ(m.ElementSize, 0.25);
  EXPECT_NE(said.find("LampGrading left out"), std::string::npos) << said;
}

TEST(LampGrading, ALuminaireGradesWhatItLightsAsALampPolygonDoes)
{
  // The same floor, ceiling and wall with the lamp polygon replaced by a luminaire at its
  // centre: lighting downward only (normal down), the floor and the wall are graded as by
  // the lamp and the ceiling behind it is not; lighting every way, the ceiling is too.
  const LampOverFloor scene;
  std::vector<int> offsets = { 0, 4, 8, 11 }, connectivity = { 0, 1, 2, 3, 8, 9, 10, 11, 12, 13, 14 };
  MesherOptions o = scene.Options(0.35);
  o.Lamps = { 0, 0, 0 };
  LampSpot luminaire;
  luminaire.Centre = { 2, 0.1, 2 };
  luminaire.Normal = { 0, -1, 0 };
  o.PointLamps = { luminaire };
  MeshedPolygons down, everyWay, none;
  ASSERT_EQ(MeshPolygons(scene.Points, offsets, connectivity, { 0, 1, 2 }, o, down), "");
  EXPECT_NEAR(EdgeNear(down, 0, { 2, 0, 2 }), 0.0625, 1e-9);
  EXPECT_NEAR(EdgeNear(down, 0, { 0.1, 0, 0.1 }), 0.25, 1e-9);
  EXPECT_EQ(ElementsOf(down, 1), 256); // the ceiling behind it: 16 x 16 as ungraded
  EXPECT_GT(ElementsOf(down, 2), 64);  // the wall it faces
  o.PointLamps[0].Normal = {};
  ASSERT_EQ(MeshPolygons(scene.Points, offsets, connectivity, { 0, 1, 2 }, o, everyWay), "");
  EXPECT_GT(ElementsOf(everyWay, 1), 256);
  // The counter counts it exactly, and without grading there is none.
  const ElementCounter count(scene.Points, offsets, connectivity, { 0, 1, 2 }, o);
  EXPECT_EQ(count(o.PatchSize, o.ElementSize), static_cast<double>(everyWay.SourcePolygon.size()));
  o.LampGrading = 0;
  ASSERT_EQ(MeshPolygons(scene.Points, offsets, connectivity, { 0, 1, 2 }, o, none), "");
  EXPECT_EQ(ElementsOf(none, 0), 256);
}

TEST(LampGrading, AShadowsEdgeGradesThePatchesItCrosses)
{
  // A 4 x 4 floor, a 0.2 m lamp 2 m over (1, 1) facing down, and a 0.5 m table top 0.5 m
  // over the floor at x, z in [2.4, 2.9]: its shadow falls on [2.87, 3.53] in both, across
  // the floor patches of x and z in [2, 4]. The lamp is too far to grade the floor by its
  // distance (0.35 * 2 m is more than the element size): only the shadow's edge does.
  const std::vector<Vec3> points = { { 0, 0, 0 }, { 0, 0, 4 }, { 4, 0, 4 }, { 4, 0, 0 }, // floor
    { 0.9, 2, 0.9 }, { 1.1, 2, 0.9 }, { 1.1, 2, 1.1 }, { 0.9, 2, 1.1 },                   // lamp
    { 2.4, 0.5, 2.4 }, { 2.4, 0.5, 2.9 }, { 2.9, 0.5, 2.9 }, { 2.9, 0.5, 2.4 } };         // table top
  const std::vector<int> offsets = { 0, 4, 8, 12 }, connectivity = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11 };
  MesherOptions o;
  o.PatchSize = 1;
  o.ElementSize = 0.25;
  o.Lamps = { 0, 1, 0 };
  o.LampGrading = 0.35;
  o.ShadowGrading = 0.5;
  MeshedPolygons shadowed, plain, unshadowed;
  ASSERT_EQ(MeshPolygons(points, offsets, connectivity, { 0, 1, 2 }, o, shadowed), "");
  // On the shadow's edge, and over the patches it crosses: half the element size.
  EXPECT_NEAR(EdgeNear(shadowed, 0, { 2.9, 0, 3.2 }), 0.125, 1e-9);
  EXPECT_NEAR(EdgeNear(shadowed, 0, { 3.9, 0, 3.9 }), 0.125, 1e-9);
  // Far from it, and in the lit patches' own rows and columns, the element size.
  EXPECT_NEAR(EdgeNear(shadowed, 0, { 0.1, 0, 0.1 }), 0.25, 1e-9);
  EXPECT_NEAR(EdgeNear(shadowed, 0, { 1.5, 0, 1.5 }), 0.25, 1e-9);
  // The table top sees the lamp from every point: not graded.
  EXPECT_EQ(ElementsOf(shadowed, 2), 4);
  // The counter counts it; without ShadowGrading, or without LampGrading, none.
  const ElementCounter count(points, offsets, connectivity, { 0, 1, 2 }, o);
  EXPECT_EQ(count(o.PatchSize, o.ElementSize), static_cast<double>(shadowed.SourcePolygon.size()));
  // Two of four patch columns and rows at half the size: (4 + 4 + 8 + 8) lines each way.
  EXPECT_EQ(ElementsOf(shadowed, 0), 24 * 24);
  // The same in millimetres far from the origin.
  std::vector<Vec3> far = points;
  for (Vec3& p : far)
  {
    p = p * 1000.0 + Vec3{ 5e4, -2e3, 7e4 };
  }
  MesherOptions mm = o;
  mm.PatchSize *= 1000, mm.ElementSize *= 1000;
  MeshedPolygons millimetres;
  ASSERT_EQ(MeshPolygons(far, offsets, connectivity, { 0, 1, 2 }, mm, millimetres), "");
  EXPECT_EQ(millimetres.SourcePolygon, shadowed.SourcePolygon);
  o.ShadowGrading = 0;
  ASSERT_EQ(MeshPolygons(points, offsets, connectivity, { 0, 1, 2 }, o, unshadowed), "");
  EXPECT_EQ(ElementsOf(unshadowed, 0), 256);
  o.ShadowGrading = 0.5;
  o.LampGrading = 0;
  ASSERT_EQ(MeshPolygons(points, offsets, connectivity, { 0, 1, 2 }, o, plain), "");
  EXPECT_EQ(ElementsOf(plain, 0), 256);
}
