// Ends the process with a one-line error when a phase outlives its time
// limit. The script sandbox counts Lua instructions, but a call into the C
// library (a backtracking string pattern) can run for hours without
// executing any; this catches that. Only for phases that have no output
// file open, since the process ends at once.
//
// A real-time interval timer (setitimer) raises SIGALRM at the limit, and
// the handler writes the message and exits: no thread to start and join
// around every script. One watchdog at a time, and nothing else in csgray
// uses SIGALRM.
#pragma once

#include <string>

namespace csgray::detail {

class Watchdog {
 public:
  // seconds <= 0: no limit.
  Watchdog(double seconds, std::string message);
  ~Watchdog();  // the phase ended in time
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

 private:
  std::string line_;  // "csgray: error: <message>\n", written by the handler
  bool armed_ = false;
};

}  // namespace csgray::detail
