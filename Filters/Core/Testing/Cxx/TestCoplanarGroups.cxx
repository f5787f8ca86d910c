// Which polygons the mesher puts in one plane, and which triangle pairs it joins, when the
// points carry float noise. Reference: the same join rule checked against every founder
// (no index), and hand-built pairs whose flatness is known.
#include "Mesh/CoplanarGroups.h"
#include "Mesh/TrianglePairs.h"
#include "Geometry/Polygon.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace radiosity;

namespace
{
/// The join rule of GroupCoplanar checked against every founder so far, polygons taken in
/// the same order (tolerance classes a factor of 16 wide, then the input's order).
std::vector<int> EveryFounderChecked(const std::vector<PolygonPlane>& planes, double offsetTolerance)
{
  auto rank = [&](int p) { return static_cast<int>(std::floor(std::log2(planes[p].Tolerance / 1e-6) / 4)); };
  std::vector<int> order(planes.size());
  for (size_t i = 0; i < order.size(); ++i)
  {
    order[i] = static_cast<int>(i);
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return rank(a) < rank(b); });
  std::vector<int> founders, group(planes.size(), -1);
  for (int p : order)
  {
    const PolygonPlane& a = planes[p];
    int best = -1;
    double nearest = 1;
    for (size_t g = 0; g < founders.size(); ++g)
    {
      const PolygonPlane& f = planes[founders[g]];
      const double distance = std::max(Norm(a.Normal - f.Normal) / (a.Tolerance + f.Tolerance),
        std::fabs(Dot(f.Normal, a.Centroid - f.Centroid)) /
          (offsetTolerance + f.Tolerance * Norm(a.Centroid - f.Centroid)));
      if (a.Key == f.Key && distance <= nearest && (best < 0 || distance < nearest))
      {
        best = static_cast<int>(g), nearest = distance;
      }
    }
    if (best < 0)
    {
      best = static_cast<int>(founders.size());
      founders.push_back(p);
    }
    group[p] = best;
  }
  return group;
}

/// True when two groupings put the same polygons together (whatever the numbers).
bool SamePartition(const std::vector<int>& a, const std::vector<int>& b)
{
  for (size_t i = 0; i < a.size(); ++i)
  {
    for (size_t j = 0; j < i; ++j)
    {
      if ((a[i] == a[j]) != (b[i] == b[j]))
      {
        return false;
      }
    }
  }
  return true;
}

Vec3 Tilted(double angle)
{
  return Vec3{ std::sin(angle), std::cos(angle), 0 };
}
} // namespace

TEST(CoplanarGroups, AFounderOfWiderToleranceInTheSameClassIsFoundAcrossTheScene)
{
  // The founder (tolerance 1.5e-5) and a precise tile (1e-6) share a class; the tile is
  // 200 m away and tilted by 0.45 of their summed tolerances: within the rule, so one plane.
  // The offset range once assumed every founder at most as uncertain as the polygon looking
  // for it, and missed this one.
  const std::vector<PolygonPlane> planes = { { Tilted(0), { -100, 0, 0 }, 1.5e-5, 0 },
    { Tilted(0.45 * 1.6e-5), { 100, 0, 0 }, 1e-6, 0 } };
  const CoplanarGroups groups = GroupCoplanar(planes, 1e-5, Vec3{});
  EXPECT_EQ(groups.Group[0], groups.Group[1]);
  EXPECT_EQ(EveryFounderChecked(planes, 1e-5)[1], 0);
}

TEST(CoplanarGroups, FloorTilesWithNoiseGroupAsEveryFounderCheckedGroupsThem)
{
  // Tiles of three parallel floors 1 cm apart, their normals turned by up to half their
  // tolerance, tolerances over three classes, 50 m across.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1, 1), spread(0, 1);
  for (int scene = 0; scene < 200; ++scene)
  {
    std::vector<PolygonPlane> planes;
    for (int t = 0; t < 30; ++t)
    {
      const double tolerance = 1e-6 * std::pow(2.0, 12 * spread(random));
      const double turn = 0.5 * tolerance;
      const Vec3 n = Normalized(Vec3{ turn * unit(random), 1, turn * unit(random) });
      const Vec3 c{ 25 * unit(random), 0.01 * (t % 3), 25 * unit(random) };
      planes.push_back({ n, c, tolerance, 0 });
    }
    const std::vector<int> reference = EveryFounderChecked(planes, 1e-5);
    ASSERT_TRUE(SamePartition(GroupCoplanar(planes, 1e-5, Vec3{ 3, 0, -2 }).Group, reference)) << "scene " << scene;
  }
}

TEST(CoplanarGroups, APolygonTrustsItsNormalAsFarAsItsNoiseAllows)
{
  // A 1 m square with 1 mm noise: its normal may turn by about 4e-3; a 10 m one by 4e-4; a
  // sliver of any noise no further than the most the grouping allows (1e-2).
  const std::vector<Vec3> square = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 0, 1 }, { 0, 0, 1 } };
  std::vector<Vec3> large = square;
  for (Vec3& p : large)
  {
    p = p * 10.0;
  }
  const PolygonPlane small = PlaneOf(square, 1e-3, 0), big = PlaneOf(large, 1e-3, 0);
  EXPECT_NEAR(small.Tolerance, 4e-3, 1e-12);
  EXPECT_NEAR(big.Tolerance, 4e-4, 1e-12);
  const std::vector<Vec3> sliver = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 0, 1e-6 } };
  EXPECT_EQ(PlaneOf(sliver, 1e-3, 0).Tolerance, 1e-2);
}

TEST(TrianglePairs, APairFlatWithinTheNoiseJoinsAndAFoldedOneDoesNot)
{
  // A unit square split along its diagonal, its far corner lifted by h: flat within 1e-3
  // joins whatever the triangles' normals say; lifted by 0.1 (a fold of 8 degrees) it
  // stays two triangles.
  for (const double h : { 0.0, 2e-4, 0.1 })
  {
    const std::vector<Vec3> points = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, h, 1 }, { 0, 0, 1 } };
    const std::vector<int> offsets = { 0, 3, 6 }, connectivity = { 0, 2, 1, 0, 3, 2 }, key = { 0, 0 };
    const PairedPolygons paired = MergeTrianglePairs(points, offsets, connectivity, key, 1e-9, 1e-3);
    EXPECT_EQ(paired.Merged, h < 1e-3 ? 1 : 0) << "lifted by " << h;
  }
}
