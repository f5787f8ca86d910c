// "point": the same intensity every way, and "lambertian": a small flat emitter facing its
// aim (intensity falls with the cosine, nothing behind), the two moving lights of old.
#include "Lights/LightKinds.h"

#include <algorithm>

namespace radiosity
{

namespace
{
class Isotropic : public LightDistribution
{
public:
  double Intensity(const Vec3&) const override { return 1; }
  double Flux() const override { return 4 * Pi; }
  const char* Kind() const override { return "point"; }
};

class Lambertian : public LightDistribution
{
public:
  double Intensity(const Vec3& direction) const override { return std::max(0.0, direction.z); }
  double Flux() const override { return Pi; }
  const char* Kind() const override { return "lambertian"; }
};
} // namespace

std::shared_ptr<const LightDistribution> MakeIsotropicLight(const LightParameters& parameters, std::string& error)
{
  static const auto shared = std::make_shared<const Isotropic>();
  return WithLumens(shared, parameters, error);
}

std::shared_ptr<const LightDistribution> MakeLambertianLight(const LightParameters& parameters, std::string& error)
{
  static const auto shared = std::make_shared<const Lambertian>();
  return WithLumens(shared, parameters, error);
}

} // namespace radiosity
