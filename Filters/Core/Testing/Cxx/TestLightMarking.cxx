#include "Import/LightMarking.h"
#include "Geometry/Polygon.h"

#include <gtest/gtest.h>

using namespace radiosity;

TEST(LightMarking, PatternsMatchLikeAShellIgnoringCase)
{
  EXPECT_TRUE(MatchesPattern("lamp*", "Lamp_Kitchen"));
  EXPECT_TRUE(MatchesPattern("*glas*", "Fensterglas"));
  EXPECT_TRUE(MatchesPattern("?ulb", "Bulb"));
  EXPECT_TRUE(MatchesPattern("*", ""));
  EXPECT_FALSE(MatchesPattern("lamp", "Lamp2"));
  EXPECT_FALSE(MatchesPattern("*a*b", "xaxc"));
  EXPECT_TRUE(MatchesPattern("a*b*c", "aXbYbZc"));
}

TEST(LightMarking, AreaLightsFaceTheirNormalWithTheirArea)
{
  for (const Vec3& normal : { Vec3{ 0, 0, -1 }, Vec3{ 1, 2, 3 }, Vec3{ 0, 5, 0 } })
  {
    AreaLight rectangle{ "r", AreaShape::Rectangle, { 1, 2, 3 }, normal, 0.5, 0.2 };
    std::vector<Vec3> loop;
    ASSERT_EQ(AreaLightLoop(rectangle, loop), "");
    const Vec3 newell = NewellVector(loop.data(), 4);
    EXPECT_NEAR(0.5 * Norm(newell), 0.1, 1e-12);                      // area w x h
    EXPECT_NEAR(Dot(Normalized(newell), Normalized(normal)), 1, 1e-12); // front faces the normal
    EXPECT_NEAR(Norm(PolygonCentroid(loop.data(), 4) - rectangle.Centre), 0, 1e-12);
    AreaLight disk{ "d", AreaShape::Disk, { 0, 0, 0 }, normal, 0.4 };
    ASSERT_EQ(AreaLightLoop(disk, loop), "");
    EXPECT_EQ(loop.size(), 32u);
    EXPECT_NEAR(PolygonArea(loop.data(), 32), 3.14159265358979 * 0.04, 1e-12); // pi R^2
    EXPECT_GT(Dot(NewellVector(loop.data(), 32), normal), 0);
  }
  std::vector<Vec3> loop;
  EXPECT_NE(AreaLightLoop(AreaLight{ "x", AreaShape::Rectangle, {}, { 0, 0, 0 } }, loop).find("'x'"), std::string::npos);
  EXPECT_NE(AreaLightLoop(AreaLight{ "y", AreaShape::Disk, {}, { 0, 0, 1 }, -1 }, loop).find("positive size"), std::string::npos);
}

TEST(LightMarking, CompactLightsClosesGapsAndDropsEmptyLights)
{
  std::vector<int> ids = { -1, 2, 2, 0, -1, 3 };
  std::vector<std::string> names = { "A", "B", "C", "D" };
  CompactLights(ids, names);
  EXPECT_EQ(ids, (std::vector<int>{ -1, 1, 1, 0, -1, 2 }));
  EXPECT_EQ(names, (std::vector<std::string>{ "A", "C", "D" }));
}
