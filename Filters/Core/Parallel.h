// A minimal parallel-for for the VTK-free core (the VTK layer is not available here).
#ifndef RadiosityCore_Parallel_h
#define RadiosityCore_Parallel_h

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace radiosity
{

inline int ResolveThreadCount(int requested)
{
  if (requested > 0)
  {
    return requested;
  }
  const unsigned hw = std::thread::hardware_concurrency();
  return hw > 0 ? static_cast<int>(hw) : 1;
}

/// Calls body(begin, end) on chunks of [0, count) from `threads` threads. Chunks are handed
/// out dynamically because receivers differ a lot in cost (occluded ones shoot rays).
/// Results must not depend on which thread runs a chunk: callers write disjoint outputs.
template <typename Body>
void ParallelFor(int count, int threads, int chunk, const Body& body)
{
  threads = std::max(1, std::min(threads, (count + chunk - 1) / std::max(chunk, 1)));
  if (threads <= 1)
  {
    body(0, count);
    return;
  }
  std::atomic<int> next{ 0 };
  auto worker = [&]() {
    for (int begin = next.fetch_add(chunk); begin < count; begin = next.fetch_add(chunk))
    {
      body(begin, std::min(count, begin + chunk));
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(threads - 1);
  for (int t = 1; t < threads; ++t)
  {
    pool.emplace_back(worker);
  }
  worker();
  for (std::thread& t : pool)
  {
    t.join();
  }
}

} // namespace radiosity

#endif
