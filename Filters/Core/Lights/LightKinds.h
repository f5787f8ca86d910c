// The one home of every kind of light that shines from a point: how it spreads its
// intensity over directions. A kind is a LightDistribution made by name from its
// parameters (as pbrt-v4's Light::Create does); PointLight (PointLight.h) places one in a
// scene, and the solver, the moving lights and the final gather shade it alike.
// Lights that are cells of the mesh (LightId, Emission) are the solver's own path.
#ifndef RadiosityCore_LightKinds_h
#define RadiosityCore_LightKinds_h

#include "Base/Vec3.h"

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace radiosity
{

/// Intensity over directions in the light's own frame (z the aim, x its C0 axis; see
/// Photometry.h), per unit of the light's strength. A kind's unit: 1 W/sr along its aim
/// for the radiometric kinds, the candela of its file at its lumens for a goniometric one.
class LightDistribution
{
public:
  virtual ~LightDistribution() = default;
  /// Intensity toward `direction` (unit, in the light's frame).
  virtual double Intensity(const Vec3& direction) const = 0;
  /// The flux it sends out, the integral of Intensity over the sphere.
  virtual double Flux() const = 0;
  /// The kind's name, as in LightKinds().
  virtual const char* Kind() const = 0;
  /// The luminous opening the light shines from, in metres (a photometric file's: width
  /// along the frame's y, length along its x, height; a negative width or length: round, of
  /// that diameter). Zero for a point. Near a surface the light is spread over it.
  virtual Vec3 Opening() const { return {}; }
};

/// A light's parameters by name, as text (from Python, a ParaView table, a file). Each
/// kind reads what it knows; what no kind read is reported, so a misspelt name is an
/// error and not a silent default.
class LightParameters
{
public:
  LightParameters() = default;
  LightParameters(std::initializer_list<std::pair<const std::string, std::string>> values)
    : Values(values)
  {
  }
  void Set(const std::string& name, const std::string& value) { Values[name] = value; }
  /// The number `name`, or `fallback` where it is not given; false with `error` where it
  /// is given but not a finite number.
  bool Number(const std::string& name, double fallback, double& value, std::string& error) const;
  /// The text `name`, empty where it is not given.
  std::string Text(const std::string& name) const;
  /// The names given that nothing read, comma-separated; empty when all were read.
  std::string Unused() const;

private:
  std::map<std::string, std::string> Values;
  mutable std::set<std::string> Read;
};

/// One row of the registry: a kind's name, what it reads, and how it is made.
struct LightKind
{
  const char* Name;
  const char* Parameters; ///< for messages and docs
  std::shared_ptr<const LightDistribution> (*Make)(const LightParameters& parameters, std::string& error);
};

/// `made`, scaled so that its flux is the parameter `lumens` where given (0 or absent: as
/// made), times the parameter `maintenance` (the maintenance factor of EN 12464-1, in
/// (0, 1], 1 where absent: the light a luminaire keeps after years of dirt and ageing);
/// null with `error` for a value out of range or not a number.
std::shared_ptr<const LightDistribution> WithLumens(
  std::shared_ptr<const LightDistribution> made, const LightParameters& parameters, std::string& error);

/// Every kind of point light: point, lambertian, spot, goniometric.
const std::vector<LightKind>& LightKinds();

/// The distribution `kind` makes of `parameters`; null with `error` naming the problem (an
/// unknown kind, a bad value, a parameter the kind does not take).
std::shared_ptr<const LightDistribution> MakeLightDistribution(
  const std::string& kind, const LightParameters& parameters, std::string& error);

/// The kinds' own makers, each in its file (IsotropicLight.cxx, ...), listed once in
/// LightKinds.cxx's table.
std::shared_ptr<const LightDistribution> MakeIsotropicLight(const LightParameters& parameters, std::string& error);
std::shared_ptr<const LightDistribution> MakeLambertianLight(const LightParameters& parameters, std::string& error);
std::shared_ptr<const LightDistribution> MakeSpotLight(const LightParameters& parameters, std::string& error);
std::shared_ptr<const LightDistribution> MakeGoniometricLight(const LightParameters& parameters, std::string& error);

} // namespace radiosity

#endif
