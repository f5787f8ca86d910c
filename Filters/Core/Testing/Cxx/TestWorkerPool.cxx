#include "Base/WorkerPool.h"

#include <gtest/gtest.h>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <mutex>
#include <set>
#include <thread>

using namespace radiosity;

TEST(WorkerPool, WorkInsideWithinKeepsToThePoolsThreads)
{
  // Libraries that run their own parallel loops (Embree's BVH build) inside Within see the
  // pool's thread count, not the machine's: one thread per rank stays one.
  for (int threads : { 1, 2 })
  {
    const WorkerPool pool(threads);
    int seen = 0;
    std::set<std::thread::id> workers;
    std::mutex lock;
    pool.Within([&] {
      seen = tbb::this_task_arena::max_concurrency();
      tbb::parallel_for(0, 20000, [&](int) {
        const std::lock_guard<std::mutex> hold(lock);
        workers.insert(std::this_thread::get_id());
      });
    });
    EXPECT_EQ(seen, threads);
    EXPECT_LE(static_cast<int>(workers.size()), threads);
  }
}

TEST(WorkerPool, ForCoversEveryItemOnce)
{
  const WorkerPool pool(2);
  std::vector<std::atomic<int>> hits(10007);
  pool.For(static_cast<int>(hits.size()), 64, [&](int begin, int end) {
    for (int i = begin; i < end; ++i)
    {
      ++hits[i];
    }
  });
  for (const auto& h : hits)
  {
    ASSERT_EQ(h.load(), 1);
  }
}
