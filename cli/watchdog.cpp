#include "cli/watchdog.h"

#include <signal.h>
#include <sys/time.h>
#include <unistd.h>

#include <cmath>

namespace csgray::detail {

namespace {

// What the handler writes; set before the timer is armed.
const char* alarmLine = nullptr;
std::size_t alarmLength = 0;

// Only async-signal-safe calls (POSIX.1-2017, 2.4.3): write and _exit.
void onAlarm(int) {
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
  struct sigaction action {};
  action.sa_handler = onAlarm;
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
  ::signal(SIGALRM, SIG_DFL);
}

}  // namespace csgray::detail
