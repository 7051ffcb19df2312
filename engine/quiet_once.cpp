// std::call_once without a system call where no thread waits.
//
// libstdc++'s std::call_once is pthread_once, and glibc's pthread_once
// (nptl/pthread_once.c, __pthread_once_slow) ends every first call of a
// flag with a futex wake-up, whether or not another thread waits on it.
// CGAL's lazy exact numbers (the plane's regions and offsets, the
// exporter's exact booleans) compute each exact value under its own
// std::call_once, so every value made exact cost a system call: 946 000
// of them in one import of OpenSCAD's GEB example, half of its time on
// this machine's virtual processors (docs/performance.md, 2026-11-27).
//
// Every link of csgray's code is made with --wrap=pthread_once
// (engine/CMakeLists.txt), so the calls compiled into csgray, CGAL's
// header code among them, come here; other libraries in the process keep
// glibc's. The flag's word holds glibc's states (0: not run, 1: running,
// 2: done), and a waiter sets a bit of its own before it sleeps, so that
// the thread that ran the function wakes sleepers only when there are
// some (the protocol of Drepper's "Futexes are tricky", 2011, mutex 2).
// As in glibc, a function that throws leaves the flag not run, for the
// next call to try again.
#include <linux/futex.h>
#include <pthread.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <climits>

namespace {

constexpr int kRunning = 1;
constexpr int kDone = 2;
constexpr int kWaiters = 4;

void wakeAll(pthread_once_t* flag) {
  syscall(SYS_futex, flag, FUTEX_WAKE_PRIVATE, INT_MAX, nullptr, nullptr, 0);
}

// Sleeps while the flag still holds state (a spurious or early return
// only sends the caller round its loop again).
void waitWhile(pthread_once_t* flag, int state) {
  syscall(SYS_futex, flag, FUTEX_WAIT_PRIVATE, state, nullptr, nullptr, 0);
}

}  // namespace

extern "C" int __wrap_pthread_once(pthread_once_t* flag, void (*function)()) {
  std::atomic_ref<int> word(*flag);
  for (;;) {
    int state = word.load(std::memory_order_acquire);
    if (state & kDone) return 0;
    if (state == 0) {
      if (!word.compare_exchange_weak(state, kRunning, std::memory_order_acquire)) continue;
      try {
        function();
      } catch (...) {
        if (word.exchange(0, std::memory_order_release) & kWaiters) wakeAll(flag);
        throw;
      }
      if (word.exchange(kDone, std::memory_order_release) & kWaiters) wakeAll(flag);
      return 0;
    }
    // Another thread runs the function: say that one waits, then sleep.
    if (!(state & kWaiters) &&
        !word.compare_exchange_weak(state, state | kWaiters, std::memory_order_relaxed))
      continue;
    waitWhile(flag, state | kWaiters);
  }
}
