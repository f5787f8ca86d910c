// Wall time and peak memory for the benches (Linux).
#ifndef RadiosityBench_BenchClock_h
#define RadiosityBench_BenchClock_h

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <string>

namespace radiosity_bench
{

inline double Now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// Peak resident memory since the last ResetPeakMemory (or the start), in MB.
inline double PeakMemoryMB()
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
  {
    if (line.rfind("VmHWM:", 0) == 0)
    {
      return std::atof(line.c_str() + 6) / 1024.0;
    }
  }
  return 0;
}

inline void ResetPeakMemory()
{
  std::ofstream("/proc/self/clear_refs") << "5";
}

} // namespace radiosity_bench

#endif
