#include "Import/LightMarking.h"

#include <cctype>
#include <cmath>

namespace radiosity
{


std::string AreaLightLoop(const AreaLight& light, std::vector<Vec3>& loop)
{
  loop.clear();
  const double length = Norm(light.Normal);
  if (!(length > 0) || !std::isfinite(length) || !std::isfinite(light.Centre.x) || !std::isfinite(light.Centre.y) ||
    !std::isfinite(light.Centre.z))
  {
    return "area light '" + light.Name + "' needs a finite centre and a non-zero normal";
  }
  const bool disk = light.Shape == AreaShape::Disk;
  if (!(light.Width > 0) || !std::isfinite(light.Width) ||
    (!disk && (!(light.Height > 0) || !std::isfinite(light.Height))))
  {
    return "area light '" + light.Name + "' needs a positive size";
  }
  Vec3 t, b;
  TangentFrame(light.Normal * (1.0 / length), t, b); // t x b = normal: corners t, b, -t, -b wind forward
  if (!disk)
  {
    const double w = 0.5 * light.Width, h = 0.5 * light.Height;
    loop = { light.Centre - t * w - b * h, light.Centre + t * w - b * h, light.Centre + t * w + b * h,
      light.Centre - t * w + b * h };
    return std::string();
  }
  // A regular n-gon of the disk's area: circumradius r with n/2 r^2 sin(2 pi/n) = pi R^2.
  constexpr int corners = 32;
  const double radius = 0.5 * light.Width * std::sqrt(2 * Pi / (corners * std::sin(2 * Pi / corners)));
  for (int k = 0; k < corners; ++k)
  {
    const double angle = 2 * Pi * k / corners;
    loop.push_back(light.Centre + t * (radius * std::cos(angle)) + b * (radius * std::sin(angle)));
  }
  return std::string();
}

void CompactLights(std::vector<int>& lightId, std::vector<std::string>& names)
{
  std::vector<int> newId(names.size(), -1);
  for (int id : lightId)
  {
    if (id >= 0 && id < static_cast<int>(names.size()))
    {
      newId[id] = 0;
    }
  }
  std::vector<std::string> kept;
  for (size_t l = 0; l < names.size(); ++l)
  {
    if (newId[l] == 0)
    {
      newId[l] = static_cast<int>(kept.size());
      kept.push_back(names[l]);
    }
  }
  for (int& id : lightId)
  {
    id = id >= 0 && id < static_cast<int>(newId.size()) ? newId[id] : -1;
  }
  names.swap(kept);
}

} // namespace radiosity
