// Coplanar faces that overlap: one keeps the overlap (a lamp, else the smaller surface, else
// the earlier), the others are cut to what it leaves.
// Reference: the exact area of the faces' union, and their own corners where nothing overlaps.
#include "Mesh/OverlapCuts.h"
#include "Geometry/Polygon.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

using namespace radiosity;

namespace
{
struct Faces
{
  std::vector<Vec3> points;
  PairedPolygons polygons;
  std::vector<int> keys;

  void Add(const std::vector<Vec3>& loop, int key = 0)
  {
    for (const Vec3& p : loop)
    {
      polygons.connectivity.push_back(static_cast<int>(points.size()));
      points.push_back(p);
    }
    polygons.offsets.push_back(static_cast<int>(polygons.connectivity.size()));
    polygons.source.push_back(static_cast<int>(keys.size()));
    keys.push_back(key);
  }

  /// An axis-aligned rectangle at height z, wound to face +z.
  void Rectangle(double x0, double x1, double y0, double y1, int key = 0, double z = 0)
  {
    Add({ { x0, y0, z }, { x1, y0, z }, { x1, y1, z }, { x0, y1, z } }, key);
  }

  std::vector<int> lights;

  OverlapCuts Cut() { return CutOverlaps(points, keys, lights, 1e-9, polygons); }

  /// An nx x ny grid of unit quads at z = 0 facing +z, sharing their corners.
  void Grid(int nx, int ny, int key)
  {
    const int base = static_cast<int>(points.size());
    for (int j = 0; j <= ny; ++j)
    {
      for (int i = 0; i <= nx; ++i)
      {
        points.push_back({ double(i), double(j), 0 });
      }
    }
    for (int j = 0; j < ny; ++j)
    {
      for (int i = 0; i < nx; ++i)
      {
        const int a = base + j * (nx + 1) + i;
        for (int id : { a, a + 1, a + nx + 2, a + nx + 1 })
        {
          polygons.connectivity.push_back(id);
        }
        polygons.offsets.push_back(static_cast<int>(polygons.connectivity.size()));
        polygons.source.push_back(static_cast<int>(keys.size()));
        keys.push_back(key);
      }
    }
  }

  /// How many of the polygons hold point p (of the z = 0 plane) strictly inside.
  int Covering(const Vec3& p) const
  {
    const std::vector<Vec3>& at = PointsOf(polygons, points);
    int count = 0;
    for (size_t i = 0; i + 1 < polygons.offsets.size(); ++i)
    {
      const std::vector<Vec3> loop = GatherLoop(at, polygons.offsets, polygons.connectivity, static_cast<int>(i));
      bool inside = std::fabs(loop[0].z) < 1e-12;
      for (size_t k = 0; k < loop.size() && inside; ++k)
      {
        const Vec3& a = loop[k];
        const Vec3& b = loop[(k + 1) % loop.size()];
        inside = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x) > 1e-12;
      }
      count += inside ? 1 : 0;
    }
    return count;
  }

  double Area() const
  {
    const std::vector<Vec3>& at = PointsOf(polygons, points);
    double area = 0;
    for (size_t i = 0; i + 1 < polygons.offsets.size(); ++i)
    {
      const std::vector<Vec3> loop = GatherLoop(at, polygons.offsets, polygons.connectivity, static_cast<int>(i));
      area += PolygonArea(loop.data(), static_cast<int>(loop.size()));
    }
    return area;
  }

  /// The sum of the faces' normals times their areas: all face +z when equal to the area.
  double FacingUp() const
  {
    const std::vector<Vec3>& at = PointsOf(polygons, points);
    double up = 0;
    for (size_t i = 0; i + 1 < polygons.offsets.size(); ++i)
    {
      const std::vector<Vec3> loop = GatherLoop(at, polygons.offsets, polygons.connectivity, static_cast<int>(i));
      up += 0.5 * NewellVector(loop.data(), static_cast<int>(loop.size())).z;
    }
    return up;
  }
};
} // namespace

