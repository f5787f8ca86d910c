#include "Mesh/ContactCuts.h"
#include "Mesh/Mesher.h"
#include "Geometry/Polygon.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace radiosity;

namespace
{
/// A 4 x 3 floor, a wall standing on it across its width at x = `wall`, and one of the
/// room's walls along its border at x = 0.
struct FloorAndWalls
{
  std::vector<Vec3> Points;
  std::vector<int> Offsets{ 0 };
  std::vector<int> Connectivity;

  explicit FloorAndWalls(double wall)
  {
    Add({ { 0, 0, 0 }, { 4, 0, 0 }, { 4, 3, 0 }, { 0, 3, 0 } });
    Add({ { wall, 0, 0 }, { wall, 0, 2 }, { wall, 3, 2 }, { wall, 3, 0 } });
    Add({ { 0, 0, 0 }, { 0, 3, 0 }, { 0, 3, 2 }, { 0, 0, 2 } });
  }

  void Add(const std::vector<Vec3>& loop)
  {
    for (const Vec3& p : loop)
    {
      Connectivity.push_back(static_cast<int>(Points.size()));
      Points.push_back(p);
    }
    Offsets.push_back(static_cast<int>(Connectivity.size()));
  }

  PolygonArrays Arrays() const { return { Points, Offsets, Connectivity }; }
};

/// The mesher's cutting over a list of elements (corners flattened, `sides` and `patch`
/// per element): each element's parts replace it, keeping its patch. Returns the number
/// of elements added.
int CutAlongContacts(const std::vector<ContactSegment>& segments, const Vec3& normal, double tolerance,
  std::vector<Vec3>& corners, std::vector<int>& sides, std::vector<int>& patch)
{
  const ContactCutter cutter(segments, normal, tolerance);
  const size_t before = sides.size();
  std::vector<Vec3> nextCorners;
  std::vector<int> nextSides, nextPatch;
  std::vector<std::vector<Vec3>> parts;
  size_t first = 0;
  for (size_t e = 0; e < before; first += sides[e], ++e)
  {
    if (cutter.Cut(corners.data() + first, sides[e], parts) == 0)
    {
      parts.assign(1, std::vector<Vec3>(corners.begin() + first, corners.begin() + first + sides[e]));
    }
    for (const std::vector<Vec3>& part : parts)
    {
      nextCorners.insert(nextCorners.end(), part.begin(), part.end());
      nextSides.push_back(static_cast<int>(part.size()));
      nextPatch.push_back(patch[e]);
    }
  }
  corners.swap(nextCorners);
  sides.swap(nextSides);
  patch.swap(nextPatch);
  return static_cast<int>(sides.size() - before);
}

double Area(const std::vector<Vec3>& corners, const std::vector<int>& sides)
{
  double area = 0;
  size_t first = 0;
  for (int n : sides)
  {
    area += PolygonArea(corners.data() + first, n);
    first += n;
  }
  return area;
}
} // namespace

TEST(ContactCuts, AWallStandingInsideAFloorIsItsContactAndTheFloorsBorderIsNot)
{
  const FloorAndWalls scene(1.8);
  const std::vector<std::vector<ContactSegment>> contacts = FindContacts(scene.Arrays(), scene.Arrays(), 1e-6);
  ASSERT_EQ(contacts.size(), 3u);
  ASSERT_EQ(contacts[0].size(), 1u); // the partition's foot; the border wall's foot is on the outline
  EXPECT_NEAR(contacts[0][0].A.x, 1.8, 1e-12);
  EXPECT_NEAR(contacts[0][0].B.x, 1.8, 1e-12);
  EXPECT_NEAR(std::fabs(contacts[0][0].B.y - contacts[0][0].A.y), 3.0, 1e-12);
  EXPECT_TRUE(contacts[1].empty()); // nothing stands on the walls
  EXPECT_TRUE(contacts[2].empty());
}

