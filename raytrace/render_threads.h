// The threads a render runs on: the caller and threads − 1 workers, which
// take tiles from a shared counter (renderer.cpp). They are made before the
// script runs and sleep while it does; wake() sets them spinning once the
// scene is made, and they spin for a while after each job before they sleep
// again, so that the render's first tiles start on every core at once: on
// a virtual machine a sleeping core can take milliseconds to wake, a few
// percent of a render of a tenth of a second. (They do not spin while the
// script runs: here a spinning thread slowed the script's thread by a
// third.)
#pragma once

#include <atomic>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace csgray::detail {

class RenderThreads {
 public:
  // threads in all, the caller included; 0: one per core.
  explicit RenderThreads(int threads = 0);
  RenderThreads(const RenderThreads&) = delete;
  RenderThreads& operator=(const RenderThreads&) = delete;
  ~RenderThreads();

  int size() const { return int(workers_.size()) + 1; }
  // The cores this process may run on: the number of threads for 0.
  static int cores();

  // Sets the sleeping threads spinning, for a job that is about to come.
  void wake();

  // Runs work(k) on every thread, k = 0 .. size() − 1, the caller's being
  // 0, and returns when all are done, rethrowing the first exception any
  // of them threw.
  void run(const std::function<void(int)>& work);

  // Lets the workers end, without waiting for them: no job may follow.
  // The destructor then only collects them, so that their exits overlap
  // whatever the caller does next (writing the image).
  void finish();

 private:
  void serve(int index);
  void failed();

  std::vector<std::thread> workers_;
  // Bumped for each job, each wake and to stop; the threads wait for it to
  // change. A bump is a job if workJob_ holds its number.
  std::atomic<std::uint64_t> bump_{0};
  std::atomic<std::uint64_t> workJob_{0};
  std::atomic<int> running_{0};  // workers still on the current job
  std::atomic<bool> stop_{false};
  const std::function<void(int)>* work_ = nullptr;
  std::mutex errorMutex_;
  std::exception_ptr error_;
};

}  // namespace csgray::detail
