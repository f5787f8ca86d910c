#include "Relight/LightRig.h"
#include "Relight/LightScenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

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

TEST(LightRig, TheRowIsReadAndWrittenThroughItsDeclaration)
{
  // Each column writes what it reads (a setting set part by part through the table is
  // the setting written by hand), a part is one heading's cells, set together or not at
  // all, and only an on/off that does not read leaves the row out.
  LightSetting bySetters;
  const double values[kSettingRowCells] = { 0, 0.25, 0.5, 0.75, 3.5, 0 };
  for (int c = 1; c < kSettingRowCells; ++c)
  {
    kSettingRowColumns[c].Set(bySetters, values[c]);
    EXPECT_TRUE(kSettingRowColumns[c].Has(bySetters)) << kSettingRowColumns[c].Name;
    EXPECT_DOUBLE_EQ(kSettingRowColumns[c].Get(bySetters), values[c]) << kSettingRowColumns[c].Name;
  }
  EXPECT_EQ(SettingRow("L", bySetters), (std::vector<std::string>{ "L", "0.25", "0.5", "0.75", "3.5", "0" }));
  std::set<std::string> headings;
  for (const SettingColumn& column : kSettingRowColumns)
  {
    headings.insert(column.Heading);
    EXPECT_TRUE(column.Kind == RowCell::Text || (column.Get && column.Set && column.Has)) << column.Name;
  }
  EXPECT_EQ(headings, (std::set<std::string>{ "Light", "Color", "Intensity", "On" }));
  const std::vector<NamedSetting> half = ParseSettingRows({ "L", "0.5", "x", "0.2", "2", "off" });
  ASSERT_EQ(half.size(), 1u);
  EXPECT_FALSE(half[0].Setting.HasColor); // one of its three cells does not read: none is taken
  EXPECT_DOUBLE_EQ(half[0].Setting.Color.x, 1.0);
  EXPECT_TRUE(half[0].Setting.HasIntensity && !half[0].Setting.Enabled);
}

TEST(LightRig, LightScenesDimGroupsOfLightsAndTheScheduleBlendsThem)
{
  std::vector<LightSceneRow> rows;
  const std::string file = "# scene, lights, dimming %, r, g, b, on\n"
                           "Meeting, Ovni*, 100, , , , on\n"
                           "Meeting, Erco*, 30, 1, 0.8, 0.6, on\n"
                           "Film, *, 10, , , , on\n"
                           "Film, Erco1, 0, , , , off   # the one by the screen\n";
  ASSERT_EQ(ParseLightScenes(file, "scenes.csv", rows), "");
  EXPECT_EQ(LightSceneNames(rows), (std::vector<std::string>{ "Meeting", "Film" }));
  LightRig rig;
  rig.Scenes = rows;
  rig.ActiveScene = "Meeting";
  const std::vector<std::string> names{ "Ovni1", "Erco1", "Erco2", "Panel" };
  // The panel's default is an Emission of 20: its strength; the scene dims a share of it.
  const std::vector<Vec3> defaults{ { 1, 1, 1 }, { 1, 1, 1 }, { 1, 1, 1 }, { 20, 20, 20 } };
  std::vector<LightSetting> effective;
  std::vector<std::string> warnings;
  ASSERT_EQ(rig.Resolve(names, defaults, 0, effective, warnings), "");
  EXPECT_DOUBLE_EQ(effective[0].Intensity, 1.0);
  EXPECT_DOUBLE_EQ(effective[1].Intensity, 0.3);
  EXPECT_DOUBLE_EQ(effective[1].Color.y, 0.8);
  EXPECT_DOUBLE_EQ(effective[3].Intensity, 20.0); // the scene does not set it
  rig.ActiveScene = "Film";
  ASSERT_EQ(rig.Resolve(names, defaults, 0, effective, warnings), "");
  EXPECT_DOUBLE_EQ(effective[3].Intensity, 2.0); // 10 % of 20
  EXPECT_FALSE(effective[1].Enabled);
  EXPECT_TRUE(effective[2].Enabled);
  // By name over the scene, the schedule over both: from Meeting at t = 0 to Film at t = 10.
  rig.ActiveScene.clear();
  rig.Schedule = { { 0, "scene:Meeting" }, { 10, "scene:Film" } };
  ASSERT_EQ(rig.Resolve(names, defaults, 5, effective, warnings), "");
  EXPECT_DOUBLE_EQ(effective[0].Intensity, 0.55); // halfway from 100 % to 10 %
  EXPECT_DOUBLE_EQ(effective[2].Intensity, 0.2);  // halfway from 30 % to 10 %
  EXPECT_DOUBLE_EQ(effective[3].Intensity, 2.0);  // Film alone sets it: held
  EXPECT_TRUE(warnings.empty());
  // A scene no row defines is an error; a keyframe of one is a warning.
  rig.ActiveScene = "Party";
  EXPECT_EQ(rig.Resolve(names, defaults, 0, effective, warnings),
    "no light scene is called 'Party' (there are Meeting, Film)");
  rig.ActiveScene.clear();
  rig.Schedule = { { 0, "scene:Party" } };
  warnings.clear();
  ASSERT_EQ(rig.Resolve(names, defaults, 0, effective, warnings), "");
  ASSERT_EQ(warnings.size(), 1u);
  // Bad rows say where.
  EXPECT_EQ(ParseLightScenes("Meeting, Ovni*, lots, , , , on\n", "s.csv", rows),
    "s.csv:1: the dimming 'lots' is not a percentage of 0 or more");
  EXPECT_EQ(ParseLightScenes("\nMeeting, Ovni*, 50, 1, 1, , on\n", "s.csv", rows),
    "s.csv:2: the color '1, 1, ' is not three numbers of 0 or more");
  EXPECT_EQ(ParseLightScenes("Meeting, Ovni*, 50\n", "s.csv", rows), "s.csv:1: 3 cells, not 7 (scene, lights, dimming %, r, g, b, on)");
  EXPECT_EQ(ParseLightScenes("# nothing\n", "s.csv", rows), "s.csv: no light scene in it (rows of: scene, lights, dimming %, r, g, b, on)");
}