TEST(ContactCuts, AWallWithinTheToleranceStandsOnTheFloorAndOneAboveItDoesNot)
{
  for (double gap : { 0.5e-6, 2e-6, 1e-3 })
  {
    FloorAndWalls scene(1.8);
    for (int k = scene.Offsets[1]; k < scene.Offsets[2]; ++k)
    {
      scene.Points[scene.Connectivity[k]].z += gap; // light passes under a wall that floats
    }
    EXPECT_EQ(FindContacts(scene.Arrays(), scene.Arrays(), 1e-6)[0].size(), gap < 1e-6 ? 1u : 0u) << "gap " << gap;
  }
}

TEST(ContactCuts, OnlySurfacesInFrontStand)
{
  // The same wall hanging below the floor (the storey beneath a slab drawn as one face)
  // touches the floor's plane from behind: no contact.
  FloorAndWalls scene(1.8);
  for (int k = scene.Offsets[1]; k < scene.Offsets[2]; ++k)
  {
    scene.Points[scene.Connectivity[k]].z *= -1;
  }
  EXPECT_TRUE(FindContacts(scene.Arrays(), scene.Arrays(), 1e-6)[0].empty());
}

TEST(ContactCuts, ElementsAcrossTheContactAreSplitAndTheAreaIsKept)
{
  // A 4 x 1 strip of 1 x 1 elements; the contact runs across it at x = 1.3, and along the
  // border between two elements at x = 3 (no cut there: it would leave nothing on one side).
  std::vector<Vec3> corners;
  std::vector<int> sides, patch;
  for (int i = 0; i < 4; ++i)
  {
    const double x = i;
    corners.insert(corners.end(), { { x, 0, 0 }, { x + 1, 0, 0 }, { x + 1, 1, 0 }, { x, 1, 0 } });
    sides.push_back(4);
    patch.push_back(i / 2);
  }
  const std::vector<ContactSegment> contacts{ { { 1.3, -1, 0 }, { 1.3, 2, 0 } }, { { 3, 0, 0 }, { 3, 1, 0 } } };
  EXPECT_EQ(CutAlongContacts(contacts, { 0, 0, 1 }, 1e-9, corners, sides, patch), 1);
  ASSERT_EQ(sides.size(), 5u);
  EXPECT_NEAR(Area(corners, sides), 4.0, 1e-12);
  size_t first = 0;
  for (size_t e = 0; e < sides.size(); first += sides[e], ++e)
  {
    double lo = 1e9, hi = -1e9;
    for (int v = 0; v < sides[e]; ++v)
    {
      lo = std::min(lo, corners[first + v].x);
      hi = std::max(hi, corners[first + v].x);
    }
    EXPECT_FALSE(lo < 1.3 - 1e-12 && hi > 1.3 + 1e-12) << "element " << e << " still spans the contact";
  }
  EXPECT_EQ(std::count(patch.begin(), patch.end(), 0), 3); // the parts keep their patch
}

TEST(ContactCuts, ASegmentEndingInsideAnElementCutsOnlyTheElementsItReaches)
{
  std::vector<Vec3> corners;
  std::vector<int> sides, patch;
  for (int i = 0; i < 4; ++i)
  {
    const double y = i;
    corners.insert(corners.end(), { { 0, y, 0 }, { 1, y, 0 }, { 1, y + 1, 0 }, { 0, y + 1, 0 } });
    sides.push_back(4);
    patch.push_back(0);
  }
  // A box's side 0.5 m long standing at x = 0.4 from y = 0.2: it reaches the first element only.
  const std::vector<ContactSegment> contacts{ { { 0.4, 0.2, 0 }, { 0.4, 0.7, 0 } } };
  EXPECT_EQ(CutAlongContacts(contacts, { 0, 0, 1 }, 1e-9, corners, sides, patch), 1);
  EXPECT_NEAR(Area(corners, sides), 4.0, 1e-12);
  // The first element's two parts come first, 0.4 and 0.6 wide; the others are as they were.
  ASSERT_EQ(sides.size(), 5u);
  EXPECT_NEAR(PolygonArea(corners.data(), sides[0]), 0.4, 1e-12);
  EXPECT_NEAR(PolygonArea(corners.data() + sides[0], sides[1]), 0.6, 1e-12);
  size_t first = static_cast<size_t>(sides[0] + sides[1]);
  for (size_t e = 2; e < sides.size(); first += sides[e], ++e)
  {
    EXPECT_EQ(sides[e], 4);
    EXPECT_NEAR(corners[first].y, static_cast<double>(e - 1), 1e-12) << "element " << e;
  }
}