TEST(OverlapCuts, TheLaterFaceKeepsWhatTheEarlierLeaves)
{
  Faces f;
  f.Rectangle(0, 2, 0, 1);
  f.Rectangle(1, 3, 0, 1);
  const OverlapCuts cuts = f.Cut();
  EXPECT_EQ(cuts.Trimmed, std::vector<int>{ 1 });
  EXPECT_TRUE(cuts.Covered.empty());
  EXPECT_NEAR(f.Area(), 3.0, 1e-12); // the union, not 4
  EXPECT_NEAR(f.FacingUp(), 3.0, 1e-12);
}

TEST(OverlapCuts, RepeatedCornersOfTheEarlierFaceCutTheSame)
{
  // A zero-length edge has no inside: taken as it is, it kept the whole overlap.
  for (int repeat = 0; repeat < 4; ++repeat)
  {
    Faces f;
    std::vector<Vec3> earlier{ { 0, 0, 0 }, { 2, 0, 0 }, { 2, 1, 0 }, { 0, 1, 0 } };
    earlier.insert(earlier.begin() + repeat, earlier[repeat]);
    f.Add(earlier);
    f.Rectangle(1, 3, 0, 1);
    f.Cut();
    EXPECT_NEAR(f.Area(), 3.0, 1e-12) << "corner " << repeat << " repeated";
  }
}

TEST(OverlapCuts, CoveredFacesAreLeftOutAndThreeLayersLeaveOne)
{
  Faces f;
  f.Rectangle(0, 4, 0, 4);
  f.Rectangle(1, 2, 1, 2); // inside the first
  f.Rectangle(0, 4, 0, 4); // a copy the copies pass would drop, here cut away
  f.Rectangle(3, 5, 3, 5); // a corner outside
  const OverlapCuts cuts = f.Cut();
  // One order for all: the smaller keep the overlap, so the first is cut around the
  // second and the fourth, and the copy of it (as large, later) lies wholly under them.
  EXPECT_EQ(cuts.Covered, (std::vector<int>{ 2 }));
  EXPECT_EQ(cuts.Trimmed, std::vector<int>{ 0 });
  EXPECT_NEAR(f.Area(), 16.0 + 4.0 - 1.0, 1e-12);
}

TEST(OverlapCuts, ANonConvexEarlierFaceCutsByItsOutline)
{
  Faces f;
  f.Add({ { 0, 0, 0 }, { 3, 0, 0 }, { 3, 1, 0 }, { 1, 1, 0 }, { 1, 3, 0 }, { 0, 3, 0 } }); // an L of area 5
  f.Rectangle(0.5, 2.5, 0.5, 2.5);                                                       // 4, of which 1.75 under the L
  f.Cut();
  EXPECT_NEAR(f.Area(), 5.0 + 4.0 - 1.75, 1e-12);
}

TEST(OverlapCuts, OtherSidesAndPlanesAreLeftAlone)
{
  Faces f;
  f.Rectangle(0, 2, 0, 1, 0);
  f.Rectangle(1, 3, 0, 1, 1, 1e-3); // a millimetre above: a layer of its own
  f.Add({ { 1, 0, 0 }, { 1, 1, 0 }, { 3, 1, 0 }, { 3, 0, 0 } }, 1); // facing down: the other side
  const std::vector<int> before = f.polygons.connectivity;
  const OverlapCuts cuts = f.Cut();
  EXPECT_TRUE(cuts.Trimmed.empty() && cuts.Covered.empty() && f.polygons.points.empty());
  EXPECT_EQ(f.polygons.connectivity, before);
}

