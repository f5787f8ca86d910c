#include "Base/WorkerPool.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>

namespace radiosity
{

struct WorkerPool::Internals
{
  int Threads = 1;
  std::unique_ptr<tbb::task_arena> Arena;
};

WorkerPool::WorkerPool(int threads)
  : Impl(new Internals)
{
  const int available = tbb::this_task_arena::max_concurrency();
  Impl->Threads = threads > 0 ? threads : std::max(1, available);
  Impl->Arena.reset(new tbb::task_arena(Impl->Threads)); // made on first use, not here
}

WorkerPool::~WorkerPool() = default;

int WorkerPool::Threads() const
{
  return Impl->Threads;
}

void WorkerPool::Run(int count, int grain, void (*call)(const void*, int, int), const void* context) const
{
  if (count <= 0)
  {
    return;
  }
  grain = std::max(1, grain);
  if (Impl->Threads == 1 || count <= grain)
  {
    call(context, 0, count);
    return;
  }
  Impl->Arena->execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, count, grain),
      [&](const tbb::blocked_range<int>& r) { call(context, r.begin(), r.end()); });
  });
}

void WorkerPool::RunWithin(void (*call)(const void*), const void* context) const
{
  Impl->Arena->execute([&] { call(context); });
}

} // namespace radiosity