TEST(ContactCuts, TheMesherCutsTheFloorWhereTheWallStandsOffTheElementGrid)
{
  for (double wall : { 1.8, 2.0 })
  {
    const FloorAndWalls scene(wall);
    MesherOptions o;
    o.PatchSize = 1.0;
    o.ElementSize = 0.5;
    MeshedPolygons m;
    ASSERT_EQ(MeshPolygons(scene.Points, scene.Offsets, scene.Connectivity, { 0, 0, 0 }, o, m), "");
    int straddling = 0, floor = 0;
    for (size_t e = 0; e + 1 < m.Offsets.size(); ++e)
    {
      double lo = 1e9, hi = -1e9, z = 0;
      for (int k = m.Offsets[e]; k < m.Offsets[e + 1]; ++k)
      {
        lo = std::min(lo, m.Points[m.Connectivity[k]].x);
        hi = std::max(hi, m.Points[m.Connectivity[k]].x);
        z = std::max(z, m.Points[m.Connectivity[k]].z);
      }
      floor += z == 0 ? 1 : 0;
      straddling += z == 0 && lo < wall - 1e-9 && hi > wall + 1e-9 ? 1 : 0;
    }
    EXPECT_EQ(straddling, 0) << "wall at " << wall;
    // 8 x 6 floor elements; off the grid the column the wall stands in is split in two.
    EXPECT_EQ(floor, wall == 2.0 ? 48 : 54) << "wall at " << wall;
    EXPECT_EQ(CountElements(scene.Points, scene.Offsets, scene.Connectivity, 1.0, 0.5),
      static_cast<double>(m.SourcePolygon.size()))
      << "the count before meshing includes the cuts";
  }
}

namespace
{
/// Elements of `m` on the plane z = 0 along the segment from `a` for `length` along `d`
/// (in that plane) whose corners lie on both sides of it, farther than `tolerance`.
int Straddling(const MeshedPolygons& m, const Vec3& a, const Vec3& d, double length, double tolerance)
{
  const Vec3 side = Normalized(Cross({ 0, 0, 1 }, d));
  int count = 0;
  for (size_t e = 0; e + 1 < m.Offsets.size(); ++e)
  {
    double lo = 1e300, hi = -1e300, first = 1e300, last = -1e300, z = 0;
    for (int k = m.Offsets[e]; k < m.Offsets[e + 1]; ++k)
    {
      const Vec3& p = m.Points[m.Connectivity[k]];
      lo = std::min(lo, Dot(side, p - a));
      hi = std::max(hi, Dot(side, p - a));
      first = std::min(first, Dot(d, p - a));
      last = std::max(last, Dot(d, p - a));
      z = std::max(z, std::fabs(p.z));
    }
    const bool along = first > tolerance && last < length - tolerance; // beside the wall's foot
    count += z < 1e-9 && along && lo < -tolerance && hi > tolerance ? 1 : 0;
  }
  return count;
}
} // namespace

