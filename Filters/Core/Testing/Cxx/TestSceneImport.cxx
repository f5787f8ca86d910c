#include "Import/SceneImport.h"
#include "Import/Wavefront.h"
#include "Base/Text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace radiosity;

namespace
{

/// A unit floor quad (material 0) and a small ceiling lamp (material 1), one object each.
RawScene FloorAndLamp()
{
  RawScene raw;
  raw.Points = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0.4, 0.4, 1 }, { 0.4, 0.6, 1 },
    { 0.6, 0.6, 1 }, { 0.6, 0.4, 1 } };
  raw.Connectivity = { 0, 1, 2, 3, 4, 5, 6, 7 };
  raw.Offsets = { 0, 4, 8 };
  raw.Material = { 0, 1 };
  raw.Object = { 0, 1 };
  raw.ObjectNames = { "Floor", "Lamp" };
  raw.Materials = { ImportMaterial{ "Oak", { 0.5, 0.4, 0.3 } }, ImportMaterial{ "Bulb", { 0.8, 0.8, 0.8 }, { 2, 2, 1.5 } } };
  return raw;
}

} // namespace

TEST(SceneImport, TextFromAFileBecomesValidUtf8ByteForByte)
{
  using radiosity::ValidUtf8;
  EXPECT_EQ(ValidUtf8("Lamp \xc3\xa9t\xc3\xa9 \xe2\x82\xac \xf0\x9f\x92\xa1"), "Lamp \xc3\xa9t\xc3\xa9 \xe2\x82\xac \xf0\x9f\x92\xa1");
  // Bytes that are not UTF-8 are read as Latin-1: K\xfc che and K\xf6 che stay two names.
  EXPECT_EQ(ValidUtf8("K\xfc" "che"), "K\xc3\xbc" "che");
  EXPECT_EQ(ValidUtf8("K\xf6" "che"), "K\xc3\xb6" "che");
  EXPECT_EQ(ValidUtf8("ro\xa6om.mtl"), "ro\xc2\xa6om.mtl");     // a lone continuation byte
  EXPECT_EQ(ValidUtf8("cut \xc3"), "cut \xc3\x83");             // a sequence cut at the end
  EXPECT_EQ(ValidUtf8("\xc0\xaf"), "\xc3\x80\xc2\xaf");          // an overlong '/'
  EXPECT_EQ(ValidUtf8("\xed\xa0\x80"), "\xc3\xad\xc2\xa0?");      // a UTF-16 surrogate
  EXPECT_EQ(ValidUtf8("\xf4\x90\x80\x80"), "\xc3\xb4???");         // past U+10FFFF
  EXPECT_EQ(ValidUtf8("\xe2\x82x"), "\xc3\xa2?x");                 // a bad second continuation
  EXPECT_EQ(ValidUtf8("trans\x85lation"), "trans?lation");          // U+0085 would end a line
  EXPECT_EQ(ValidUtf8(std::string("a\0b", 3)), std::string("a\0b", 3));
}

TEST(SceneImport, MtlGivesDiffuseEmissiveAndTextures)
{
  std::vector<ImportMaterial> m;
  const std::string text = "# comment\r\nnewmtl Kiefer, glänzend\r\nKd 0.5 0.4 0.3\r\nKs 1 1 1\r\n"
                           "newmtl Lamp\nKe 4 4 3\nKd 0.2\nmap_Kd -s 1 1 1 wood grain.png\nmap_Ke -o 0 0 0 glow.png\n"
                           "newmtl Kiefer, glänzend\nKd 0 0 0\n";
  ASSERT_EQ(ParseMtl(text, m), "");
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].Name, "Kiefer, glänzend");
  EXPECT_DOUBLE_EQ(m[0].Diffuse.y, 0.4);            // the first definition of a repeated name wins
  EXPECT_DOUBLE_EQ(m[1].Emissive.z, 3);
  EXPECT_DOUBLE_EQ(m[1].Diffuse.x, 0.2);            // one number: grey
  EXPECT_EQ(m[1].DiffuseTexture, "grain.png");      // the last word after the options
  EXPECT_EQ(m[1].EmissiveTexture, "glow.png");
  EXPECT_EQ(m[0].EmissiveTexture, "");
  EXPECT_NE(ParseMtl("newmtl a\nKd 0.5 nan 0.5\n", m).find("line 2"), std::string::npos);
  EXPECT_NE(ParseMtl("Kd 1 1 1\n", m).find("before any newmtl"), std::string::npos);
  EXPECT_NE(ParseMtl("newmtl a\nKd 0.5 0.5\n", m).find("one or three"), std::string::npos);
}

