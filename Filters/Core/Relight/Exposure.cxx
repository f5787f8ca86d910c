#include "Relight/Exposure.h"

#include <algorithm>
#include <cmath>

namespace radiosity
{

double MeteredExposure(
  const float* rgb, std::size_t count, const std::vector<char>& skip, double unlit, const std::vector<double>& area)
{
  std::vector<std::pair<double, double>> lit; // luminance, weight
  lit.reserve(count);
  double total = 0;
  for (std::size_t i = 0; i < count; ++i)
  {
    const float* c = rgb + 3 * i;
    const double y = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; // Rec. 709
    const double w = area.size() == count ? area[i] : 1.0;
    if ((skip.empty() || !skip[i]) && y > 0 && std::isfinite(y) && w > 0 && std::isfinite(w))
    {
      lit.emplace_back(y, w);
      total += w;
    }
  }
  if (lit.empty())
  {
    return unlit;
  }
  std::sort(lit.begin(), lit.end());
  double below = 0;
  for (const auto& [y, w] : lit)
  {
    below += w;
    if (below >= kMeteredPercentile * total)
    {
      return kMeteredWhite / y;
    }
  }
  return kMeteredWhite / lit.back().first;
}

} // namespace radiosity
