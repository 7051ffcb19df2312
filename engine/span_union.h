// The union of many span lists, gathered one list at a time: a ray that
// crosses a plate drilled by a loop (s = s - hole, thousands of times)
// meets hundreds of holes, and subtracting them one by one from a result
// with a gap for each hole before costs the square of their number. Here
// the spans are gathered, sorted by where they start and joined in one
// sweep where they overlap or touch (closer than kSameT, as the booleans
// join them), n log n in all, and the union is subtracted once.
#pragma once

#include <vector>

#include "engine/span_list.h"

namespace csgray::detail {

class SpanUnion {
 public:
  void clear() { spans_.clear(); }
  bool empty() const { return spans_.empty(); }
  void add(const SpanList& spans) { spans_.insert(spans_.end(), spans.begin(), spans.end()); }
  // The union of every list added since clear().
  const SpanList& united();

 private:
  std::vector<Span> spans_;
  SpanList result_;
};

// A SpanUnion for the calling thread at the current depth of booleans
// nested in booleans (each depth has its own, kept between rays so that
// a ray allocates nothing once they have grown), held while alive.
class BorrowedSpanUnion {
 public:
  BorrowedSpanUnion();
  ~BorrowedSpanUnion();
  BorrowedSpanUnion(const BorrowedSpanUnion&) = delete;
  BorrowedSpanUnion& operator=(const BorrowedSpanUnion&) = delete;
  SpanUnion& operator*() const { return *union_; }
  SpanUnion* operator->() const { return union_; }

 private:
  SpanUnion* union_;
};

}  // namespace csgray::detail
