#include "Mesh/Mesher.h"
#include "Geometry/Polygon.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

using namespace radiosity;

namespace
{
double TotalArea(const MeshedPolygons& m)
{
  double area = 0;
  for (size_t e = 0; e + 1 < m.Offsets.size(); ++e)
  {
    std::vector<Vec3> loop;
    for (int k = m.Offsets[e]; k < m.Offsets[e + 1]; ++k)
    {
      loop.push_back(m.Points[m.Connectivity[k]]);
    }
    area += PolygonArea(loop.data(), static_cast<int>(loop.size()));
  }
  return area;
}

MesherOptions Sizes(double patch, double element)
{
  MesherOptions o;
  o.PatchSize = patch;
  o.ElementSize = element;
  return o;
}
}

TEST(Mesher, QuadBecomesGridOfPatchesAndElements)
{
  const std::vector<Vec3> points = { { 0, 0, 0 }, { 2, 0, 0 }, { 2, 1, 0 }, { 0, 1, 0 } };
  MeshedPolygons m;
  ASSERT_EQ(MeshPolygons(points, { 0, 4 }, { 0, 1, 2, 3 }, { 0 }, Sizes(1, 0.5), m), "");
  EXPECT_EQ(m.Patches, 2);
  EXPECT_EQ(m.SourcePolygon.size(), 8u);
  EXPECT_EQ(m.Points.size(), 15u); // a 5 x 3 lattice: points are shared
  EXPECT_NEAR(TotalArea(m), 2.0, 1e-12);
  for (int p = 0; p < 2; ++p)
  {
    EXPECT_EQ(std::count(m.PatchId.begin(), m.PatchId.end(), p), 4);
  }
}

TEST(Mesher, TriangleEdgesStayWithinSizes)
{
  const std::vector<Vec3> points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
  MeshedPolygons m;
  ASSERT_EQ(MeshPolygons(points, { 0, 3 }, { 0, 1, 2 }, { 0 }, Sizes(1, 0.5), m), "");
  EXPECT_EQ(m.SourcePolygon.size(), 16u);
  EXPECT_EQ(m.Patches, 4);
  EXPECT_NEAR(TotalArea(m), 0.5, 1e-12);
  for (size_t e = 0; e + 1 < m.Offsets.size(); ++e)
  {
    for (int k = m.Offsets[e]; k < m.Offsets[e + 1]; ++k)
    {
      const int next = k + 1 < m.Offsets[e + 1] ? k + 1 : m.Offsets[e];
      EXPECT_LE(Norm(m.Points[m.Connectivity[k]] - m.Points[m.Connectivity[next]]), 0.5 + 1e-12);
    }
  }
}

TEST(Mesher, SharesPointsOnlyWithinOneFlatMaterial)
{
  // Two coplanar unit quads side by side, and a wall standing on their shared edge line.
  const std::vector<Vec3> points = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 2, 0, 0 },
    { 2, 1, 0 }, { 1, 0, 1 }, { 1, 1, 1 } };
  const std::vector<int> offsets = { 0, 4, 8, 12 };
  const std::vector<int> conn = { 0, 1, 2, 3, 1, 4, 5, 2, 1, 2, 7, 6 };
  MeshedPolygons same, different;
  ASSERT_EQ(MeshPolygons(points, offsets, conn, { 0, 0, 0 }, Sizes(1, 1), same), "");
  ASSERT_EQ(MeshPolygons(points, offsets, conn, { 0, 1, 0 }, Sizes(1, 1), different), "");
  // Same material: the floor quads share 2 points; the wall has its own 4.
  EXPECT_EQ(same.Points.size(), 6u + 4u);
  EXPECT_EQ(different.Points.size(), 4u + 4u + 4u);
}

TEST(Mesher, RefusesBadSizesAndExplosions)
{
  const std::vector<Vec3> points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
  MeshedPolygons m;
  EXPECT_NE(MeshPolygons(points, { 0, 3 }, { 0, 1, 2 }, { 0 }, Sizes(0, 0.5), m), "");
  MesherOptions tiny = Sizes(1, 1e-6);
  EXPECT_NE(MeshPolygons(points, { 0, 3 }, { 0, 1, 2 }, { 0 }, tiny, m).find("ElementSize"), std::string::npos);
}

