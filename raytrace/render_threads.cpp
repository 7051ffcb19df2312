#include "raytrace/render_threads.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#if defined(__linux__)
#include <sched.h>
#endif

namespace csgray::detail {

namespace {

// How long a woken thread spins before it sleeps: longer than making the
// renderer from a scene takes, and than the step between the passes of an
// adaptive render. (GNU OpenMP's threads spin in the same way before they
// sleep, GOMP_SPINCOUNT.)
constexpr auto kSpin = std::chrono::milliseconds(50);

}  // namespace

int RenderThreads::cores() {
#if defined(__linux__)
  // The cores this process may run on (taskset, a container's cpuset), not
  // all the machine has.
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof(set), &set) == 0) return std::max(1, CPU_COUNT(&set));
#endif
  return int(std::max(1u, std::thread::hardware_concurrency()));
}

RenderThreads::RenderThreads(int threads) {
  if (threads <= 0) threads = cores();
  workers_.reserve(threads - 1);
  for (int k = 1; k < threads; ++k) workers_.emplace_back([this, k] { serve(k); });
}

RenderThreads::~RenderThreads() {
  finish();
  for (std::thread& t : workers_) t.join();
}

void RenderThreads::finish() {
  if (stop_.exchange(true, std::memory_order_relaxed)) return;
  bump_.fetch_add(1, std::memory_order_release);
  bump_.notify_all();
}

void RenderThreads::failed() {
  std::lock_guard<std::mutex> lock(errorMutex_);
  if (!error_) error_ = std::current_exception();
}

void RenderThreads::wake() {
  bump_.fetch_add(1, std::memory_order_release);
  bump_.notify_all();
}

void RenderThreads::run(const std::function<void(int)>& work) {
  if (stop_.load(std::memory_order_relaxed))
    throw std::logic_error("RenderThreads::run after finish: the workers have ended");
  work_ = &work;
  error_ = nullptr;
  running_.store(int(workers_.size()), std::memory_order_relaxed);
  // Publishes work_ and running_ with the job's number, then the job.
  workJob_.store(bump_.load(std::memory_order_relaxed) + 1, std::memory_order_release);
  bump_.fetch_add(1, std::memory_order_release);
  bump_.notify_all();
  try {
    work(0);
  } catch (...) {
    failed();
  }
  for (int left; (left = running_.load(std::memory_order_acquire)) != 0;)
    running_.wait(left, std::memory_order_acquire);
  work_ = nullptr;
  if (error_) std::rethrow_exception(error_);
}

void RenderThreads::serve(int index) {
  std::uint64_t seen = 0;
  bool spin = false;  // asleep until the first wake or job
  for (;;) {
    const auto sleepAt = std::chrono::steady_clock::now() + kSpin;
    std::uint64_t bump;
    while ((bump = bump_.load(std::memory_order_acquire)) == seen) {
      if (spin && std::chrono::steady_clock::now() < sleepAt) {
        std::this_thread::yield();  // to any thread with work, if there are more than cores
      } else {
        bump_.wait(seen, std::memory_order_acquire);
      }
    }
    seen = bump;
    spin = true;
    if (stop_.load(std::memory_order_relaxed)) return;
    // A wake, or a job this thread woke too late to see as one (it has
    // seen a later bump, and comes round to that job next).
    if (workJob_.load(std::memory_order_acquire) != bump) continue;
    try {
      (*work_)(index);
    } catch (...) {
      failed();
    }
    if (running_.fetch_sub(1, std::memory_order_acq_rel) == 1) running_.notify_one();
  }
}

}  // namespace csgray::detail
