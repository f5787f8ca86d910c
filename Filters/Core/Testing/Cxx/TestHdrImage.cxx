#include "Image/HdrImage.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace radiosity;

TEST(HdrImage, RayCastAndExrRoundTripKeepLinearValues)
{
  // A 2 x 2 square facing the camera, with radiosity rising from left (1) to right (3).
  SceneMesh mesh;
  mesh.Points = { { -1, -1, 0 }, { 1, -1, 0 }, { 1, 1, 0 }, { -1, 1, 0 } };
  mesh.AddPolygon({ 0, 1, 2, 3 });
  const std::vector<Vec3> values = { { 1, 1, 1 }, { 3, 3, 3 }, { 3, 3, 3 }, { 1, 1, 1 } };
  Visibility scene(mesh);
  ASSERT_EQ(scene.Error(), "");
  PinholeCamera camera;
  camera.Position = { 0, 0, 5 };
  camera.Width = 65;
  camera.Height = 33;
  camera.ViewAngle = 40;
  const std::vector<float> rgb = RenderRadiosity(scene, values, camera);
  const std::string path = ::testing::TempDir() + "radiosity_roundtrip.exr";
  ASSERT_EQ(WriteExr(path, camera.Width, camera.Height, rgb), "");
  int w = 0, h = 0;
  std::vector<float> back;
  ASSERT_EQ(ReadExr(path, w, h, back), "");
  std::remove(path.c_str());
  ASSERT_EQ(w, 65);
  ASSERT_EQ(h, 33);
  // The centre pixel sees x = 0: halfway between 1 and 3 is 2, exact in half precision.
  const float* centre = &back[3 * (16 * 65 + 32)];
  EXPECT_NEAR(centre[0], 2.0f, 1e-3f);
  // Values above 1 survive (this is the point of HDR output), corners miss the square.
  float peak = 0;
  for (float v : back)
  {
    peak = std::max(peak, v);
  }
  EXPECT_GT(peak, 2.5f);
  EXPECT_EQ(back[0], 0.0f);
  // Linear in x across the square: pixel columns symmetric about the centre average to 2.
  const float* left = &back[3 * (16 * 65 + 27)];
  const float* right = &back[3 * (16 * 65 + 37)];
  EXPECT_NEAR(0.5f * (left[0] + right[0]), 2.0f, 2e-3f);
  EXPECT_LT(left[0], right[0]);
}

TEST(HdrImage, LayeredExrKeepsEveryLightInFloat)
{
  // Two lights' pictures and their sum, 3 x 2 pixels, with values half floats would round.
  const int w = 3, h = 2;
  std::vector<float> a(3 * w * h), b(3 * w * h), sum(3 * w * h);
  for (size_t i = 0; i < a.size(); ++i)
  {
    a[i] = 1.0f + 1e-5f * static_cast<float>(i);
    b[i] = 1e-4f * static_cast<float>(i * i) + 12345.678f;
    sum[i] = a[i] + b[i];
  }
  const std::string path = ::testing::TempDir() + "radiosity_layers.exr";
  ASSERT_EQ(WriteExrLayers(path, w, h, { "", "Warm White", "Lamp_2" }, { sum, a, b }), "");
  int rw = 0, rh = 0;
  std::vector<float> back;
  ASSERT_EQ(ReadExrLayer(path, "Warm White", rw, rh, back), "");
  EXPECT_EQ(rw, w);
  EXPECT_EQ(rh, h);
  EXPECT_EQ(back, a); // bit for bit: 32-bit float channels
  ASSERT_EQ(ReadExrLayer(path, "Lamp_2", rw, rh, back), "");
  EXPECT_EQ(back, b);
  ASSERT_EQ(ReadExrLayer(path, "", rw, rh, back), "");
  EXPECT_EQ(back, sum);
  EXPECT_NE(ReadExrLayer(path, "Nobody", rw, rh, back).find("no channel Nobody.R"), std::string::npos);
  std::remove(path.c_str());
  EXPECT_NE(WriteExrLayers(path, w, h, { "x" }, { std::vector<float>(5) }).find("do not match"), std::string::npos);
}

