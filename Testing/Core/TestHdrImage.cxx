#include "HdrImage.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace radiosity;

TEST(HdrImage, RayCastAndExrRoundTripKeepLinearValues)
{
  // A 2 x 2 square facing the camera, with radiosity rising from left (1) to right (3).
  SceneMesh mesh;
  mesh.points = { { -1, -1, 0 }, { 1, -1, 0 }, { 1, 1, 0 }, { -1, 1, 0 } };
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
