// Ends the process with a one-line error when a phase outlives its time
// limit. The script sandbox counts Lua instructions, but a call into the C
// library (a backtracking string pattern) can run for hours without
// executing any; this catches that. Only for phases that have no output
// file open, since the process ends at once.
#pragma once

#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace csgray {

class Watchdog {
 public:
  // seconds <= 0: no limit.
  Watchdog(double seconds, std::string message);
  ~Watchdog();  // the phase ended in time
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

 private:
  std::mutex mutex_;
  std::condition_variable finished_;
  bool done_ = false;
  std::thread thread_;
};

}  // namespace csgray
