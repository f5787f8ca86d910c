// The kinds of point light: made by name from their parameters, their flux in closed form,
// their frame, and their direct light on a floor against closed forms (Lambert's point
// source, the solid angle a rectangle subtends).
#include "Lights/PhotometricFiles.h"
#include "Lights/PointShading.h"
#include "Geometry/PreparedScene.h"
#include "SceneBuilders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

using namespace radiosity;
using namespace radiosity_test;

namespace
{
std::shared_ptr<const LightDistribution> Made(const std::string& kind, const LightParameters& parameters)
{
  std::string error;
  auto made = MakeLightDistribution(kind, parameters, error);
  EXPECT_EQ(error, "") << kind;
  return made;
}

/// A floor [-a, a] x [-b, b] at z = 0 facing up, n x n elements.
SceneMesh Floor(double a, double b, int n)
{
  SceneMesh mesh;
  int patch = 0;
  AddGrid(mesh, { -a, -b, 0 }, { 2 * a, 0, 0 }, { 0, 2 * b, 0 }, n, n, { 0.5, 0.5, 0.5 }, -1, patch);
  return mesh;
}

/// Tells C0 from C90: 10 cd toward x, 30 toward y, in between by the angle.
class Lopsided : public LightDistribution
{
public:
  double Intensity(const Vec3& d) const override { return 10 * d.x * d.x + 30 * d.y * d.y + 5 * d.z * d.z; }
  double Flux() const override { return 4 * Pi * 45 / 3; }
  const char* Kind() const override { return "test"; }
};
} // namespace

TEST(LightKinds, EveryKindIsMadeByNameAndSaysWhatItDoesNotTake)
{
  for (const LightKind& kind : LightKinds())
  {
    LightParameters parameters;
    if (std::string(kind.Name) == "goniometric")
    {
      parameters.Set("file", std::string(RELIGHT_DATA_DIR) + "/Photometry/bega_sym1.ldt");
    }
    const auto made = Made(kind.Name, parameters);
    ASSERT_TRUE(made) << kind.Name;
    EXPECT_STREQ(made->Kind(), kind.Name);
  }
  std::string error;
  EXPECT_FALSE(MakeLightDistribution("laser", {}, error));
  EXPECT_EQ(error, "no kind of light is called 'laser' (there are point, lambertian, spot, goniometric)");
  EXPECT_FALSE(MakeLightDistribution("spot", { { "cone", "20" }, { "fallof", "3" } }, error));
  EXPECT_EQ(error, "a spot light does not take fallof (it takes cone (degrees, 30), falloff (degrees, 5), lumens (1 W/sr "
                   "in the cone if left out), maintenance (1))");
  EXPECT_FALSE(MakeLightDistribution("spot", { { "cone", "wide" } }, error));
  EXPECT_EQ(error, "'cone' is 'wide', not a number");
  EXPECT_FALSE(MakeLightDistribution("goniometric", {}, error));
  EXPECT_EQ(error, "a goniometric light needs its photometric file ('file')");
  EXPECT_FALSE(MakeLightDistribution("goniometric", { { "file", "/nowhere/lamp.ies" } }, error));
  EXPECT_EQ(error, "/nowhere/lamp.ies: cannot be read (missing, unreadable or over 64 MiB)");
}

