#include "Lights/LightColors.h"

namespace radiosity
{

std::vector<Vec3> LightDefaultColors(int lights, const std::vector<double>& given, const std::vector<int>& lightId,
  const std::vector<Vec3>& emission)
{
  std::vector<Vec3> colors(lights, { 1, 1, 1 });
  if (given.size() == 3 * static_cast<size_t>(lights))
  {
    for (int l = 0; l < lights; ++l)
    {
      colors[l] = { given[3 * l], given[3 * l + 1], given[3 * l + 2] };
    }
    return colors;
  }
  std::vector<Vec3> sum(lights);
  std::vector<int> count(lights, 0);
  for (size_t c = 0; c < lightId.size() && c < emission.size(); ++c)
  {
    if (lightId[c] >= 0 && lightId[c] < lights)
    {
      sum[lightId[c]] += emission[c];
      ++count[lightId[c]];
    }
  }
  for (int l = 0; l < lights; ++l)
  {
    colors[l] = count[l] ? sum[l] * (1.0 / count[l]) : colors[l];
  }
  return colors;
}

} // namespace radiosity
