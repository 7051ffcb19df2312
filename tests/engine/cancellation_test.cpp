// The calling thread's cancel flag (engine/cancellation.h).
#include "engine/cancellation.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

namespace csgray::detail {
namespace {

TEST(Cancellation, AScopeSetsTheFlagOfItsThreadAndGivesTheOuterOneBack) {
  std::atomic<bool> outer = false, inner = true;
  EXPECT_EQ(cancelFlag(), nullptr);
  EXPECT_NO_THROW(stopIfCancelled());  // no flag: nothing to stop
  {
    const CancelScope a(&outer);
    EXPECT_EQ(cancelFlag(), &outer);
    EXPECT_NO_THROW(stopIfCancelled());
    {
      const CancelScope b(&inner);
      EXPECT_EQ(cancelFlag(), &inner);
      EXPECT_THROW(stopIfCancelled(), Cancelled);
      // Another thread has its own flag: none.
      const std::atomic<bool>* seen = &outer;
      std::thread([&] { seen = cancelFlag(); }).join();
      EXPECT_EQ(seen, nullptr);
    }
    EXPECT_EQ(cancelFlag(), &outer);
    outer = true;
    EXPECT_THROW(stopIfCancelled(), Cancelled);
    // A flag handed to another thread is read there.
    bool stopped = false;
    std::thread([&, flag = cancelFlag()] {
      try {
        stopIfCancelled(flag);
      } catch (const Cancelled&) {
        stopped = true;
      }
    }).join();
    EXPECT_TRUE(stopped);
  }
  EXPECT_EQ(cancelFlag(), nullptr);
}

}  // namespace
}  // namespace csgray::detail
