// Parallel loops for the VTK-free core (oneTBB underneath, threads kept between calls).
#ifndef RadiosityCore_WorkerPool_h
#define RadiosityCore_WorkerPool_h

#include <functional>
#include <memory>

namespace radiosity
{

/// A fixed set of worker threads. A solve makes one and reuses it for every shot, so the
/// hot loop creates no threads. Callers write disjoint outputs (or per-item slots reduced
/// afterwards in a fixed order), so results never depend on the thread count.
class WorkerPool
{
public:
  explicit WorkerPool(int threads); ///< 0: every hardware thread
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int Threads() const;

  /// Calls body(begin, end) on sub-ranges of [0, count) of about `grain` items.
  void For(int count, int grain, const std::function<void(int, int)>& body) const;

private:
  struct Internals;
  std::unique_ptr<Internals> Impl;
};

} // namespace radiosity

#endif
