// Relighting: B_j = sum_i E_i * B_j,i (the paper's equation 1), per RGB channel.
#ifndef RadiosityCore_Relight_h
#define RadiosityCore_Relight_h

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace radiosity
{

/// `solutions[i]` points at n RGB tuples of light i's unit-emission solution (any value
/// type); `weights` holds 3 * k factors (colour * intensity, 0 for a disabled light).
/// Writes n RGB tuples to `out`. Cost O(n k); nothing else is recomputed.
template <typename T, typename Out>
void CombineLights(const std::vector<const T*>& solutions, const std::vector<double>& weights,
  std::size_t n, Out* out)
{
  const std::size_t k = solutions.size();
  for (std::size_t j = 0; j < 3 * n; ++j)
  {
    out[j] = 0;
  }
  for (std::size_t i = 0; i < k; ++i)
  {
    const double w[3] = { weights[3 * i], weights[3 * i + 1], weights[3 * i + 2] };
    if (w[0] == 0 && w[1] == 0 && w[2] == 0)
    {
      continue; // a disabled light contributes nothing, not even a NaN from its data
    }
    const T* s = solutions[i];
    for (std::size_t j = 0; j < n; ++j)
    {
      out[3 * j + 0] += static_cast<Out>(w[0] * s[3 * j + 0]);
      out[3 * j + 1] += static_cast<Out>(w[1] * s[3 * j + 1]);
      out[3 * j + 2] += static_cast<Out>(w[2] * s[3 * j + 2]);
    }
  }
}

/// Linear radiosity to 8-bit display colour: exposure, clamp, sRGB transfer curve.
inline unsigned char ToDisplay(double linear, double exposure)
{
  double v = linear * exposure;
  if (!(v > 0))
  {
    return 0;
  }
  v = std::min(v, 1.0);
  const double s = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
  return static_cast<unsigned char>(std::lround(255.0 * s));
}

} // namespace radiosity

#endif
