// Elements lying face to face on another surface: the floor under a box's bottom. The
// answer is geometry's own, so it does not move with the scene.
#include "Geometry/FaceContact.h"
#include "SceneBuilders.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace radiosity;
using radiosity_test::AddGrid;
using radiosity_test::AllPolygons;

namespace
{
/// A 4 m floor of 0.5 m elements (facing up), a 1 m box bottom of 0.5 m elements on it
/// at (1..2, 1..2) facing down, and a panel 1 mm above the floor at (3..4, 3..4) facing
/// down, which touches nothing.
SceneMesh FloorWithBoxBottom()
{
  SceneMesh mesh;
  int patch = 0;
  const Vec3 X{ 1, 0, 0 }, Y{ 0, 1, 0 }, rho{ 0.5, 0.5, 0.5 };
  AddGrid(mesh, { 0, 0, 0 }, X * 4, Y * 4, 8, 8, rho, -1, patch);
  AddGrid(mesh, { 1, 1, 0 }, Y, X, 2, 2, rho, -1, patch);
  AddGrid(mesh, { 3, 3, 1e-3 }, Y, X, 2, 2, rho, -1, patch);
  return mesh;
}

/// `mesh` turned 37 degrees about a skew axis and moved `shift` along (1, -0.5, 0.3).
SceneMesh Turned(SceneMesh mesh, double shift)
{
  const Vec3 k = Normalized(Vec3{ 0.3, 0.8, 0.2 });
  const double a = 37 * M_PI / 180, c = std::cos(a), s = std::sin(a);
  for (Vec3& p : mesh.Points)
  {
    p = p * c + Cross(k, p) * s + k * (Dot(k, p) * (1 - c)) + Vec3{ 1, -0.5, 0.3 } * shift;
  }
  return mesh;
}
} // namespace

TEST(FaceContact, TheFloorUnderABoxBottomAndTheBottomAreFaceToFaceWhereverTheSceneLies)
{
  // Floor elements 18, 19, 26, 27 lie under the box's bottom (64..67), which lies on them;
  // the panel a millimetre up touches nothing.
  const std::vector<int> expected{ 18, 19, 26, 27, 64, 65, 66, 67 };
  for (const double shift : { 0.0, 1e3, 1e5 })
  {
    const SceneMesh mesh = shift == 0 ? FloorWithBoxBottom() : Turned(FloorWithBoxBottom(), shift);
    const SceneGeometry g(mesh);
    EXPECT_EQ(FaceToFace(mesh, g, AllPolygons(mesh), 1e-6), expected) << "moved " << shift;
  }
}

TEST(FaceContact, OneLargeCandidateAmongSmallOnesChangesNothing)
{
  // The grid's cells follow the median candidate: one floor-sized candidate made every
  // element visit every candidate.
  SceneMesh mesh = FloorWithBoxBottom();
  int patch = 100;
  AddGrid(mesh, { -10, -10, 5 }, Vec3{ 20, 0, 0 }, Vec3{ 0, 20, 0 }, 1, 1, { 0.5, 0.5, 0.5 }, -1, patch);
  const SceneGeometry g(mesh);
  EXPECT_EQ(FaceToFace(mesh, g, AllPolygons(mesh), 1e-6), (std::vector<int>{ 18, 19, 26, 27, 64, 65, 66, 67 }));
}