TEST(OverlapCuts, OfTwoSurfacesTheSmallerKeepsTheOverlapInEitherOrder)
{
  // A poster on a wall, drawn after it or before it: the wall is cut around the poster.
  for (const bool posterFirst : { false, true })
  {
    Faces f;
    if (posterFirst)
    {
      f.Rectangle(1, 2, 1, 2, 1);
    }
    f.Rectangle(0, 4, 0, 3, 0);
    if (!posterFirst)
    {
      f.Rectangle(1, 2, 1, 2, 1);
    }
    const OverlapCuts cuts = f.Cut();
    EXPECT_EQ(cuts.Trimmed, std::vector<int>{ posterFirst ? 1 : 0 }) << "poster first: " << posterFirst;
    EXPECT_NEAR(f.Area(), 12.0, 1e-12);
    EXPECT_NEAR(f.FacingUp(), 12.0, 1e-12);
  }
}

TEST(OverlapCuts, AWallAPatchOfItAndAPosterOverBothLeaveNoHole)
{
  // Earlier-wins for one material and smaller-wins for two made a circle here: the wall
  // lost (1.5, 1.5) to the poster, the poster to the patch, the patch to the wall.
  Faces f;
  f.Rectangle(0, 4, 0, 3, 0);
  f.Rectangle(1, 2, 1, 2, 0);
  f.Rectangle(0.5, 2.5, 0.5, 2.5, 1);
  f.Cut();
  EXPECT_NEAR(f.Area(), 12.0, 1e-12);
  for (const Vec3& p : { Vec3{ 1.5, 1.5, 0 }, Vec3{ 0.7, 0.7, 0 }, Vec3{ 3, 2, 0 } })
  {
    EXPECT_EQ(f.Covering(p), 1) << p.x << ", " << p.y;
  }
}

TEST(OverlapCuts, ALampKeepsTheOverlapOverItsTile)
{
  // A lamp drawn with its tile's corners, or a little larger: the tile gives way, the lamp
  // keeps all its area (as the smaller, a lamp the size of its tile was cut away before).
  for (const double grow : { 0.0, 0.01 })
  {
    Faces f;
    f.Rectangle(0, 0.6, 0, 0.6, 0);
    f.Rectangle(-grow, 0.6 + grow, -grow, 0.6 + grow, 1);
    f.lights = { -1, 0 };
    const OverlapCuts cuts = f.Cut();
    EXPECT_EQ(cuts.Covered, std::vector<int>{ 0 }) << "grown " << grow;
    EXPECT_NEAR(f.Area(), (0.6 + 2 * grow) * (0.6 + 2 * grow), 1e-12);
  }
}

TEST(OverlapCuts, AWallTessellatedFinerThanAPosterStillGivesWay)
{
  // The wall is 12 quads of 1 m2 sharing their corners, the poster 2.25 m2: the wall's
  // surface, not each quad, is the larger.
  Faces f;
  f.Grid(4, 3, 0);
  f.Rectangle(0.25, 1.75, 0.25, 1.75, 1);
  const OverlapCuts cuts = f.Cut();
  EXPECT_TRUE(cuts.Covered.empty());
  EXPECT_EQ(cuts.Trimmed, (std::vector<int>{ 0, 1, 4, 5 }));
  EXPECT_NEAR(f.Area(), 12.0, 1e-12);
  EXPECT_EQ(f.Covering({ 1, 1, 0 }), 1);
}

TEST(OverlapCuts, AFanOfNeighboursIsNotCutAndTakesLittleTime)
{
  // 4,000 triangles around one centre (a CAD disk): every box holds the centre, so the
  // grid cannot part them; only their edges can.
  Faces f;
  const int n = 4000;
  for (int k = 0; k < n; ++k)
  {
    const double a = 2 * M_PI * k / n, b = 2 * M_PI * (k + 1) / n;
    f.Add({ { 0, 0, 0 }, { std::cos(a), std::sin(a), 0 }, { std::cos(b), std::sin(b), 0 } });
  }
  const auto start = std::chrono::steady_clock::now();
  const OverlapCuts cuts = f.Cut();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_TRUE(cuts.Trimmed.empty() && cuts.Covered.empty());
  std::printf("fan of %d triangles: %.2f s\n", n, seconds); // printed, not asserted
}