TEST(Mesher, CountAndBudgetMatchTheMesh)
{
  // A quad, a triangle and a non-convex L: the count without meshing equals the mesh, and
  // the budget's element size is the smallest that fits.
  const std::vector<Vec3> points = { { 0, 0, 0 }, { 3, 0, 0 }, { 3, 2, 0 }, { 0, 2, 0 }, // quad
    { 0, 0, 1 }, { 2.5, 0, 1 }, { 0, 1.7, 1 },                                              // triangle
    { 0, 0, 2 }, { 2, 0, 2 }, { 2, 1, 2 }, { 1, 1, 2 }, { 1, 2, 2 }, { 0, 2, 2 } };         // L
  const std::vector<int> offsets = { 0, 4, 7, 13 };
  const std::vector<int> connectivity = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12 };
  for (double element : { 0.5, 0.23, 0.1 })
  {
    MeshedPolygons m;
    ASSERT_EQ(MeshPolygons(points, offsets, connectivity, { 0, 1, 2 }, Sizes(1, element), m), "");
    EXPECT_EQ(CountElements(points, offsets, connectivity, 1, element), static_cast<double>(m.SourcePolygon.size()))
      << element;
  }
  const double budget = 500;
  const double size = ElementSizeForBudget(points, offsets, connectivity, 1, 0.05, budget);
  EXPECT_GT(size, 0.05);
  EXPECT_LE(CountElements(points, offsets, connectivity, 1, size), budget);
  EXPECT_GT(CountElements(points, offsets, connectivity, 1, size * 0.999), budget);
  EXPECT_EQ(ElementSizeForBudget(points, offsets, connectivity, 1, 0.5, budget), 0.5); // fits already
}

TEST(Mesher, TrianglePairsBecomeQuads)
{
  // A unit square exported as two triangles with split vertices: meshed as the square.
  const std::vector<Vec3> points = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } };
  const std::vector<int> offsets = { 0, 3, 6 }, connectivity = { 0, 1, 2, 3, 4, 5 };
  MeshedPolygons quad, split;
  ASSERT_EQ(MeshPolygons({ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } }, { 0, 4 }, { 0, 1, 2, 3 }, { 0 },
              Sizes(1, 0.25), quad),
    "");
  ASSERT_EQ(MeshPolygons(points, offsets, connectivity, { 0, 0 }, Sizes(1, 0.25), split), "");
  EXPECT_EQ(split.MergedTrianglePairs, 1);
  EXPECT_EQ(split.SourcePolygon.size(), quad.SourcePolygon.size()); // 16, not 2 x 32
  EXPECT_NEAR(TotalArea(split), 1.0, 1e-12);
  // Not joined: another material, a fold, a non-convex union, or merging turned off.
  MeshedPolygons other;
  ASSERT_EQ(MeshPolygons(points, offsets, connectivity, { 0, 1 }, Sizes(1, 0.25), other), "");
  EXPECT_EQ(other.MergedTrianglePairs, 0);
  std::vector<Vec3> folded = points;
  folded[5] = { 0, 1, 0.3 };
  ASSERT_EQ(MeshPolygons(folded, offsets, connectivity, { 0, 0 }, Sizes(1, 0.25), other), "");
  EXPECT_EQ(other.MergedTrianglePairs, 0);
  std::vector<Vec3> dart = points;
  dart[5] = { 1.5, 1.8, 0 }; // the union is not convex (reflex at (1, 1))
  ASSERT_EQ(MeshPolygons(dart, offsets, connectivity, { 0, 0 }, Sizes(1, 0.25), other), "");
  EXPECT_EQ(other.MergedTrianglePairs, 0);
  MesherOptions off = Sizes(1, 0.25);
  off.MergeTriangles = false;
  ASSERT_EQ(MeshPolygons(points, offsets, connectivity, { 0, 0 }, off, other), "");
  EXPECT_EQ(other.MergedTrianglePairs, 0);
  EXPECT_GT(other.SourcePolygon.size(), quad.SourcePolygon.size());
}

TEST(Mesher, SliversAreNotCutIntoManyPatches)
{
  // A 3 m x 2 cm strip: split along its length it would be 6 x 6 x 2 lattice patches of
  // almost no area; by area it is one patch, and its elements still have short edges.
  const std::vector<Vec3> points = { { 0, 0, 0 }, { 3, 0, 0 }, { 3, 0.02, 0 } };
  MeshedPolygons m;
  ASSERT_EQ(MeshPolygons(points, { 0, 3 }, { 0, 1, 2 }, { 0 }, Sizes(0.5, 0.25), m), "");
  EXPECT_EQ(m.Patches, 1);
  EXPECT_NEAR(TotalArea(m), 0.03, 1e-12);
  EXPECT_EQ(CountElements(points, { 0, 3 }, { 0, 1, 2 }, 0.5, 0.25), static_cast<double>(m.SourcePolygon.size()));
  for (size_t e = 0; e + 1 < m.Offsets.size(); ++e)
  {
    for (int k = m.Offsets[e]; k < m.Offsets[e + 1]; ++k)
    {
      const int next = k + 1 < m.Offsets[e + 1] ? k + 1 : m.Offsets[e];
      EXPECT_LE(Norm(m.Points[m.Connectivity[k]] - m.Points[m.Connectivity[next]]), 0.25 + 1e-12);
    }
  }
}

