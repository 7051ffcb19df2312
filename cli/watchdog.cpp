#include "cli/watchdog.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>

namespace csgray {

Watchdog::Watchdog(double seconds, std::string message) {
  if (seconds <= 0.0) return;
  thread_ = std::thread([this, seconds, message = std::move(message)] {
    std::unique_lock<std::mutex> lock(mutex_);
    if (finished_.wait_for(lock, std::chrono::duration<double>(seconds), [this] { return done_; }))
      return;
    std::fprintf(stderr, "csgray: error: %s\n", message.c_str());
    std::fflush(stderr);
    std::_Exit(1);
  });
}

Watchdog::~Watchdog() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    done_ = true;
  }
  finished_.notify_one();
  thread_.join();
}

}  // namespace csgray
