// Relighting: B_j = sum_i E_i * B_j,i (the paper's equation 1), per RGB channel.
#ifndef RadiosityCore_Relight_h
#define RadiosityCore_Relight_h

#include "Base/WorkerPool.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace radiosity
{

/// Tuples [begin, end) of the combination. Blocked so the output block stays in cache
/// while every light is added to it: memory traffic is one read of each solution and one
/// write of the result, the minimum.
template <typename T, typename Out>
void CombineLightsRange(const std::vector<const T*>& solutions, const std::vector<double>& weights,
  std::size_t begin, std::size_t end, Out* out)
{
  constexpr std::size_t block = 1024;
  const std::size_t k = solutions.size();
  double sum[3 * block];
  for (std::size_t b0 = begin; b0 < end; b0 += block)
  {
    const std::size_t count = std::min(block, end - b0);
    std::fill(sum, sum + 3 * count, 0.0);
    for (std::size_t i = 0; i < k; ++i)
    {
      const double w0 = weights[3 * i], w1 = weights[3 * i + 1], w2 = weights[3 * i + 2];
      if (w0 == 0 && w1 == 0 && w2 == 0)
      {
        continue; // a disabled light contributes nothing, not even a NaN from its data
      }
      const T* s = solutions[i] + 3 * b0;
      for (std::size_t j = 0; j < count; ++j)
      {
        sum[3 * j + 0] += w0 * s[3 * j + 0];
        sum[3 * j + 1] += w1 * s[3 * j + 1];
        sum[3 * j + 2] += w2 * s[3 * j + 2];
      }
    }
    Out* o = out + 3 * b0;
    for (std::size_t j = 0; j < 3 * count; ++j)
    {
      o[j] = static_cast<Out>(sum[j]);
    }
  }
}

/// `solutions[i]` points at n RGB tuples of solution i (any value type); `weights` holds
/// 3 * k factors (color * intensity, 0 for a disabled light). Writes n RGB tuples to
/// `out`, accumulating in double. Cost O(n k); nothing else is recomputed.
template <typename T, typename Out>
void CombineLights(const std::vector<const T*>& solutions, const std::vector<double>& weights,
  std::size_t n, Out* out, const WorkerPool* pool = nullptr)
{
  if (!pool || n < 16384)
  {
    CombineLightsRange(solutions, weights, 0, n, out);
    return;
  }
  constexpr int tuplesPerTask = 8192;
  const int tasks = static_cast<int>((n + tuplesPerTask - 1) / tuplesPerTask);
  pool->For(tasks, 1, [&](int first, int last) {
    CombineLightsRange(solutions, weights, static_cast<std::size_t>(first) * tuplesPerTask,
      std::min(n, static_cast<std::size_t>(last) * tuplesPerTask), out);
  });
}

/// One kind of item's per-light solutions (a data set's points, or its cells), as a relight
/// reads them: arrays of Items RGB tuples in their own memory, all float or all double.
struct SolutionTable
{
  std::size_t Items = 0;
  std::vector<const float*> Floats;
  std::vector<const double*> Doubles;
  bool Empty() const { return Floats.empty() && Doubles.empty(); }
};

/// CombineLights over whichever type the table holds.
template <typename Out>
void CombineTable(const SolutionTable& table, const std::vector<double>& weights, Out* out, const WorkerPool* pool)
{
  if (!table.Floats.empty())
  {
    CombineLights(table.Floats, weights, table.Items, out, pool);
  }
  else
  {
    CombineLights(table.Doubles, weights, table.Items, out, pool);
  }
}

/// Linear radiosity to 8-bit display color: exposure, clamp, sRGB transfer curve.
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

/// ToDisplay for many values: a table of the sRGB curve instead of a pow per channel,
/// which would cost more than the combination itself.
class DisplayCurve
{
public:
  DisplayCurve()
  {
    for (int i = 0; i <= Size; ++i)
    {
      Table[i] = ToDisplay((i + 0.5) / Size, 1.0);
    }
  }
  template <typename T>
  void Apply(const T* linear, std::size_t count, double exposure, unsigned char* out) const
  {
    const double scale = exposure * Size;
    for (std::size_t i = 0; i < count; ++i)
    {
      const double v = linear[i] * scale;
      out[i] = v > 0 ? Table[v < Size ? static_cast<int>(v) : Size] : 0;
    }
  }

private:
  static constexpr int Size = 16384; // finer than one display code at the steepest part
  unsigned char Table[Size + 1];
};

} // namespace radiosity

#endif
