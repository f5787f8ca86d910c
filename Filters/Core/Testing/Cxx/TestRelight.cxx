#include "Relight/Exposure.h"
#include "Relight/Relight.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

TEST(Relight, IsTheWeightedSumAndIgnoresDisabledLights)
{
  const std::vector<float> a = { 1, 2, 3, 0.5f, 0.25f, 0.125f };
  const std::vector<float> b = { 10, 20, 30, 40, 50, 60 };
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<float> off = { nan, nan, nan, nan, nan, nan };
  const std::vector<double> weights = { 2, 1, 0.5, 0.1, 0.2, 0.3, 0, 0, 0 };
  std::vector<float> out(6);
  radiosity::CombineLights<float, float>({ a.data(), b.data(), off.data() }, weights, 2, out.data());
  for (int j = 0; j < 2; ++j)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double expected = weights[c] * a[3 * j + c] + weights[3 + c] * b[3 * j + c];
      EXPECT_NEAR(out[3 * j + c], expected, 1e-6 * expected);
    }
  }
}

TEST(Relight, TheMeterWeighsSurfacesByArea)
{
  // A 99.5 m^2 wall at luminance 1 and a hundred 0.01 m^2 fittings at 10: by count the
  // fittings are the brightest 99 %, so the wall came out at 8 % of white; by area they are
  // under 1 %, and the wall is metered to 80 % of white.
  std::vector<float> rgb(3 * 101, 10.0f);
  std::fill(rgb.begin(), rgb.begin() + 3, 1.0f);
  std::vector<double> area(101, 0.01);
  area[0] = 99.5;
  EXPECT_NEAR(radiosity::MeteredExposure(rgb.data(), 101, {}, 1.0, area), 0.8, 1e-12);
  EXPECT_NEAR(radiosity::MeteredExposure(rgb.data(), 101, {}), 0.08, 1e-12);
  EXPECT_EQ(radiosity::MeteredExposure(rgb.data(), 0, {}, 0.0, {}), 0.0); // nothing lit: `unlit`
}

TEST(Relight, DisplayCurveIsMonotoneAndClamped)
{
  EXPECT_EQ(radiosity::ToDisplay(0, 1), 0);
  EXPECT_EQ(radiosity::ToDisplay(-1, 1), 0);
  EXPECT_EQ(radiosity::ToDisplay(std::nan(""), 1), 0);
  EXPECT_EQ(radiosity::ToDisplay(1, 1), 255);
  EXPECT_EQ(radiosity::ToDisplay(50, 1), 255);
  EXPECT_EQ(radiosity::ToDisplay(0.5, 2), 255);
  EXPECT_EQ(radiosity::ToDisplay(0.2159, 1), 128); // sRGB code 128 is linear 0.21586
  int last = 0;
  for (double v = 0; v < 1.2; v += 0.01)
  {
    const int d = radiosity::ToDisplay(v, 1);
    EXPECT_GE(d, last);
    last = d;
  }
}
