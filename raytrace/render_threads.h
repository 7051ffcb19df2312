// The threads a render runs on: the caller and threads − 1 workers, which
// take tiles from a shared counter (renderer.cpp). They are made before the
// scene is (while the script runs), and between jobs they spin for a while
// before they sleep, so that the render's first tiles start on every core
// at once: on a virtual machine a sleeping core can take milliseconds to
// wake, a few percent of a render of a tenth of a second.
#pragma once

#include <atomic>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace csgray {

class RenderThreads {
 public:
  // threads in all, the caller included; 0: one per core.
  explicit RenderThreads(int threads = 0);
  RenderThreads(const RenderThreads&) = delete;
  RenderThreads& operator=(const RenderThreads&) = delete;
  ~RenderThreads();

  int size() const { return int(workers_.size()) + 1; }

  // Runs work(k) on every thread, k = 0 .. size() − 1, the caller's being
  // 0, and returns when all are done, rethrowing the first exception any
  // of them threw.
  void run(const std::function<void(int)>& work);

 private:
  void serve(int index);
  void failed();

  std::vector<std::thread> workers_;
  std::atomic<std::uint64_t> job_{0};  // bumped for each job, and to stop
  std::atomic<int> running_{0};        // workers still on the current job
  std::atomic<bool> stop_{false};
  const std::function<void(int)>* work_ = nullptr;
  std::mutex errorMutex_;
  std::exception_ptr error_;
};

}  // namespace csgray
