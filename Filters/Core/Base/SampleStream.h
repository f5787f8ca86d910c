// Counter-based random numbers for the samplers.
#ifndef RadiosityCore_SampleStream_h
#define RadiosityCore_SampleStream_h

#include <cstdint>

namespace radiosity
{

/// Counter-based random numbers: a sample depends only on its indices, so results are the
/// same for any number of threads.
struct SampleStream
{
  std::uint64_t State;
  SampleStream(std::uint64_t a, std::uint64_t b, std::uint64_t c = 0)
    : State((a * 0x9E3779B97F4A7C15ull) ^ (b * 0xC2B2AE3D27D4EB4Full) ^ (c + 0x632BE59BD9B4E019ull))
  {
  }
  double Next()
  {
    std::uint64_t z = (State += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * (1.0 / 9007199254740992.0);
  }
};

} // namespace radiosity

#endif
