#include "Relight/LightRig.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace radiosity;

namespace
{

LightSetting Intensity(double value)
{
  LightSetting s;
  s.HasIntensity = true;
  s.Intensity = value;
  return s;
}

} // namespace

TEST(LightRig, PrecedenceIsDefaultsNameScheduleIndex)
{
  LightRig rig;
  const std::vector<std::string> names = { "Warm", "Cool" };
  const std::vector<Vec3> defaults = { { 1, 0.8, 0.6 }, { 0.5, 0.6, 1 } };
  std::vector<LightSetting> effective;
  std::vector<std::string> warnings;
  ASSERT_EQ(rig.Resolve(names, defaults, 0, effective, warnings), "");
  EXPECT_DOUBLE_EQ(effective[0].Color.y, 0.8); // the default color, intensity 1, on
  EXPECT_DOUBLE_EQ(effective[1].Intensity, 1);
  rig.ByName["Warm"] = Intensity(2);
  rig.Schedule.push_back({ 0, "Warm", { 1, 1, 1 }, 3, true });
  rig.Schedule.push_back({ 10, "Warm", { 1, 1, 1 }, 5, false });
  ASSERT_EQ(rig.Resolve(names, defaults, 5, effective, warnings), "");
  EXPECT_DOUBLE_EQ(effective[0].Intensity, 4);   // the schedule beats the name, interpolated
  EXPECT_TRUE(effective[0].Enabled);             // on/off held from the keyframe before
  EXPECT_DOUBLE_EQ(effective[0].Color.z, 1);     // the keyframe's color
  rig.ByIndex[0] = Intensity(7);
  ASSERT_EQ(rig.Resolve(names, defaults, 5, effective, warnings), "");
  EXPECT_DOUBLE_EQ(effective[0].Intensity, 7);   // the index beats the schedule
  ASSERT_EQ(rig.Resolve(names, defaults, 12, effective, warnings), "");
  EXPECT_FALSE(effective[0].Enabled);            // after the last keyframe: held
  EXPECT_EQ(rig.KeyframeTimes(), (std::vector<double>{ 0, 10 }));
}

TEST(LightRig, ADefaultIsAHueTimesAnIntensity)
{
  // An area light of intensity 20 (Emission 20 x its color): set to 40 it shines at 40, set
  // to white it keeps 20 (it shone at 800 and dropped to 1 when the default was a color).
  LightRig rig;
  const std::vector<std::string> names = { "Key" };
  const std::vector<Vec3> defaults = { { 20, 10, 5 } };
  std::vector<LightSetting> effective;
  std::vector<std::string> warnings;
  ASSERT_EQ(rig.Resolve(names, defaults, 0, effective, warnings), "");
  EXPECT_DOUBLE_EQ(effective[0].Intensity, 20);
  EXPECT_DOUBLE_EQ(effective[0].Color.y, 0.5);
  EXPECT_DOUBLE_EQ(effective[0].Weight().x, 20); // the picture at the defaults is the Emission
  rig.ByIndex[0] = Intensity(40);
  ASSERT_EQ(rig.Resolve(names, defaults, 0, effective, warnings), "");
  EXPECT_DOUBLE_EQ(effective[0].Weight().y, 20);
  LightSetting white;
  white.HasColor = true;
  rig.ByIndex[0] = white;
  ASSERT_EQ(rig.Resolve(names, defaults, 0, effective, warnings), "");
  EXPECT_DOUBLE_EQ(effective[0].Weight().z, 20);
  const std::vector<Vec3> dark = { { 0, 0, 0 } };
  ASSERT_EQ(LightRig().Resolve(names, dark, 0, effective, warnings), "");
  EXPECT_DOUBLE_EQ(effective[0].Weight().x, 0); // no Emission: dark until given a color
}

TEST(LightRig, WeightsSplitIndirectLight)
{
  LightSetting on, off;
  on.Color = { 1, 0.5, 0.25 };
  on.Intensity = 4;
  off.Enabled = false;
  EXPECT_EQ(LightWeights({ on, off }, 1.0), (std::vector<double>{ 4, 2, 1, 0, 0, 0 }));
  // s B_total + (1 - s) B_direct with s = 0.25.
  EXPECT_EQ(LightWeights({ on }, 0.25), (std::vector<double>{ 1, 0.5, 0.25, 3, 1.5, 0.75 }));
}

