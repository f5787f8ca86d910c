#include "Lights/PointLight.h"

#include <algorithm>
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

double PointLight::OpeningSize() const
{
  const Vec3 o = Distribution ? Distribution->Opening() : Vec3();
  return std::max(std::fabs(o.x), std::fabs(o.y));
}

std::vector<Vec3> PointLight::OpeningPoints(int count) const
{
  const Vec3 o = Distribution ? Distribution->Opening() : Vec3();
  const int side = std::max(1, static_cast<int>(std::lround(std::sqrt(static_cast<double>(count)))));
  Vec3 x, y, z;
  Frame(x, y, z);
  std::vector<Vec3> points;
  const bool round = o.x < 0 || o.y < 0;
  for (int i = 0; i < side; ++i)
  {
    for (int j = 0; j < side; ++j)
    {
      const double u = (i + 0.5) / side, v = (j + 0.5) / side;
      if (round)
      {
        // Equal-area rings (radius by the square root), turned by the cell.
        const double radius = 0.5 * OpeningSize() * std::sqrt(u), angle = 2 * Pi * v;
        points.push_back(Position + x * (radius * std::cos(angle)) + y * (radius * std::sin(angle)));
      }
      else
      {
        points.push_back(Position + x * ((u - 0.5) * std::fabs(o.y)) + y * ((v - 0.5) * std::fabs(o.x)));
      }
    }
  }
  return points;
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
