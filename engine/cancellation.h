// A caller's wish to stop a long computation of the library (an export,
// a check): a flag that another thread sets, read at the steps where the
// computation can stop cleanly, which then throw Cancelled.
//
// The flag is the calling thread's, set for the length of a CancelScope.
// An export reads it at each of its booleans and inside CGAL's
// corefinement (its visitor), dozens of calls below the library's entry;
// carrying it down as an argument would change each of those layers for
// one atomic load. Work that a step hands to other threads (TBB) takes the
// flag with it: cancelFlag() on the calling thread, stopIfCancelled(flag)
// on the others.
#pragma once

#include <atomic>

namespace csgray::detail {

// Thrown where a set flag is read. Not a std::exception, so that the
// export's retries and fallbacks, which catch those, let it through.
struct Cancelled {};

// Makes `flag` the calling thread's (null: none) while it lives; the flag
// before comes back after it.
class CancelScope {
 public:
  explicit CancelScope(const std::atomic<bool>* flag);
  ~CancelScope();
  CancelScope(const CancelScope&) = delete;
  CancelScope& operator=(const CancelScope&) = delete;

 private:
  const std::atomic<bool>* outer_;
};

// The calling thread's flag, or null.
const std::atomic<bool>* cancelFlag();

// Throws Cancelled when the flag is set.
inline void stopIfCancelled(const std::atomic<bool>* flag) {
  if (flag && flag->load(std::memory_order_relaxed)) throw Cancelled();
}
inline void stopIfCancelled() { stopIfCancelled(cancelFlag()); }

}  // namespace csgray::detail
