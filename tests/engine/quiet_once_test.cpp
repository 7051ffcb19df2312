// std::call_once through csgray's pthread_once (engine/quiet_once.cpp):
// the function runs once, every caller returns after it has finished, and
// a function that throws leaves the flag for the next call.
#include <gtest/gtest.h>
#include <pthread.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

extern "C" int __wrap_pthread_once(pthread_once_t*, void (*)());

namespace {

TEST(QuietOnce, CallsOfPthreadOnceAreSentToIt) {
  // With --wrap, this file's reference to pthread_once is one to the wrapper.
  EXPECT_EQ(reinterpret_cast<void*>(&pthread_once), reinterpret_cast<void*>(&__wrap_pthread_once));
}

// Starts threads that wait for one another, then each calls call(i).
template <class Call>
void runTogether(int threads, Call call) {
  std::atomic<int> ready{0};
  std::vector<std::thread> pool;
  for (int i = 0; i < threads; ++i)
    pool.emplace_back([&, i] {
      ++ready;
      while (ready.load() < threads) std::this_thread::yield();
      call(i);
    });
  for (std::thread& t : pool) t.join();
}

TEST(QuietOnce, ManyThreadsRunTheFunctionOnceAndReturnAfterIt) {
  for (int round = 0; round < 20; ++round) {
    std::once_flag flag;
    std::atomic<int> runs{0};
    int value = 0;  // written by the one run, read by all: call_once orders them
    std::atomic<int> sawValue{0};
    runTogether(6, [&](int) {
      std::call_once(flag, [&] {
        ++runs;
        // Long enough for the others to find it running and sleep.
        std::this_thread::sleep_for(std::chrono::milliseconds(round % 2 ? 5 : 0));
        value = 42;
      });
      if (value == 42) ++sawValue;
    });
    EXPECT_EQ(runs.load(), 1) << "round " << round;
    EXPECT_EQ(sawValue.load(), 6) << "round " << round;
  }
}

TEST(QuietOnce, AFunctionThatThrowsLeavesTheFlagForTheNextCall) {
  std::once_flag flag;
  int runs = 0;
  EXPECT_THROW(std::call_once(flag,
                              [&] {
                                ++runs;
                                throw std::runtime_error("first try");
                              }),
               std::runtime_error);
  std::call_once(flag, [&] { ++runs; });
  std::call_once(flag, [&] { ++runs; });
  EXPECT_EQ(runs, 2);
}

TEST(QuietOnce, AThreadThatWaitsOnAThrowingRunRunsTheFunctionItself) {
  std::once_flag flag;
  std::atomic<int> runs{0}, throws{0}, finished{0};
  runTogether(2, [&](int) {
    try {
      std::call_once(flag, [&] {
        // The first run sleeps (so the other thread waits on it) and throws.
        if (++runs == 1) {
          std::this_thread::sleep_for(std::chrono::milliseconds(20));
          throw std::runtime_error("first run");
        }
      });
      ++finished;
    } catch (const std::runtime_error&) {
      ++throws;
    }
  });
  EXPECT_EQ(runs.load(), 2);
  EXPECT_EQ(throws.load(), 1);
  EXPECT_EQ(finished.load(), 1);
}

}  // namespace
