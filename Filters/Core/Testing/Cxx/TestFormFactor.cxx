// Form factors against closed forms from the radiation heat-transfer literature
// (values in shared/REFERENCES.md: Howell's catalogue C-11, C-14; Lambert's formula).
#include "Geometry/FormFactor.h"
#include "Geometry/Polygon.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using radiosity::Vec3;

namespace
{
std::vector<Vec3> Rectangle(const Vec3& origin, const Vec3& u, const Vec3& v)
{
  return { origin, origin + u, origin + u + v, origin + v };
}

/// Howell C-11: directly opposed identical rectangles a x b at distance c.
double OpposedRectangles(double a, double b, double c)
{
  const double X = a / c, Y = b / c;
  const double pi = 3.14159265358979323846;
  return 2.0 / (pi * X * Y) *
    (std::log(std::sqrt((1 + X * X) * (1 + Y * Y) / (1 + X * X + Y * Y))) +
      X * std::sqrt(1 + Y * Y) * std::atan(X / std::sqrt(1 + Y * Y)) +
      Y * std::sqrt(1 + X * X) * std::atan(Y / std::sqrt(1 + X * X)) - X * std::atan(X) -
      Y * std::atan(Y));
}
}

TEST(PointToPolygon, CentredUnderUnitSquare)
{
  const auto square = Rectangle({ -0.5, -0.5, 1 }, { 1, 0, 0 }, { 0, 1, 0 });
  EXPECT_NEAR(radiosity::PointToPolygonFormFactor({ 0, 0, 0 }, { 0, 0, 1 }, square.data(), 4),
    0.2394565, 1e-7);
}

TEST(PointToPolygon, UnderCornerOfRectangles)
{
  struct Case
  {
    double a, b, c, expected;
  };
  for (const Case& k : { Case{ 1, 1, 1, 0.138532 }, Case{ 2, 1, 1, 0.167375 }, Case{ 1, 1, 2, 0.059864 } })
  {
    const auto rect = Rectangle({ 0, 0, k.c }, { k.a, 0, 0 }, { 0, k.b, 0 });
    EXPECT_NEAR(radiosity::PointToPolygonFormFactor({ 0, 0, 0 }, { 0, 0, 1 }, rect.data(), 4),
      k.expected, 1e-6)
      << k.a << "x" << k.b << " at " << k.c;
  }
}

TEST(PointToPolygon, OrientationDoesNotMatter)
{
  auto square = Rectangle({ -0.5, -0.5, 1 }, { 1, 0, 0 }, { 0, 1, 0 });
  std::vector<Vec3> reversed(square.rbegin(), square.rend());
  EXPECT_DOUBLE_EQ(radiosity::PointToPolygonFormFactor({ 0, 0, 0 }, { 0, 0, 1 }, square.data(), 4),
    radiosity::PointToPolygonFormFactor({ 0, 0, 0 }, { 0, 0, 1 }, reversed.data(), 4));
}

TEST(PointToPolygon, ApproachingPerpendicularWallEdge)
{
  // Unit wall in the plane x = 0 (y in [-0.5, 0.5], z in [0, 1]), receiver facing up at
  // mid-edge distance x: the exact value tends to 1/2.
  const auto wall = Rectangle({ 0, -0.5, 0 }, { 0, 1, 0 }, { 0, 0, 1 });
  struct Case
  {
    double x, expected;
  };
  for (const Case& k : { Case{ 0.5, 0.1901359 }, Case{ 0.1, 0.4225449 }, Case{ 0.01, 0.4921590 },
         Case{ 1e-6, 0.5 } })
  {
    EXPECT_NEAR(radiosity::PointToPolygonFormFactor({ k.x, 0, 0 }, { 0, 0, 1 }, wall.data(), 4),
      k.expected, 1e-6)
      << "x = " << k.x;
  }
}

TEST(PointToPolygon, ClipsPolygonStraddlingReceiverPlane)
{
  // Unit square in x = 1, y, z in [-0.5, 0.5], receiver at origin facing +z: only the
  // upper half is visible. Unclipped, the halves cancel to 0.
  const auto square = Rectangle({ 1, -0.5, -0.5 }, { 0, 1, 0 }, { 0, 0, 1 });
  EXPECT_NEAR(radiosity::PointToPolygonFormFactor({ 0, 0, 0 }, { 0, 0, 1 }, square.data(), 4),
    0.027855, 1e-6);
}

TEST(PointToPolygon, BehindReceiverIsZero)
{
  const auto square = Rectangle({ -0.5, -0.5, -1 }, { 1, 0, 0 }, { 0, 1, 0 });
  EXPECT_EQ(radiosity::PointToPolygonFormFactor({ 0, 0, 0 }, { 0, 0, 1 }, square.data(), 4), 0.0);
}