TEST(LightRig, BadValuesAreErrorsAndUnknownNamesWarn)
{
  LightRig rig;
  rig.ByIndex[1] = Intensity(-1);
  rig.ByName["Nobody"] = Intensity(1);
  rig.Schedule.push_back({ 0, "7", { 1, 1, 1 }, 1, true });
  std::vector<LightSetting> effective;
  std::vector<std::string> warnings;
  const std::string error = rig.Resolve({ "A", "B" }, {}, 0, effective, warnings);
  EXPECT_NE(error.find("light 'B' has intensity -1"), std::string::npos);
  rig.ByIndex[1].Intensity = std::nan("");
  rig.ByIndex[1].HasEnabled = true;
  rig.ByIndex[1].Enabled = false; // a light switched off may hold anything
  ASSERT_EQ(rig.Resolve({ "A", "B" }, {}, 0, effective, warnings), "");
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("No light is named 'Nobody'"), std::string::npos);
  EXPECT_NE(warnings[1].find("names '7'"), std::string::npos);
}

TEST(LightRig, KeyframeRowsParse)
{
  LightKeyframe key;
  ASSERT_TRUE(ParseKeyframe({ " 2.5", "Warm, White", "1", "0.5", "0", "3", " OFF" }, key));
  EXPECT_EQ(key.Light, "Warm, White");
  EXPECT_DOUBLE_EQ(key.Time, 2.5);
  EXPECT_FALSE(key.Enabled);
  EXPECT_TRUE(ParseKeyframe({ "0", "A", "1", "1", "1", "1" }, key)); // enabled is optional
  EXPECT_FALSE(ParseKeyframe({ "0", "A", "1", "1", "1" }, key));
  EXPECT_FALSE(ParseKeyframe({ "0", "A", "1", "1", "1x", "1" }, key));
  EXPECT_FALSE(ParseKeyframe({ "0", "A", "1", "1", "1", "1", "maybe" }, key));
  EXPECT_FALSE(ParseKeyframe({ "nan", "A", "1", "1", "1", "1" }, key));
}

TEST(LightRig, SettingRowsReadBackAsWritten)
{
  LightSetting warm;
  warm.HasColor = warm.HasIntensity = warm.HasEnabled = true;
  warm.Color = { 1, 0.8, 0.6 };
  warm.Intensity = 2.5;
  LightSetting dimmed; // only the intensity given: the color stays the default
  dimmed.HasIntensity = dimmed.HasEnabled = true;
  dimmed.Intensity = 0.5;
  dimmed.Enabled = false;
  std::vector<std::string> flat = SettingInputRow("Warm, White", warm);
  const std::vector<std::string> second = SettingInputRow("B", dimmed);
  EXPECT_EQ(second, (std::vector<std::string>{ "B", "nan", "nan", "nan", "0.5", "0" }));
  flat.insert(flat.end(), second.begin(), second.end());
  flat.insert(flat.end(), { "C", "1", "1" }); // a part-row: dropped
  const std::vector<NamedSetting> rows = ParseSettingRows(flat);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].Name, "Warm, White");
  EXPECT_TRUE(rows[0].Setting.HasColor);
  EXPECT_DOUBLE_EQ(rows[0].Setting.Color.y, 0.8);
  EXPECT_DOUBLE_EQ(rows[0].Setting.Intensity, 2.5);
  EXPECT_TRUE(rows[0].Setting.Enabled);
  EXPECT_FALSE(rows[1].Setting.HasColor);
  EXPECT_TRUE(rows[1].Setting.HasIntensity);
  EXPECT_FALSE(rows[1].Setting.Enabled);
  // What SettingRow writes (every part a number) reads back whole.
  const std::vector<NamedSetting> full = ParseSettingRows(SettingRow("B", dimmed));
  ASSERT_EQ(full.size(), 1u);
  EXPECT_TRUE(full[0].Setting.HasColor && full[0].Setting.HasIntensity);
  EXPECT_TRUE(ParseSettingRows({ "", "1", "1", "1", "1", "1" }).empty());
  EXPECT_TRUE(ParseSettingRows({ "A", "1", "1", "1", "1", "maybe" }).empty());
  const std::vector<NamedSetting> two = ParseSettingRows({ "A", "1", "1", "1", "1", "2" }); // the server's integer: on
  ASSERT_EQ(two.size(), 1u);
  EXPECT_TRUE(two[0].Setting.Enabled);
}