TEST(SceneImport, EmissiveMaterialsBecomeNamedLights)
{
  ImportedScene out;
  ASSERT_EQ(BuildImportedScene(FloorAndLamp(), ImportOptions(), out), "");
  ASSERT_EQ(out.Mesh.NumberOfPolygons(), 2);
  EXPECT_EQ(out.LightNames, std::vector<std::string>{ "Bulb" });
  EXPECT_EQ(out.Mesh.LightId, (std::vector<int>{ -1, 0 }));
  EXPECT_DOUBLE_EQ(out.Emission[1].x, 2);
  EXPECT_DOUBLE_EQ(out.Mesh.Reflectance[0].z, 0.3);
  EXPECT_EQ(out.Summary, "2 polygons, 2 materials, 1 lights, 0 degenerate cells dropped");
  int lights = 0;
  EXPECT_EQ(ValidateScene(out.Mesh, lights), "");
  EXPECT_EQ(lights, 1);
}

TEST(SceneImport, LightsPerObjectNamesLightsAfterObjects)
{
  RawScene raw = FloorAndLamp();
  // A second lamp object with the same material: one light by material, two by object.
  raw.Points.insert(raw.Points.end(), { { 0.1, 0.1, 1 }, { 0.1, 0.2, 1 }, { 0.2, 0.2, 1 } });
  raw.Connectivity.insert(raw.Connectivity.end(), { 8, 9, 10 });
  raw.Offsets.push_back(11);
  raw.Material.push_back(1);
  raw.Object.push_back(2);
  raw.ObjectNames.push_back("Lamp");
  ImportedScene byMaterial, byObject;
  ASSERT_EQ(BuildImportedScene(raw, ImportOptions(), byMaterial), "");
  EXPECT_EQ(byMaterial.LightNames.size(), 1u);
  ImportOptions options;
  options.LightsPerObject = true;
  ASSERT_EQ(BuildImportedScene(raw, options, byObject), "");
  EXPECT_EQ(byObject.LightNames, (std::vector<std::string>{ "Lamp", "Lamp (2)" }));
  EXPECT_EQ(byObject.Mesh.LightId, (std::vector<int>{ -1, 0, 1 }));
}

TEST(SceneImport, DegenerateCellsAreDroppedAndCounted)
{
  RawScene raw = FloorAndLamp();
  // Collinear corners, and a triangle with a repeated corner: both have no area.
  raw.Points.insert(raw.Points.end(), { { 0, 0, 2 }, { 1, 0, 2 }, { 2, 0, 2 } });
  raw.Connectivity.insert(raw.Connectivity.end(), { 8, 9, 10, 0, 1, 1 });
  raw.Offsets.insert(raw.Offsets.end(), { 11, 14 });
  raw.Material.insert(raw.Material.end(), { 0, 0 });
  raw.Object.insert(raw.Object.end(), { 0, 0 });
  ImportedScene out;
  ASSERT_EQ(BuildImportedScene(raw, ImportOptions(), out), "");
  EXPECT_EQ(out.Mesh.NumberOfPolygons(), 2);
  EXPECT_EQ(out.Dropped, 2);
  EXPECT_NE(out.Summary.find("2 degenerate cells dropped"), std::string::npos);
}

