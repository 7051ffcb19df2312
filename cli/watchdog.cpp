#include "cli/watchdog.h"

#include <signal.h>
#include <sys/time.h>
#include <unistd.h>

#include <cmath>

namespace csgray::detail {

namespace {

// What the handler writes, or the flag it sets; set before the timer is
// armed.
const char* alarmLine = nullptr;
std::size_t alarmLength = 0;
std::atomic<bool>* alarmFlag = nullptr;
static_assert(std::atomic<bool>::is_always_lock_free, "a lock-free store is signal-safe");

// Only async-signal-safe calls (POSIX.1-2017, 2.4.3): write and _exit, or
// a lock-free atomic store.
void onAlarm(int) {
  if (alarmFlag) {
    alarmFlag->store(true);
    return;
  }
  ssize_t written = ::write(STDERR_FILENO, alarmLine, alarmLength);
  (void)written;
  ::_exit(1);
}

}  // namespace

Watchdog::Watchdog(double seconds, std::string message)
    : line_("csgray: error: " + std::move(message) + "\n") {
  if (!(seconds > 0.0)) return;
  alarmLine = line_.c_str();
  alarmLength = line_.size();
  alarmFlag = nullptr;
  arm(seconds, 0);
}

Watchdog::Watchdog(double seconds, std::atomic<bool>& flag) {
  if (!(seconds > 0.0)) return;
  alarmFlag = &flag;
  // The process goes on: system calls the signal interrupts are restarted.
  arm(seconds, SA_RESTART);
}

void Watchdog::arm(double seconds, int flags) {
  struct sigaction action {};
  action.sa_handler = onAlarm;
  action.sa_flags = flags;
  sigemptyset(&action.sa_mask);
  if (::sigaction(SIGALRM, &action, nullptr) != 0) return;
  itimerval timer{};
  double whole = std::floor(seconds);
  timer.it_value.tv_sec = time_t(whole);
  timer.it_value.tv_usec = suseconds_t((seconds - whole) * 1e6);
  if (timer.it_value.tv_sec == 0 && timer.it_value.tv_usec == 0) timer.it_value.tv_usec = 1;
  armed_ = ::setitimer(ITIMER_REAL, &timer, nullptr) == 0;
}

Watchdog::~Watchdog() {
  if (!armed_) return;
  itimerval off{};
  ::setitimer(ITIMER_REAL, &off, nullptr);
  // Ignored rather than the default, which ends the process: an alarm
  // raised just before the timer was stopped may still be on its way.
  ::signal(SIGALRM, SIG_IGN);
}

}  // namespace csgray::detail
