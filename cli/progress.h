// A progress bar on stderr for renders that take longer than a second,
// shown only when stderr is a terminal (never in logs or pipes).
#pragma once

#include <chrono>
#include <mutex>

namespace csgray::detail {

class ProgressBar {
 public:
  explicit ProgressBar(const char* label);
  ~ProgressBar();  // clears the bar's line
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // The share done, in [0, 1]; safe to call from any thread.
  void update(double fraction);

 private:
  const char* label_;
  bool terminal_;
  bool shown_ = false;
  int lastPercent_ = -1;
  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
};

}  // namespace csgray::detail