TEST(PointToPolygon, CoaxialDisk)
{
  // A 256-gon inscribed in the disk; area-corrected radius gives r^2 / (h^2 + r^2).
  for (double h : { 1.0, 2.0 })
  {
    std::vector<Vec3> disk;
    const int n = 256;
    const double pi = 3.14159265358979323846;
    const double r = std::sqrt(2 * pi / (n * std::sin(2 * pi / n))); // same area as r = 1
    for (int i = 0; i < n; ++i)
    {
      disk.push_back({ r * std::cos(2 * pi * i / n), r * std::sin(2 * pi * i / n), h });
    }
    EXPECT_NEAR(radiosity::PointToPolygonFormFactor({ 0, 0, 0 }, { 0, 0, 1 }, disk.data(), n),
      1.0 / (h * h + 1.0), 2e-5);
  }
}

TEST(PolygonToPolygon, OpposedSquaresMatchHowell)
{
  EXPECT_NEAR(OpposedRectangles(1, 1, 1), 0.199825, 1e-6); // the formula itself
  struct Case
  {
    double a, b, c, expected;
  };
  for (const Case& k : { Case{ 1, 1, 1, 0.199825 }, Case{ 1, 2, 1, 0.285875 }, Case{ 2, 2, 1, 0.415253 },
         Case{ 0.5, 0.5, 1, 0.068590 }, Case{ 10, 10, 1, 0.826995 } })
  {
    const auto from = Rectangle({ 0, 0, 0 }, { k.a, 0, 0 }, { 0, k.b, 0 });
    const auto to = Rectangle({ 0, 0, k.c }, { k.a, 0, 0 }, { 0, k.b, 0 });
    // Keep sub-triangles well below the gap so the midpoint rule is accurate.
    const int subdivisions = static_cast<int>(48 * std::ceil(std::max(k.a, k.b) / k.c));
    EXPECT_NEAR(radiosity::PolygonToPolygonFormFactor(from.data(), 4, to.data(), 4, subdivisions),
      k.expected, 1e-4 * k.expected)
      << k.a << "x" << k.b << " gap " << k.c;
  }
}

TEST(PolygonToPolygon, PerpendicularSquaresSharingAnEdge)
{
  const auto floor = Rectangle({ 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 });
  const auto wall = Rectangle({ 0, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 });
  // The integrand is log-singular at the shared edge: refine until well inside 0.1 %.
  EXPECT_NEAR(radiosity::PolygonToPolygonFormFactor(floor.data(), 4, wall.data(), 4, 64), 0.200044, 2e-4);
  // l = 1, w = 1, h = 2 (Howell C-14): F12 = 0.232853, F21 = 0.116426.
  const auto tall = Rectangle({ 0, 0, 0 }, { 0, 1, 0 }, { 0, 0, 2 });
  const double f12 = radiosity::PolygonToPolygonFormFactor(floor.data(), 4, tall.data(), 4, 64);
  const double f21 = radiosity::PolygonToPolygonFormFactor(tall.data(), 4, floor.data(), 4, 64);
  EXPECT_NEAR(f12, 0.232853, 3e-4);
  EXPECT_NEAR(f21, 0.116426, 3e-4);
}

TEST(PolygonToPolygon, Reciprocity)
{
  // A_i F_ij = A_j F_ji for an oblique, unequal pair (no closed form needed).
  const std::vector<Vec3> a = { { 0, 0, 0 }, { 2, 0, 0 }, { 2, 1, 0 }, { 0, 1, 0 } };
  // b's right-hand normal faces a: back faces neither emit nor receive.
  const std::vector<Vec3> b = { { 0.2, 1.4, 1.6 }, { 1.1, 0.2, 2.0 }, { 0.5, -0.3, 1.2 } };
  const double fab = radiosity::PolygonToPolygonFormFactor(a.data(), 4, b.data(), 3, 48);
  const double fba = radiosity::PolygonToPolygonFormFactor(b.data(), 3, a.data(), 4, 48);
  const double areaA = radiosity::PolygonArea(a.data(), 4), areaB = radiosity::PolygonArea(b.data(), 3);
  EXPECT_GT(fab, 0.01);
  EXPECT_NEAR(areaA * fab, areaB * fba, 1e-4 * areaA * fab);
}

TEST(PolygonToPolygon, UnitCubeSumsToOne)
{
  // From the bottom face: opposite + 4 adjacent = 1, and F_adjacent = (1 - F_opposite) / 4.
  const auto bottom = Rectangle({ 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 });
  const std::vector<std::vector<Vec3>> others = { Rectangle({ 0, 0, 1 }, { 1, 0, 0 }, { 0, 1, 0 }),
    Rectangle({ 0, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }), Rectangle({ 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }),
    Rectangle({ 0, 0, 0 }, { 1, 0, 0 }, { 0, 0, 1 }), Rectangle({ 0, 1, 0 }, { 1, 0, 0 }, { 0, 0, 1 }) };
  double sum = 0;
  for (const auto& face : others)
  {
    sum += radiosity::PolygonToPolygonFormFactor(bottom.data(), 4, face.data(), 4, 64);
  }
  EXPECT_NEAR(sum, 1.0, 1e-9); // exact inner integral covers the hemisphere at every point
}