TEST(SceneImport, ClampsReflectanceAndScalesUnits)
{
  RawScene raw = FloorAndLamp();
  raw.Materials[0].Diffuse = { 1.02, 0.5, -0.1 };
  for (Vec3& p : raw.Points)
  {
    p = p * 1000.0; // millimetres
  }
  ImportOptions options;
  options.UnitScale = 0.001;
  ImportedScene out;
  ASSERT_EQ(BuildImportedScene(raw, options, out), "");
  EXPECT_DOUBLE_EQ(out.Mesh.Reflectance[0].x, 1.0);
  EXPECT_DOUBLE_EQ(out.Mesh.Reflectance[0].z, 0.0);
  EXPECT_NEAR(out.Mesh.Points[2].x, 1.0, 1e-12);
  ASSERT_FALSE(out.Warnings.empty());
  EXPECT_NE(out.Warnings[0].find("'Oak'"), std::string::npos);
}

TEST(SceneImport, BadInputIsAnErrorNamingIt)
{
  ImportedScene out;
  RawScene nan = FloorAndLamp();
  nan.Points[5].y = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(BuildImportedScene(nan, ImportOptions(), out).find("point 5"), std::string::npos);
  RawScene negative = FloorAndLamp();
  negative.Materials[1].Emissive.x = -1;
  EXPECT_NE(BuildImportedScene(negative, ImportOptions(), out).find("'Bulb'"), std::string::npos);
  ImportOptions zero;
  zero.UnitScale = 0;
  EXPECT_NE(BuildImportedScene(FloorAndLamp(), zero, out).find("unit scale"), std::string::npos);
  EXPECT_EQ(BuildImportedScene(RawScene(), ImportOptions(), out), "no polygons");
  RawScene dark = FloorAndLamp();
  dark.Materials[1].Emissive = Vec3();
  ASSERT_EQ(BuildImportedScene(dark, ImportOptions(), out), "");
  EXPECT_TRUE(out.LightNames.empty());
  EXPECT_NE(out.Warnings.back().find("no emissive material"), std::string::npos);
}

TEST(SceneImport, ObjGivesFacesMaterialsAndObjects)
{
  RawScene raw;
  std::vector<std::string> libraries;
  const std::string text = "mtllib a b.mtl\nv 0 0 0\nv 1 0 0 0.5 0.5 0.5\nv 1 1 0\nv 0 1 0\n"
                           "f 1 2 3\nusemtl Red Brick\no Wall 1\nf -4/1 -3/2/1 -2//1 -1\ng Trim\nusemtl Oak\nf 1 3 4\n";
  ASSERT_EQ(ParseObj(text, raw, libraries), "");
  EXPECT_EQ(libraries, std::vector<std::string>{ "a b.mtl" });
  ASSERT_EQ(raw.NumberOfPolygons(), 3);
  EXPECT_EQ(raw.Material, (std::vector<int>{ -1, 0, 1 }));
  EXPECT_EQ(raw.Object, (std::vector<int>{ -1, 0, 1 }));
  EXPECT_EQ(raw.Materials[0].Name, "Red Brick");
  EXPECT_EQ(raw.ObjectNames, (std::vector<std::string>{ "Wall 1", "Trim" }));
  EXPECT_EQ(std::vector<int>(raw.Connectivity.begin() + 3, raw.Connectivity.begin() + 7), (std::vector<int>{ 0, 1, 2, 3 }));
  EXPECT_NE(ParseObj("v 0 0\n", raw, libraries).find("line 1"), std::string::npos);
  EXPECT_NE(ParseObj("v 0 0 0\nf 1 0 1\n", raw, libraries).find("face corner '0'"), std::string::npos);
  EXPECT_NE(ParseObj("v 0 0 0\nv 1 0 0\nf 1 2\n", raw, libraries).find("three corners"), std::string::npos);
}