TEST(ContactCuts, ASlantedWallOnATriangularFloorCutsItsTriangles)
{
  // A triangle floor (barycentric lattice of triangle elements) with a wall standing at 30
  // degrees across it; then the whole scene turned, scaled and moved: the same count.
  FloorAndWalls scene(1.8);
  scene.Points.clear(); // our own floor and wall instead

  scene.Offsets = { 0 };
  scene.Connectivity.clear();
  const Vec3 a{ 0.3, 0.2, 0 }, d = Normalized(Vec3{ std::cos(0.5236), std::sin(0.5236), 0 });
  scene.Add({ { 0, 0, 0 }, { 4, 0, 0 }, { 0, 3, 0 } });
  scene.Add({ a, a + Vec3{ 0, 0, 2 }, a + d * 2.5 + Vec3{ 0, 0, 2 }, a + d * 2.5 });
  MesherOptions o;
  o.PatchSize = 1.0;
  o.ElementSize = 0.25;
  MeshedPolygons m;
  ASSERT_EQ(MeshPolygons(scene.Points, scene.Offsets, scene.Connectivity, { 0, 0 }, o, m), "");
  EXPECT_EQ(Straddling(m, a, d, 2.5, 1e-9), 0);
  FloorAndWalls lifted = scene;
  for (int k = lifted.Offsets[1]; k < lifted.Offsets[2]; ++k)
  {
    lifted.Points[lifted.Connectivity[k]].z += 1e-3;
  }
  EXPECT_GT(static_cast<double>(m.SourcePolygon.size()),
    CountElements(lifted.Points, lifted.Offsets, lifted.Connectivity, 1.0, 0.25))
    << "cut, the floor has more elements than under a floating wall";
  const double count = static_cast<double>(m.SourcePolygon.size());
  EXPECT_EQ(CountElements(scene.Points, scene.Offsets, scene.Connectivity, 1.0, 0.25), count);
  FloorAndWalls moved = scene;
  const double c = std::cos(0.7), s = std::sin(0.7);
  for (Vec3& p : moved.Points)
  {
    const Vec3 r{ c * p.x - s * p.z, p.y, s * p.x + c * p.z };
    p = r * 1000.0 + Vec3{ 1e4, -2e3, 5e2 };
  }
  MeshedPolygons turned;
  o.PatchSize = 1000.0;
  o.ElementSize = 250.0;
  ASSERT_EQ(MeshPolygons(moved.Points, moved.Offsets, moved.Connectivity, { 0, 0 }, o, turned), "");
  EXPECT_EQ(static_cast<double>(turned.SourcePolygon.size()), count) << "turned, scaled by 1000 and moved";
}

TEST(ContactCuts, APieceIsCutByTheWallsOfOtherPieces)
{
  // MPI: a rank holding the floor alone cuts it as one process does, given the whole scene.
  const FloorAndWalls whole(1.8);
  FloorAndWalls floor(1.8);
  floor.Offsets.resize(2);
  floor.Connectivity.resize(4);
  MesherOptions o;
  o.PatchSize = 1.0;
  o.ElementSize = 0.5;
  MeshedPolygons alone, together;
  ASSERT_EQ(MeshPolygons(floor.Points, floor.Offsets, floor.Connectivity, { 0 }, o, alone), "");
  const PolygonArrays arrays = whole.Arrays();
  o.WholeScene = &arrays;
  ASSERT_EQ(MeshPolygons(floor.Points, floor.Offsets, floor.Connectivity, { 0 }, o, together), "");
  EXPECT_EQ(alone.SourcePolygon.size(), 48u);    // 8 x 6, nothing stands on it
  EXPECT_EQ(together.SourcePolygon.size(), 54u); // the wall's column split, as in one process
  EXPECT_EQ(CountElements(floor.Points, floor.Offsets, floor.Connectivity, 1.0, 0.5, &arrays), 54.0);
}

TEST(ContactCuts, CountingAbsurdlySmallElementsBesideAWallNeitherMakesThemNorFails)
{
  // 2e-4 m elements on the 4 x 3 floor: 3e8 of them. The count says so (for the size
  // limit's error) instead of making and cutting them all, which took gigabytes.
  const FloorAndWalls scene(1.8);
  const double count = CountElements(scene.Points, scene.Offsets, scene.Connectivity, 1.0, 2e-4);
  EXPECT_GE(count, 3e8);
  MesherOptions o;
  o.PatchSize = 1.0;
  o.ElementSize = 2e-4;
  o.MaximumElements = 20000000;
  MeshedPolygons m;
  EXPECT_NE(MeshPolygons(scene.Points, scene.Offsets, scene.Connectivity, { 0, 0, 0 }, o, m).find("more than the limit"),
    std::string::npos);
}
