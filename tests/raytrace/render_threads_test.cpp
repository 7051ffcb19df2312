// The render's threads: every thread runs each job once, jobs follow one
// another on the same threads, an exception on any thread reaches the
// caller once all have finished, and finish() lets the workers end without
// waiting for them.
#include "raytrace/render_threads.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

namespace csgray::detail {
namespace {

TEST(RenderThreads, EveryThreadRunsEachJobOnce) {
  for (int threads : {1, 2, 5}) {
    RenderThreads pool(threads);
    ASSERT_EQ(pool.size(), threads);
    for (int job = 0; job < 100; ++job) {
      std::vector<std::atomic<int>> runs(threads);
      std::atomic<int> total = 0;
      pool.run([&](int k) {
        ++runs[k];
        ++total;
      });
      // All of them have finished when run returns.
      ASSERT_EQ(total, threads) << "job " << job;
      for (int k = 0; k < threads; ++k) ASSERT_EQ(runs[k], 1) << "thread " << k;
    }
  }
}

TEST(RenderThreads, TheCallerIsThreadZeroAndTheOthersAreDistinct) {
  RenderThreads pool(4);
  std::vector<std::thread::id> ids(4);
  pool.run([&](int k) { ids[k] = std::this_thread::get_id(); });
  EXPECT_EQ(ids[0], std::this_thread::get_id());
  EXPECT_EQ(std::set<std::thread::id>(ids.begin(), ids.end()).size(), 4u);
}

TEST(RenderThreads, AllCoresByDefault) {
  EXPECT_GE(RenderThreads::cores(), 1);
  EXPECT_LE(RenderThreads::cores(), int(std::max(1u, std::thread::hardware_concurrency())));
  EXPECT_EQ(RenderThreads().size(), RenderThreads::cores());
  EXPECT_EQ(RenderThreads(0).size(), RenderThreads::cores());
}

TEST(RenderThreads, SleepingThreadsWakeForTheNextJob) {
  RenderThreads pool(3);
  pool.run([](int) {});
  // Longer than the threads spin before they sleep.
  std::this_thread::sleep_for(std::chrono::milliseconds(120));
  std::atomic<int> total = 0;
  pool.run([&](int) { ++total; });
  EXPECT_EQ(total, 3);
}

TEST(RenderThreads, AnExceptionReachesTheCallerAfterEveryThreadIsDone) {
  RenderThreads pool(3);
  std::atomic<int> finished = 0;
  EXPECT_THROW(pool.run([&](int k) {
    if (k == 2) throw std::runtime_error("tile failed");
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    ++finished;
  }),
               std::runtime_error);
  EXPECT_EQ(finished, 2);
  // The threads serve the next job as before.
  std::atomic<int> total = 0;
  pool.run([&](int) { ++total; });
  EXPECT_EQ(total, 3);
}

// Each worker ends (its thread-local objects are destroyed) after finish()
// and before the pool is destroyed; no job may follow. (At namespace scope,
// a thread-local is made, and its destruction arranged, in each thread that
// uses it.)
std::atomic<int> workersEnded = 0;
struct WorkerEnd {
  bool counts = false;
  ~WorkerEnd() {
    if (counts) ++workersEnded;
  }
};
thread_local WorkerEnd workerEnd;

TEST(RenderThreads, FinishLetsTheWorkersEndBeforeThePoolGoes) {
  RenderThreads pool(3);
  pool.run([&](int k) { workerEnd.counts = k != 0; });
  EXPECT_EQ(workersEnded, 0);
  pool.finish();
  pool.finish();  // once is enough; again does nothing
  const auto limit = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (workersEnded < 2 && std::chrono::steady_clock::now() < limit)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  EXPECT_EQ(workersEnded, 2);
  EXPECT_THROW(pool.run([](int) {}), std::logic_error);
}

}  // namespace
}  // namespace csgray::detail
