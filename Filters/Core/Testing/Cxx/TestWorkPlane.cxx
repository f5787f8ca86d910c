// The work plane's grid (EN 12464-1's spacing, points at the cells' centres, quads between
// them) and which of its points stand in a room: over a floor, under a ceiling.
#include "Geometry/Scene.h"
#include "Geometry/Visibility.h"
#include "SceneBuilders.h"
#include "Solve/WorkPlane.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace radiosity;
using namespace radiosity_test;

namespace
{
/// Which points `PointsInRoom` keeps on `mesh`, a plane `height` over the box `bounds`.
std::vector<char> Kept(const SceneMesh& mesh, const double bounds[6], double height, bool ceiling, WorkPlaneGrid& grid)
{
  std::string error;
  grid = LayWorkPlane(bounds, 2, height, 0.0, 0.5, error);
  EXPECT_EQ(error, "");
  const SceneGeometry g(mesh);
  const Visibility rays(mesh);
  return PointsInRoom(grid, 2, height, ceiling, rays, g.Normal);
}

int Count(const std::vector<char>& keep)
{
  int n = 0;
  for (char k : keep)
  {
    n += k ? 1 : 0;
  }
  return n;
}
} // namespace

TEST(WorkPlane, TheGridTakesEn12464SpacingAndQuadsBetweenItsPoints)
{
  // p = 0.2 * 5^log10(d): 0.2 m at 1 m, 1 m at 10 m, 0.2 * 5^0.699 = 0.617 m at 5 m.
  EXPECT_NEAR(WorkPlaneSpacing(1), 0.2, 1e-12);
  EXPECT_NEAR(WorkPlaneSpacing(10), 1.0, 1e-12);
  EXPECT_NEAR(WorkPlaneSpacing(5), 0.2 * std::pow(5.0, std::log10(5.0)), 1e-12);
  const double bounds[6] = { 0, 4, 0, 3, 0, 2.5 };
  std::string error;
  const WorkPlaneGrid grid = LayWorkPlane(bounds, 2, 0.8, 0.5, 0, error);
  ASSERT_EQ(error, "");
  // 3 x 2 m inside the border, p = 0.2 * 5^log10(3) = 0.43 m: 7 x 5 cells.
  EXPECT_EQ(grid.Nu, 7);
  EXPECT_EQ(grid.Nv, 5);
  EXPECT_EQ(grid.Points.size(), 35u);
  EXPECT_EQ(grid.Quads.size(), 6u * 4u);
  EXPECT_NEAR(grid.Points[0].x, 0.5 + 3.0 / 14, 1e-12);
  EXPECT_NEAR(grid.Points[0].z, 0.8, 1e-12);
}

TEST(WorkPlane, OnlyPointsOverAFloorAndUnderACeilingStandInTheRoom)
{
  // A closed 4 m room; the box it is laid in runs 4 m further along x, where there is no
  // floor (a room's box that takes in an open hall or the air outside a sloping roof).
  const SceneMesh room = Box(4, 8, 2, { 0.5, 0.5, 0.5 }, [](int) { return -1; });
  const double wide[6] = { 0, 8, 0, 4, 0, 4 };
  WorkPlaneGrid grid;
  const std::vector<char> keep = Kept(room, wide, 0.8, true, grid);
  for (size_t p = 0; p < grid.Points.size(); ++p)
  {
    EXPECT_EQ(keep[p] != 0, grid.Points[p].x < 4) << "point " << p << " at x " << grid.Points[p].x;
  }
  EXPECT_EQ(Count(keep), 8 * 8);
  const WorkPlaneGrid kept = KeptPoints(grid, keep);
  EXPECT_EQ(kept.Points.size(), 64u);
  EXPECT_EQ(kept.Quads.size(), 7u * 7u); // only between points both kept
  // Laid 0.8 m over a floor 2 m higher than the room's (a gallery's box over the hall):
  // the floor lies 2.8 m down, no point stands on it.
  const double gallery[6] = { 0, 4, 0, 4, 2, 4 };
  EXPECT_EQ(Count(Kept(room, gallery, 0.8, true, grid)), 0);
  // A floor alone: the points stand over it, but under no ceiling.
  SceneMesh floor;
  int patch = 0;
  AddGrid(floor, { 0, 0, 0 }, { 4, 0, 0 }, { 0, 4, 0 }, 4, 2, { 0.5, 0.5, 0.5 }, -1, patch);
  const double box[6] = { 0, 4, 0, 4, 0, 3 };
  EXPECT_EQ(Count(Kept(floor, box, 0.8, false, grid)), 64);
  EXPECT_EQ(Count(Kept(floor, box, 0.8, true, grid)), 0);
  // Height 0 keeps every point (the plane is the floor).
  EXPECT_EQ(Count(Kept(room, wide, 0.0, true, grid)), 128);
  // Inside a solid (the same box facing out): its bottom faces down, its top up.
  SceneMesh solid = room;
  for (int e = 0; e < solid.NumberOfPolygons(); ++e)
  {
    std::reverse(solid.Connectivity.begin() + solid.Offsets[e], solid.Connectivity.begin() + solid.Offsets[e + 1]);
  }
  EXPECT_EQ(Count(Kept(solid, wide, 0.8, false, grid)), 0);
  EXPECT_EQ(Count(Kept(solid, wide, 0.8, true, grid)), 0);
}

TEST(WorkPlane, APointOnADeskStandsOnItAtAnyUpAxis)
{
  // A 4 m room with a desk top 0.8 m up over half of it, the plane at 0.8 m: the points over
  // the desk lie on it and stay (the desk is their floor, the ceiling above). With y up.
  SceneMesh room;
  int patch = 0;
  const Vec3 grey{ 0.5, 0.5, 0.5 };
  AddGrid(room, { 0, 0, 0 }, { 0, 0, 4 }, { 4, 0, 0 }, 4, 2, grey, -1, patch);   // floor y = 0, facing +y
  AddGrid(room, { 0, 4, 0 }, { 4, 0, 0 }, { 0, 0, 4 }, 4, 2, grey, -1, patch);   // ceiling y = 4, facing -y
  AddGrid(room, { 0, 0.8, 0 }, { 0, 0, 2 }, { 4, 0, 0 }, 4, 2, grey, -1, patch); // desk top, z < 2
  const SceneGeometry g(room);
  ASSERT_GT(g.Normal[0].y, 0.99);
  ASSERT_LT(g.Normal[16].y, -0.99);
  std::string error;
  const double box[6] = { 0, 4, 0, 4, 0, 4 };
  const WorkPlaneGrid grid = LayWorkPlane(box, 1, 0.8, 0.0, 0.5, error);
  ASSERT_EQ(error, "");
  const Visibility rays(room);
  EXPECT_EQ(Count(PointsInRoom(grid, 1, 0.8, true, rays, g.Normal)), 64);
}
