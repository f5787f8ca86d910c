// Coplanar faces that overlap: one keeps the overlap (a lamp, else a face lying wholly on
// faces of other surfaces, else the earlier), the others are cut to what it leaves; those of
// two surfaces are said too. Of coincident copies one is kept.
// Reference: the exact area of the faces' union, and their own corners where nothing overlaps.
#include "Mesh/CoincidentCopies.h"
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
      polygons.Connectivity.push_back(static_cast<int>(points.size()));
      points.push_back(p);
    }
    polygons.Offsets.push_back(static_cast<int>(polygons.Connectivity.size()));
    polygons.Source.push_back(static_cast<int>(keys.size()));
    keys.push_back(key);
  }

  /// An axis-aligned rectangle at height z, wound to face +z.
  void Rectangle(double x0, double x1, double y0, double y1, int key = 0, double z = 0)
  {
    Add({ { x0, y0, z }, { x1, y0, z }, { x1, y1, z }, { x0, y1, z } }, key);
  }

  OverlapCuts Cut(const std::vector<char>& lamps = {}) { return CutOverlaps(points, keys, lamps, 1e-9, polygons); }

  double Area() const
  {
    const std::vector<Vec3>& at = PointsOf(polygons, points);
    double area = 0;
    for (size_t i = 0; i + 1 < polygons.Offsets.size(); ++i)
    {
      const std::vector<Vec3> loop = GatherLoop(at, polygons.Offsets, polygons.Connectivity, static_cast<int>(i));
      area += PolygonArea(loop.data(), static_cast<int>(loop.size()));
    }
    return area;
  }

  /// The sum of the faces' normals times their areas: all face +z when equal to the area.
  double FacingUp() const
  {
    const std::vector<Vec3>& at = PointsOf(polygons, points);
    double up = 0;
    for (size_t i = 0; i + 1 < polygons.Offsets.size(); ++i)
    {
      const std::vector<Vec3> loop = GatherLoop(at, polygons.Offsets, polygons.Connectivity, static_cast<int>(i));
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
  f.Rectangle(1, 2, 1, 2); // wholly under the first
  f.Rectangle(0, 4, 0, 4); // a copy the copies pass would drop, here cut away
  f.Rectangle(3, 5, 3, 5); // a corner outside
  const OverlapCuts cuts = f.Cut();
  EXPECT_EQ(cuts.Covered, (std::vector<int>{ 1, 2 }));
  EXPECT_EQ(cuts.Trimmed, std::vector<int>{ 3 });
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

TEST(OverlapCuts, OtherSurfacesAreCutAndSaidOtherSidesAndPlanesLeftAlone)
{
  Faces f;
  f.Rectangle(0, 2, 0, 1, 0);
  f.Rectangle(1, 3, 0, 1, 1);       // another material: cut where the earlier lies, and said
  f.Rectangle(1, 3, 0, 1, 0, 1e-3); // a millimetre above: a layer of its own
  f.Add({ { 1, 0, 0 }, { 1, 1, 0 }, { 3, 1, 0 }, { 3, 0, 0 } }); // facing down: the other side
  const OverlapCuts cuts = f.Cut();
  EXPECT_EQ(cuts.Trimmed, std::vector<int>{ 1 });
  EXPECT_TRUE(cuts.Covered.empty());
  EXPECT_EQ(cuts.Differing, (std::vector<std::pair<int, int>>{ { 0, 1 } }));
  EXPECT_NEAR(f.Area(), 2.0 + 1.0 + 2.0 + 2.0, 1e-12); // the plane z = 0, facing up: 3 = its union
}

TEST(OverlapCuts, OneOrderForEveryMaterialLeavesNoHoleAndNoDoubleCover)
{
  // A wall, a patch of it drawn again, a poster over both. A rule that let the smaller of
  // two materials win made a cycle with the earlier-wins rule of one material and left
  // (1.5, 1.5) to none; both kept made it twice. One order (KeepingOrder): the poster lies
  // on the wall's material; the patch lies on its own wall, so it is part of it and does not
  // count as lying on the poster. The poster keeps, the wall is cut around it, the patch
  // under it left out.
  Faces f;
  f.Rectangle(0, 4, 0, 3, 0);
  f.Rectangle(1, 2, 1, 2, 0);
  f.Rectangle(0.5, 2.5, 0.5, 2.5, 1);
  Faces lit = f; // the same, the poster a lamp panel
  const OverlapCuts cuts = f.Cut();
  EXPECT_EQ(cuts.Trimmed, (std::vector<int>{ 0 }));
  EXPECT_EQ(cuts.Covered, (std::vector<int>{ 1 }));
  EXPECT_NEAR(f.Area(), 12.0, 1e-12); // the wall's, each point once
  EXPECT_TRUE(cuts.Differing.empty());
  EXPECT_EQ(cuts.OnTop, (std::vector<std::pair<int, int>>{ { 2, 0 }, { 2, 1 } })); // the poster lies on the wall
  // A lamp keeps the overlap wherever it comes: the wall is cut around it.
  const OverlapCuts around = lit.Cut({ 0, 0, 1 });
  EXPECT_EQ(around.Trimmed, std::vector<int>{ 0 });
  EXPECT_EQ(around.Covered, std::vector<int>{ 1 });
  EXPECT_NEAR(lit.Area(), 12.0, 1e-12);
  EXPECT_EQ(around.Differing, (std::vector<std::pair<int, int>>{ { 2, 0 }, { 2, 1 } }));
}

TEST(OverlapCuts, APosterKeepsItsPlaceOnTheWallDrawnBeforeOrAfter)
{
  // A poster of another material lying wholly on a wall: the poster is what is seen, the
  // wall gives way around it, whichever of the two the file gives first (the earlier one
  // kept the overlap before, and a poster drawn after its wall was cut away).
  for (bool posterFirst : { false, true })
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
    const int poster = posterFirst ? 0 : 1, wall = 1 - poster;
    const OverlapCuts cuts = f.Cut();
    EXPECT_EQ(cuts.Trimmed, std::vector<int>{ wall });
    EXPECT_TRUE(cuts.Covered.empty());
    EXPECT_TRUE(cuts.Differing.empty());
    EXPECT_EQ(cuts.OnTop, (std::vector<std::pair<int, int>>{ { poster, wall } })); // said as meant
    EXPECT_NEAR(f.Area(), 12.0, 1e-12); // the wall less the poster, and the poster whole
  }
  // Triangulated, as most exports give them: the wall's two triangles and the poster's,
  // the poster over the wall's diagonal, lying on neither triangle alone but on the wall.
  for (bool posterFirst : { false, true })
  {
    Faces t;
    const auto wall = [&t]() {
      t.Add({ { 0, 0, 0 }, { 4, 0, 0 }, { 4, 3, 0 } }, 0);
      t.Add({ { 0, 0, 0 }, { 4, 3, 0 }, { 0, 3, 0 } }, 0);
    };
    if (!posterFirst)
    {
      wall();
    }
    t.Add({ { 1.5, 1, 0 }, { 2.5, 1, 0 }, { 2.5, 2, 0 } }, 1);
    t.Add({ { 1.5, 1, 0 }, { 2.5, 2, 0 }, { 1.5, 2, 0 } }, 1);
    if (posterFirst)
    {
      wall();
    }
    const OverlapCuts cuts = t.Cut();
    EXPECT_TRUE(cuts.Covered.empty());
    EXPECT_EQ(cuts.Trimmed, posterFirst ? (std::vector<int>{ 2, 3 }) : (std::vector<int>{ 0, 1 }));
    EXPECT_NEAR(t.Area(), 12.0, 1e-12);
  }
  // A poster hanging over the wall's edge does not lie on it: the earlier keeps, as before.
  Faces over;
  over.Rectangle(0, 4, 0, 3, 0);
  over.Rectangle(3.5, 4.5, 1, 2, 1);
  const OverlapCuts cuts = over.Cut();
  EXPECT_EQ(cuts.Trimmed, std::vector<int>{ 1 });
  EXPECT_NEAR(over.Area(), 12.0 + 0.5, 1e-12);
}

TEST(OverlapCuts, LampsOfTwoLightsAreNotCutTheCeilingIs)
{
  // Two lamp panels of different lights half over each other in the ceiling's plane (two
  // circuits of one fixture): cut, one would emit half the power it was given. Both stay
  // whole and are said; the ceiling is cut around both.
  Faces f;
  f.Rectangle(0, 2, 0, 1, 1);
  f.Rectangle(1, 3, 0, 1, 2);
  f.Rectangle(0, 4, 0, 2, 0);
  const OverlapCuts cuts = f.Cut({ 1, 1, 0 });
  EXPECT_EQ(cuts.LampsKept, (std::vector<std::pair<int, int>>{ { 0, 1 } }));
  EXPECT_EQ(cuts.Trimmed, std::vector<int>{ 2 });
  EXPECT_EQ(cuts.Differing, (std::vector<std::pair<int, int>>{ { 0, 2 }, { 1, 2 } }));
  EXPECT_NEAR(f.Area(), 2.0 + 2.0 + (8.0 - 3.0), 1e-12); // the lamps whole, the ceiling less their union
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

TEST(CoincidentCopies, OneOfEachSetIsKeptALampOverTheSurfaceItDoubles)
{
  // A ceiling tile drawn three times (CAD and BIM exports repeat faces): the same material
  // twice, another once. Each copy would receive the full light: one is kept, the earlier.
  Faces f;
  f.Rectangle(0, 1, 0, 1, 0);
  f.Rectangle(0, 1, 0, 1, 0);
  f.Add({ { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 0 } }, 1); // the same corners from another start
  f.Rectangle(2, 3, 0, 1, 1);                                      // elsewhere: not a copy
  PairedPolygons copies = f.polygons;
  CoincidentCopies found = DropCoincidentCopies(f.points, f.keys, {}, 1e-9, copies);
  EXPECT_EQ(copies.Source, (std::vector<int>{ 0, 3 }));
  EXPECT_EQ(found.Dropped, std::vector<int>{ 1 });
  EXPECT_EQ(found.Differing, (std::vector<std::pair<int, int>>{ { 0, 2 } }));
  // The third copy a lamp (a lamp panel drawn over the tile it replaces): the lamp is kept,
  // the tiles before it left out, so the lamp still shines and nothing is lit twice.
  copies = f.polygons;
  found = DropCoincidentCopies(f.points, f.keys, { 0, 0, 1, 0 }, 1e-9, copies);
  EXPECT_EQ(copies.Source, (std::vector<int>{ 2, 3 }));
  EXPECT_TRUE(found.Dropped.empty());
  EXPECT_EQ(found.Differing, (std::vector<std::pair<int, int>>{ { 2, 0 }, { 2, 1 } }));
  // Two lamps of different lights in one place (two circuits of one fixture) over a tile:
  // both stay, each a light of its own, and are said; the tile goes.
  Faces h;
  h.Rectangle(0, 1, 0, 1, 0);
  h.Rectangle(0, 1, 0, 1, 1);
  h.Rectangle(0, 1, 0, 1, 2);
  found = DropCoincidentCopies(h.points, h.keys, { 0, 1, 1 }, 1e-9, h.polygons);
  EXPECT_EQ(h.polygons.Source, (std::vector<int>{ 1, 2 }));
  EXPECT_EQ(found.Differing, (std::vector<std::pair<int, int>>{ { 1, 0 } }));
  EXPECT_EQ(found.LampsKept, (std::vector<std::pair<int, int>>{ { 1, 2 } }));
  // The facing side tells copies apart: the tile turned over is a face of its own.
  Faces g;
  g.Rectangle(0, 1, 0, 1, 0);
  g.Add({ { 0, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 }, { 1, 0, 0 } }, 1);
  found = DropCoincidentCopies(g.points, g.keys, {}, 1e-9, g.polygons);
  EXPECT_EQ(g.polygons.Source, (std::vector<int>{ 0, 1 }));
  EXPECT_TRUE(found.Differing.empty());
}