TEST(LightKinds, FluxInClosedForm)
{
  EXPECT_NEAR(Made("point", {})->Flux(), 4 * Pi, 1e-12);
  EXPECT_NEAR(Made("lambertian", {})->Flux(), Pi, 1e-12);
  EXPECT_NEAR(Made("lambertian", { { "lumens", "1000" } })->Flux(), 1000, 1e-9);
  EXPECT_NEAR(Made("lambertian", { { "lumens", "1000" } })->Intensity({ 0, 0, 1 }), 1000 / Pi, 1e-9);
  // A hard-edged spot: the cap's solid angle.
  EXPECT_NEAR(Made("spot", { { "cone", "30" }, { "falloff", "0" } })->Flux(), 2 * Pi * (1 - std::cos(Pi / 6)), 1e-12);
  // A soft one against a plain midpoint sum of its own profile.
  const auto spot = Made("spot", { { "cone", "20" }, { "falloff", "15" } });
  double sum = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i)
  {
    const double t = (i + 0.5) * Pi / n;
    sum += spot->Intensity({ std::sin(t), 0, std::cos(t) }) * 2 * Pi * std::sin(t) * Pi / n;
  }
  EXPECT_NEAR(spot->Flux(), sum, 1e-8 * sum);
  // A luminaire at its file's lumens, or at the lumens asked for.
  const std::string file = std::string(RELIGHT_DATA_DIR) + "/Photometry/interlight_ovni_absolute.ies";
  PhotometricWeb web;
  ASSERT_EQ(ReadPhotometricFile(file, web), "");
  EXPECT_NEAR(Made("goniometric", { { "file", file } })->Flux(), web.Flux(), 1e-9 * web.Flux());
  const auto dimmed = Made("goniometric", { { "file", file }, { "lumens", "1000" } });
  EXPECT_NEAR(dimmed->Flux(), 1000, 1e-9);
  EXPECT_NEAR(dimmed->Intensity({ 0, 0, 1 }), web.Intensity({ 0, 0, 1 }) * 1000 / web.Flux(), 1e-9);
  // A maintenance factor: what is left after years of dirt and ageing, on any kind.
  EXPECT_NEAR(Made("goniometric", { { "file", file }, { "lumens", "1000" }, { "maintenance", "0.8" } })->Flux(), 800, 1e-9);
  EXPECT_NEAR(Made("point", { { "maintenance", "0.5" } })->Flux(), 2 * Pi, 1e-12);
  std::string error;
  EXPECT_FALSE(MakeLightDistribution("point", { { "maintenance", "1.5" } }, error));
  EXPECT_EQ(error, "a maintenance factor is above 0 and at most 1, not 1.500000");
  // A lamp tilted from its measured position: the file's TILT table's factor at that angle.
  const std::string tilted = ::testing::TempDir() + "tilted.ies";
  {
    std::ofstream out(tilted);
    out << "IESNA:LM-63-2002\nTILT=INCLUDE\n1\n3\n0 45 90\n1.0 0.9 0.6\n1 -1 1 1 1 1 2 0 0 0\n1 1 10\n0\n0\n100\n";
  }
  EXPECT_NEAR(Made("goniometric", { { "file", tilted } })->Intensity({ 0, 0, 1 }), 100, 1e-9);
  EXPECT_NEAR(Made("goniometric", { { "file", tilted }, { "tilt", "67.5" } })->Intensity({ 0, 0, 1 }), 75, 1e-9);
}

TEST(LightKinds, TheFrameFollowsAimAndRotation)
{
  PointLight light;
  light.Distribution = std::make_shared<const Lopsided>();
  light.Aim = { 0, 0, -1 }; // a downlight: C0 along world x, C90 along -y (seen from above, clockwise)
  EXPECT_NEAR(light.Toward({ 1, 0, 0 }), 10, 1e-12);
  EXPECT_NEAR(light.Toward({ 0, -1, 0 }), 30, 1e-12);
  EXPECT_NEAR(light.Toward({ 0, 0, -1 }), 5, 1e-12);
  light.Rotation = 90; // C0 turned onto where C90 was
  EXPECT_NEAR(light.Toward({ 0, -1, 0 }), 10, 1e-12);
  EXPECT_NEAR(light.Toward({ 1, 0, 0 }), 30, 1e-12);
  light.Rotation = 0;
  light.Aim = { 1, 0, 0 }; // along x: C0 falls back to the world's y
  EXPECT_NEAR(light.Toward({ 1, 0, 0 }), 5, 1e-12);
  EXPECT_NEAR(light.Toward({ 0, 1, 0 }), 10, 1e-12);
  EXPECT_NEAR(light.Flux(), 4 * Pi * 15, 1e-9);
  EXPECT_EQ(PointLightProblem(light, "light 'a'"), "");
  light.Aim = {};
  EXPECT_EQ(PointLightProblem(light, "light 'a'"), "light 'a' has no aim (a zero or non-finite direction)");
}

