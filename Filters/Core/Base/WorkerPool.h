// Parallel loops for the VTK-free core (oneTBB underneath, threads kept between calls).
#ifndef RadiosityCore_WorkerPool_h
#define RadiosityCore_WorkerPool_h

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

  /// Calls body(begin, end) on sub-ranges of [0, count) of about `grain` items. The body
  /// is passed by reference, not wrapped in a std::function: a call allocates nothing.
  template <typename Body>
  void For(int count, int grain, const Body& body) const
  {
    this->Run(count, grain,
      [](const void* context, int begin, int end) { (*static_cast<const Body*>(context))(begin, end); },
      &body);
  }

  /// Calls body() with the libraries' own parallel work (Embree's BVH build) held to
  /// this pool's threads: one thread per rank means one, not every core of the node.
  template <typename Body>
  void Within(const Body& body) const
  {
    this->RunWithin([](const void* context) { (*static_cast<const Body*>(context))(); }, &body);
  }

private:
  void Run(int count, int grain, void (*call)(const void*, int, int), const void* context) const;
  void RunWithin(void (*call)(const void*), const void* context) const;
  struct Internals;
  std::unique_ptr<Internals> Impl;
};

} // namespace radiosity

#endif
