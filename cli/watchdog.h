// Ends the process with a one-line error when a phase outlives its time
// limit. The script sandbox counts Lua instructions, but a call into the C
// library (a backtracking string pattern) can run for hours without
// executing any; this catches that, and ends --timeout in the export's
// booleans and the check. Only for phases that have no output file open,
// since the process ends at once. For work that stops cleanly by itself
// (the renderer, at each pixel), it raises a flag instead.
//
// A real-time interval timer (setitimer) raises SIGALRM at the limit, and
// the handler writes the message and exits: no thread to start and join
// around every script. One watchdog at a time, and nothing else in csgray
// uses SIGALRM.
#pragma once

#include <atomic>
#include <string>

namespace csgray::detail {

class Watchdog {
 public:
  // seconds <= 0: no limit.
  Watchdog(double seconds, std::string message);
  // Sets flag at the limit and lets the process go on.
  Watchdog(double seconds, std::atomic<bool>& flag);
  ~Watchdog();  // the phase ended in time
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

 private:
  std::string line_;  // "csgray: error: <message>\n", written by the handler
  bool armed_ = false;
  // Sets the handler (with sigaction's flags) and starts the timer.
  void arm(double seconds, int flags);
};

}  // namespace csgray::detail