TEST(HdrImage, PacketsOfRaysHitWhatSingleRaysHit)
{
  // A box of 6 x 6 x 6 quads seen from inside at grazing and edge-on angles: every ray of a
  // packet (with a last, partial packet) reports the ray's own single-ray hit.
  SceneMesh mesh;
  const int n = 6;
  auto face = [&](const Vec3& o, const Vec3& u, const Vec3& v) {
    const int base = static_cast<int>(mesh.Points.size());
    for (int j = 0; j <= n; ++j)
    {
      for (int i = 0; i <= n; ++i)
      {
        mesh.Points.push_back(o + u * (double(i) / n) + v * (double(j) / n));
      }
    }
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const int a = base + j * (n + 1) + i;
        mesh.AddPolygon({ a, a + 1, a + n + 2, a + n + 1 });
      }
    }
  };
  face({ 0, 0, 0 }, { 0, 1, 0 }, { 1, 0, 0 });
  face({ 0, 0, 1 }, { 1, 0, 0 }, { 0, 1, 0 });
  face({ 0, 0, 0 }, { 1, 0, 0 }, { 0, 0, 1 });
  face({ 0, 1, 0 }, { 0, 0, 1 }, { 1, 0, 0 });
  face({ 0, 0, 0 }, { 0, 0, 1 }, { 0, 1, 0 });
  face({ 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 });
  const Visibility scene(mesh);
  ASSERT_EQ(scene.Error(), "");
  const Vec3 origin{ 0.3, 0.6, 0.45 };
  std::vector<Vec3> directions;
  for (int k = 0; k < 301; ++k)
  {
    const double a = 0.37 * k, b = 0.011 * k - 1.5;
    directions.push_back({ std::cos(a) * std::cos(b), std::sin(a) * std::cos(b), std::sin(b) });
  }
  int compared = 0;
  for (size_t first = 0; first < directions.size(); first += Visibility::PacketSize)
  {
    const int count = static_cast<int>(std::min<size_t>(Visibility::PacketSize, directions.size() - first));
    Visibility::Hit hits[Visibility::PacketSize];
    bool found[Visibility::PacketSize];
    scene.IntersectPacket(origin, &directions[first], count, hits, found);
    for (int i = 0; i < count; ++i)
    {
      Visibility::Hit single;
      ASSERT_EQ(found[i], scene.Intersect(origin, directions[first + i], single));
      ASSERT_TRUE(found[i]) << "a ray from inside a closed box escaped";
      EXPECT_EQ(hits[i].Polygon, single.Polygon);
      EXPECT_EQ(hits[i].U, single.U);
      EXPECT_EQ(hits[i].V, single.V);
      EXPECT_EQ(hits[i].Distance, single.Distance);
      ++compared;
    }
  }
  EXPECT_EQ(compared, 301);
  // Shadow rays in packets: segments from points on the floor to one light above a wall
  // standing inside the box, as the moving-light shader casts them.
  SceneMesh walled = mesh;
  const int base = static_cast<int>(walled.Points.size());
  walled.Points.insert(walled.Points.end(), { { 0.5, 0, 0 }, { 0.5, 1, 0 }, { 0.5, 1, 0.6 }, { 0.5, 0, 0.6 } });
  walled.AddPolygon({ base, base + 1, base + 2, base + 3 });
  const Visibility withWall(walled);
  const Vec3 light{ 0.2, 0.5, 0.9 };
  std::vector<Vec3> floor;
  for (int k = 0; k < 203; ++k)
  {
    floor.push_back({ 0.005 * k, 0.3 + 0.002 * k, 1e-6 });
  }
  int blockedCount = 0;
  for (size_t first = 0; first < floor.size(); first += Visibility::PacketSize)
  {
    const int count = static_cast<int>(std::min<size_t>(Visibility::PacketSize, floor.size() - first));
    bool blocked[Visibility::PacketSize];
    withWall.OccludedPacket(&floor[first], light, count, 1e-6, blocked);
    for (int i = 0; i < count; ++i)
    {
      EXPECT_EQ(blocked[i], withWall.Occluded(floor[first + i], light, 1e-6)) << "point " << first + i;
      blockedCount += blocked[i] ? 1 : 0;
    }
  }
  EXPECT_GT(blockedCount, 50); // behind the wall, seen from the light
  EXPECT_LT(blockedCount, 203);
}

TEST(HdrImage, AFolderThatIsNotThereIsNamed)
{
  // The writers' temporary file would otherwise fail as "cannot open <path>.part".
  const std::string folder = ::testing::TempDir() + "no_such_folder_for_radiosity";
  const std::string error = WriteExr(folder + "/view.exr", 2, 2, std::vector<float>(12, 1.0f));
  EXPECT_NE(error.find("the folder '" + folder + "' does not exist"), std::string::npos) << error;
  std::FILE* part = std::fopen((folder + "/view.exr.part").c_str(), "rb");
  EXPECT_EQ(part, nullptr);
  // A file where the folder should be is not called missing: the open's own error stands.
  const std::string file = ::testing::TempDir() + "radiosity_not_a_folder";
  std::FILE* plain = std::fopen(file.c_str(), "wb");
  ASSERT_NE(plain, nullptr);
  std::fclose(plain);
  const std::string inside = WriteExr(file + "/view.exr", 2, 2, std::vector<float>(12, 1.0f));
  EXPECT_FALSE(inside.empty());
  EXPECT_EQ(inside.find("does not exist"), std::string::npos) << inside;
  std::remove(file.c_str());
}
