#include "raytrace/render_threads.h"

#include <algorithm>
#include <chrono>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace csgray {

namespace {

// How long an idle worker spins before it sleeps: longer than the script
// of most parts takes, short enough not to matter to anyone else. (GNU
// OpenMP's threads spin in the same way before they sleep, GOMP_SPINCOUNT.)
constexpr auto kSpin = std::chrono::milliseconds(50);

void pause() {
#if defined(__SSE2__)
  _mm_pause();
#endif
}

}  // namespace

RenderThreads::RenderThreads(int threads) {
  if (threads <= 0) threads = int(std::max(1u, std::thread::hardware_concurrency()));
  workers_.reserve(threads - 1);
  for (int k = 1; k < threads; ++k) workers_.emplace_back([this, k] { serve(k); });
}

RenderThreads::~RenderThreads() {
  stop_.store(true, std::memory_order_relaxed);
  job_.fetch_add(1, std::memory_order_release);
  job_.notify_all();
  for (std::thread& t : workers_) t.join();
}

void RenderThreads::failed() {
  std::lock_guard<std::mutex> lock(errorMutex_);
  if (!error_) error_ = std::current_exception();
}

void RenderThreads::run(const std::function<void(int)>& work) {
  work_ = &work;
  error_ = nullptr;
  running_.store(int(workers_.size()), std::memory_order_relaxed);
  job_.fetch_add(1, std::memory_order_release);  // publishes work_ and running_
  job_.notify_all();
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
  for (;;) {
    const auto sleepAt = std::chrono::steady_clock::now() + kSpin;
    std::uint64_t job;
    while ((job = job_.load(std::memory_order_acquire)) == seen) {
      if (std::chrono::steady_clock::now() < sleepAt) {
        pause();
      } else {
        job_.wait(seen, std::memory_order_acquire);
      }
    }
    seen = job;
    if (stop_.load(std::memory_order_relaxed)) return;
    try {
      (*work_)(index);
    } catch (...) {
      failed();
    }
    if (running_.fetch_sub(1, std::memory_order_acq_rel) == 1) running_.notify_one();
  }
}

}  // namespace csgray