TEST(LightKinds, DirectLightOnAFloorMatchesClosedForms)
{
  // A spot 2 m over a 4 x 6 m floor: at each point Lambert's I(theta) cos(theta) / d^2.
  const SceneMesh mesh = Floor(2, 3, 40);
  PreparedScene prepared;
  ASSERT_EQ(PrepareTransport(mesh, 0, ProcessGroup(), prepared), "");
  PointLight light;
  light.Position = { 0.3, -0.2, 2 };
  light.Distribution = Made("spot", { { "cone", "25" }, { "falloff", "10" } });
  light.Intensity = 100;
  for (const Vec3& p : { Vec3{ 0.3, -0.2, 0 }, Vec3{ 1.0, 0.5, 0 }, Vec3{ -0.5, -1.2, 0 } })
  {
    const Vec3 d = light.Position - p;
    const double r = Norm(d), cosine = d.z / r;
    const double expected = 100 * light.Distribution->Intensity({ 0, 0, cosine }) * cosine / (r * r);
    // The light's frame is turned, not its profile: the spot is round, so only the angle counts.
    const Vec3 e = PointIrradianceAt(light, p, { 0, 0, 1 }, *prepared.Rays, prepared.Geometry->RayLift);
    EXPECT_NEAR(e.x, expected, 1e-9 * (1 + expected)) << p.x << " " << p.y;
  }
  // An isotropic source over the floor's centre sends I times the solid angle the floor
  // subtends onto it: 4 arcsin(ab / sqrt((a^2 + h^2)(b^2 + h^2))) for half-sides a, b.
  PointLight bulb;
  bulb.Position = { 0, 0, 1.5 };
  std::vector<Vec3> irradiance(mesh.NumberOfPolygons());
  AddPointIrradiance(bulb, mesh, *prepared.Geometry, *prepared.Rays, 0, mesh.NumberOfPolygons(), irradiance);
  double power = 0;
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    power += irradiance[e].x * prepared.Geometry->Area[e];
  }
  const double a = 2, b = 3, h = 1.5;
  const double omega = 4 * std::asin(a * b / std::sqrt((a * a + h * h) * (b * b + h * h)));
  EXPECT_NEAR(power, omega, 2e-3 * omega);
}

TEST(LightKinds, ABlockerCastsAnExactShadow)
{
  SceneMesh mesh = Floor(2, 2, 10);
  int patch = 100;
  // A 1 m board at z = 1 facing down, under the light.
  AddGrid(mesh, { -0.5, -0.5, 1 }, { 0, 1, 0 }, { 1, 0, 0 }, 2, 2, { 0.5, 0.5, 0.5 }, -1, patch);
  PreparedScene prepared;
  ASSERT_EQ(PrepareTransport(mesh, 0, ProcessGroup(), prepared), "");
  PointLight light;
  light.Position = { 0, 0, 2 };
  const double lift = prepared.Geometry->RayLift;
  EXPECT_EQ(PointIrradianceAt(light, { 0.2, 0.1, 0 }, { 0, 0, 1 }, *prepared.Rays, lift).x, 0.0);
  EXPECT_NEAR(PointIrradianceAt(light, { 1.8, 0, 0 }, { 0, 0, 1 }, *prepared.Rays, lift).x,
    2 / std::pow(1.8 * 1.8 + 4, 1.5), 1e-12);
}

TEST(LightKinds, ALargeOpeningNearASurfaceIsSpreadOverItsArea)
{
  // A round Lambertian luminaire of 1 m diameter (a cosine table, LM-63's negative width
  // and length for round), 0.5 m over a floor: under its centre a disk of radiance
  // I0 / A gives I0 / (a^2 + h^2) = 2000 lx for I0 = 1000 cd, where a point would give
  // I0 / h^2 = 4000. Far off, the two agree.
  std::string table = "IESNA:LM-63-2002\nTILT=NONE\n1 -1 1 19 1 1 2 -1.0 -1.0 0\n1 1 0\n";
  for (int i = 0; i <= 90; i += 5)
  {
    table += std::to_string(i) + " ";
  }
  table += "\n0\n";
  for (int i = 0; i <= 90; i += 5)
  {
    table += std::to_string(1000 * std::cos(i * Pi / 180)) + " ";
  }
  const std::string path = ::testing::TempDir() + "round_panel.ies";
  {
    std::ofstream out(path);
    out << table << "\n";
  }
  const SceneMesh mesh = Floor(3, 3, 12);
  PreparedScene prepared;
  ASSERT_EQ(PrepareTransport(mesh, 0, ProcessGroup(), prepared), "");
  PointLight panel;
  panel.Position = { 0, 0, 0.5 };
  panel.Distribution = Made("goniometric", { { "file", path } });
  EXPECT_NEAR(panel.OpeningSize(), 1.0, 1e-12);
  const double lift = prepared.Geometry->RayLift;
  EXPECT_NEAR(PointIrradianceAt(panel, { 0, 0, 0 }, { 0, 0, 1 }, *prepared.Rays, lift).x, 2000, 0.03 * 2000);
  panel.Position = { 0, 0, 6 }; // 12 opening sizes away: a point, I0 / h^2
  EXPECT_NEAR(PointIrradianceAt(panel, { 0, 0, 0 }, { 0, 0, 1 }, *prepared.Rays, lift).x, 1000.0 / 36, 1e-6);
}