TEST(Mesher, ACircleOfManyCornersIsMeshedByArea)
{
  // A CAD circle: 10,000 corners, radius 1 m. Its triangles are slivers from rim to rim,
  // and split along their length they made 363,000 elements; a grid over its area makes
  // about pi / 0.25^2 = 50, and the same number wherever the disk is turned.
  const int corners = 10000;
  const Vec3 axis = Normalized({ 0.3, 0.8, 0.2 });
  for (double angle : { 0.0, 0.65 })
  {
    std::vector<Vec3> points;
    std::vector<int> connectivity;
    const Vec3 a = Normalized(Cross(axis, { 1, 0, 0 })), b = Cross(axis, a);
    const Vec3 u = a * std::cos(angle) + b * std::sin(angle), v = Cross(axis, u);
    for (int i = 0; i < corners; ++i)
    {
      const double t = 2 * 3.14159265358979 * i / corners;
      points.push_back(Vec3{ 5, -3, 2 } + u * std::cos(t) + v * std::sin(t));
      connectivity.push_back(i);
    }
    MeshedPolygons m;
    ASSERT_EQ(MeshPolygons(points, { 0, corners }, connectivity, { 0 }, Sizes(0.5, 0.25), m), "");
    const size_t elements = m.SourcePolygon.size();
    EXPECT_EQ(elements, 60u) << "turned by " << angle; // the 8 x 8 grid less its four corners
    EXPECT_NEAR(TotalArea(m), PolygonArea(points.data(), corners), 1e-9);
    EXPECT_EQ(CountElements(points, { 0, corners }, connectivity, 0.5, 0.25), static_cast<double>(elements));
    EXPECT_EQ(m.Patches, 16);
  }
}

TEST(Mesher, AGearOfManyCornersIsMeshedByItsConvexPieces)
{
  // A CAD gear: 1,000 teeth of 4 corners each around a 1 m disk, 1 cm tall. Not convex,
  // so its ear-clipped triangles were slivers from rim to rim: 72,796 elements. Meshed by
  // its convex pieces (the disk inside the tooth roots on a grid, each tooth one piece):
  // about the teeth plus pi / 0.25^2, the same turned, the area kept exactly.
  const int teeth = 1000;
  const Vec3 axis = Normalized({ 0.3, 0.8, 0.2 });
  const Vec3 u = Normalized(Cross(axis, { 1, 0, 0 })), v = Cross(axis, u);
  std::vector<Vec3> points;
  std::vector<int> connectivity;
  for (int i = 0; i < teeth; ++i)
  {
    const double step = 2 * 3.14159265358979 / teeth;
    for (auto [at, radius] : { std::pair{ 0.0, 1.0 }, { 0.25, 1.0 }, { 0.3, 1.01 }, { 0.7, 1.01 } })
    {
      const double t = (i + at) * step;
      connectivity.push_back(static_cast<int>(points.size()));
      points.push_back(Vec3{ 5, -3, 2 } + u * (radius * std::cos(t)) + v * (radius * std::sin(t)));
    }
  }
  const int corners = static_cast<int>(points.size());
  ASSERT_FALSE(IsConvex(points.data(), corners));
  MeshedPolygons m;
  ASSERT_EQ(MeshPolygons(points, { 0, corners }, connectivity, { 0 }, Sizes(0.5, 0.25), m), "");
  const size_t elements = m.SourcePolygon.size();
  std::printf("gear of %d corners: %zu elements, %d patches\n", corners, elements, m.Patches);
  EXPECT_GT(elements, static_cast<size_t>(teeth));
  EXPECT_LT(elements, static_cast<size_t>(teeth + 200));
  EXPECT_NEAR(TotalArea(m), PolygonArea(points.data(), corners), 1e-9);
  EXPECT_EQ(CountElements(points, { 0, corners }, connectivity, 0.5, 0.25), static_cast<double>(elements));
  for (size_t e = 0; e + 1 < m.Offsets.size(); ++e)
  {
    std::vector<Vec3> element;
    for (int k = m.Offsets[e]; k < m.Offsets[e + 1]; ++k)
    {
      element.push_back(m.Points[m.Connectivity[k]]);
    }
    ASSERT_TRUE(IsConvex(element.data(), static_cast<int>(element.size()), 1e-9)) << "element " << e;
  }
}

