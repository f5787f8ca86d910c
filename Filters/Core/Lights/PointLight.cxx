#include "Lights/PointLight.h"

#include <cmath>

namespace radiosity
{

void PointLight::Frame(Vec3& x, Vec3& y, Vec3& z) const
{
  z = Normalized(Aim);
  const Vec3 reference = std::fabs(z.x) > 0.99 ? Vec3{ 0, 1, 0 } : Vec3{ 1, 0, 0 };
  const Vec3 x0 = Normalized(reference - z * Dot(reference, z));
  const Vec3 y0 = Cross(z, x0);
  const double r = Rotation * Pi / 180;
  x = x0 * std::cos(r) + y0 * std::sin(r);
  y = Cross(z, x);
}

double PointLight::Toward(const Vec3& d) const
{
  if (!Distribution)
  {
    return Intensity;
  }
  Vec3 x, y, z;
  Frame(x, y, z);
  const Vec3 unit = Normalized(d);
  return Intensity * Distribution->Intensity({ Dot(unit, x), Dot(unit, y), Dot(unit, z) });
}

double PointLight::Flux() const { return Intensity * (Distribution ? Distribution->Flux() : 4 * Pi); }

std::string PointLightProblem(const PointLight& light, const std::string& what)
{
  const Vec3& p = light.Position;
  const Vec3& c = light.Color;
  if (!std::isfinite(p.x + p.y + p.z))
  {
    return what + " has a non-finite position";
  }
  if (!std::isfinite(Dot(light.Aim, light.Aim)) || !(Dot(light.Aim, light.Aim) > 0))
  {
    return what + " has no aim (a zero or non-finite direction)";
  }
  if (!std::isfinite(light.Rotation) || !std::isfinite(light.Intensity) || light.Intensity < 0)
  {
    return what + " has a non-finite rotation or a negative or non-finite intensity";
  }
  if (!std::isfinite(c.x + c.y + c.z) || c.x < 0 || c.y < 0 || c.z < 0)
  {
    return what + " has a negative or non-finite color";
  }
  return {};
}

} // namespace radiosity
