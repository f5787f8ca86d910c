// "spot": full intensity within `cone` degrees of the aim, easing to nothing over the
// next `falloff` degrees (a smoothstep in the angle, as renderers' spots do).
#include "Lights/LightKinds.h"

#include <algorithm>
#include <cmath>

namespace radiosity
{

namespace
{
class Spot : public LightDistribution
{
public:
  Spot(double cone, double falloff)
    : Inner(cone * Pi / 180)
    , Outer((cone + falloff) * Pi / 180)
  {
  }
  double Intensity(const Vec3& direction) const override
  {
    return Profile(std::acos(std::max(-1.0, std::min(1.0, direction.z))));
  }
  double Flux() const override
  {
    // The integral over the angle from the aim of Profile(t) 2 pi sin t: closed form inside
    // the cone, Simpson's rule over the easing (smooth there, 256 steps: exact to 1e-10).
    double flux = 2 * Pi * (1 - std::cos(Inner));
    const int n = 256;
    const double h = (Outer - Inner) / n;
    double sum = 0;
    for (int i = 0; i <= n && h > 0; ++i)
    {
      const double t = Inner + i * h;
      sum += (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2)) * Profile(t) * std::sin(t);
    }
    return flux + 2 * Pi * sum * h / 3;
  }
  const char* Kind() const override { return "spot"; }

private:
  double Profile(double angle) const
  {
    if (angle <= Inner)
    {
      return 1;
    }
    if (angle >= Outer)
    {
      return 0;
    }
    const double s = (Outer - angle) / (Outer - Inner);
    return s * s * (3 - 2 * s);
  }
  double Inner, Outer;
};
} // namespace

std::shared_ptr<const LightDistribution> MakeSpotLight(const LightParameters& parameters, std::string& error)
{
  double cone, falloff;
  if (!parameters.Number("cone", 30, cone, error) || !parameters.Number("falloff", 5, falloff, error))
  {
    return nullptr;
  }
  if (!(cone >= 0) || !(falloff >= 0) || cone + falloff > 180 || cone + falloff <= 0)
  {
    error = "a spot light's cone and falloff must be 0 or more and add up to more than 0 and at most 180 degrees";
    return nullptr;
  }
  return WithLumens(std::make_shared<const Spot>(cone, falloff), parameters, error);
}

} // namespace radiosity