TEST(Mesher, SmallPolygonsShareAPatchInTheirCell)
{
  // Four 0.2 m squares of one material in one plane, inside one 1 m cell: one patch. A
  // fifth in another material, or one in another cell, keeps its own.
  std::vector<Vec3> points;
  std::vector<int> offsets = { 0 }, connectivity, keys;
  auto square = [&](double x, double y, int key) {
    for (const Vec3& p : { Vec3{ x, y, 0 }, Vec3{ x + 0.2, y, 0 }, Vec3{ x + 0.2, y + 0.2, 0 }, Vec3{ x, y + 0.2, 0 } })
    {
      connectivity.push_back(static_cast<int>(points.size()));
      points.push_back(p);
    }
    offsets.push_back(static_cast<int>(connectivity.size()));
    keys.push_back(key);
  };
  square(0.1, 0.1, 0);
  square(0.5, 0.1, 0);
  square(0.1, 0.5, 0);
  square(0.3, 0.3, 0);
  square(0.6, 0.6, 1); // another material
  square(1.3, 0.1, 0); // another cell
  MeshedPolygons shared, own;
  ASSERT_EQ(MeshPolygons(points, offsets, connectivity, keys, Sizes(1, 0.1), shared), "");
  EXPECT_EQ(shared.Patches, 3);
  std::set<int> first(shared.PatchId.begin(), shared.PatchId.begin() + 16);
  EXPECT_EQ(first.size(), 1u); // the four squares' 4 x 4 elements
  MesherOptions off = Sizes(1, 0.1);
  off.SharePatches = false;
  ASSERT_EQ(MeshPolygons(points, offsets, connectivity, keys, off, own), "");
  EXPECT_EQ(own.Patches, 6);
  EXPECT_NEAR(TotalArea(shared), 6 * 0.04, 1e-12);
}

// The suggested sizes follow the scene's unit and size, not its placement: a 4 x 2.5 x 4
// box in metres gets 1 and 0.25 (diagonal 6.18, a sixth rounded down to 1), in
// millimetres 1000 and 250, moved far away or turned the same; the area is the box's 72.
TEST(Mesher, SuggestedSizesFollowTheScaleNotThePlacement)
{
  const auto box = [](double scale, Vec3 offset, double turn = 0.0) {
    std::vector<Vec3> points;
    for (int i = 0; i < 8; ++i)
    {
      const Vec3 p = Vec3{ 4.0 * (i & 1), 2.5 * ((i >> 1) & 1), 4.0 * ((i >> 2) & 1) } * scale;
      const Vec3 turned{ std::cos(turn) * p.x - std::sin(turn) * p.y, std::sin(turn) * p.x + std::cos(turn) * p.y, p.z };
      points.push_back(turned + offset);
    }
    const std::vector<int> connectivity = { 0, 1, 3, 2, 4, 6, 7, 5, 0, 4, 5, 1, 2, 3, 7, 6, 0, 2, 6, 4, 1, 5, 7, 3 };
    const SuggestedSizes sizes = SuggestMeshSizes(points, { 0, 4, 8, 12, 16, 20, 24 }, connectivity);
    // The estimate against the mesher itself, at the suggested sizes.
    MeshedPolygons meshed;
    EXPECT_EQ(MeshPolygons(points, { 0, 4, 8, 12, 16, 20, 24 }, connectivity, { 0, 0, 0, 0, 0, 0 },
                Sizes(sizes.PatchSize, sizes.ElementSize), meshed), "");
    EXPECT_NEAR(sizes.Elements, static_cast<double>(meshed.Offsets.size() - 1), 1e-6);
    return sizes;
  };
  const SuggestedSizes metres = box(1.0, Vec3{});
  EXPECT_DOUBLE_EQ(metres.PatchSize, 1.0);
  EXPECT_DOUBLE_EQ(metres.ElementSize, 0.25);
  EXPECT_NEAR(metres.Area, 2 * (16 + 10 + 10), 1e-9);
  const SuggestedSizes millimetres = box(1000.0, Vec3{});
  EXPECT_DOUBLE_EQ(millimetres.PatchSize, 1000.0);
  EXPECT_DOUBLE_EQ(millimetres.ElementSize, 250.0);
  const SuggestedSizes moved = box(1.0, Vec3{ 1e5, -3e4, 7e3 });
  EXPECT_DOUBLE_EQ(moved.PatchSize, 1.0);
  // Turned 37 degrees about z, the room's axis-aligned box grows from a diagonal of 6.18
  // to 7.55: at 1.8x scale a sixth of it would cross 2 (1.85 -> 2.27), its extent does not.
  for (double scale : { 1.0, 1.8, 1000.0 })
  {
    EXPECT_DOUBLE_EQ(box(scale, Vec3{}, 37.0 * 3.14159265358979 / 180).PatchSize, box(scale, Vec3{}).PatchSize);
  }
  const SuggestedSizes small = box(0.3, Vec3{}); // diagonal 1.85: a sixth is 0.309, so 0.25
  EXPECT_DOUBLE_EQ(small.PatchSize, 0.25);
  const SuggestedSizes empty = SuggestMeshSizes({}, { 0 }, {});
  EXPECT_DOUBLE_EQ(empty.PatchSize, 1.0);
  EXPECT_DOUBLE_EQ(empty.Area, 0.0);
}
