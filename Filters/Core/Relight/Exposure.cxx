#include "Relight/Exposure.h"

#include <algorithm>
#include <cmath>

namespace radiosity
{

double MeteredExposure(const float* rgb, std::size_t count, const std::vector<char>& skip, double unlit)
{
  std::vector<double> luminance;
  luminance.reserve(count);
  for (std::size_t i = 0; i < count; ++i)
  {
    const float* c = rgb + 3 * i;
    const double y = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; // Rec. 709
    if ((skip.empty() || !skip[i]) && y > 0 && std::isfinite(y))
    {
      luminance.push_back(y);
    }
  }
  if (luminance.empty())
  {
    return unlit;
  }
  const auto at = luminance.begin() + static_cast<std::ptrdiff_t>(kMeteredPercentile * (luminance.size() - 1));
  std::nth_element(luminance.begin(), at, luminance.end());
  return kMeteredWhite / *at;
}

} // namespace radiosity
