#include "engine/span_union.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace csgray::detail {

const SpanList& SpanUnion::united() {
  result_.clear();
  if (spans_.empty()) return result_;
  std::sort(spans_.begin(), spans_.end(),
            [](const Span& a, const Span& b) { return a.in.t < b.in.t; });
  Span current = spans_.front();
  for (std::size_t i = 1; i < spans_.size(); ++i) {
    const Span& next = spans_[i];
    if (clearlyBefore(current.out.t, next.in.t)) {
      result_.push_back(current);
      current = next;
    } else if (next.out.t > current.out.t) {
      current.out = next.out;
    }
  }
  result_.push_back(current);
  return result_;
}

namespace {

struct Pool {
  std::vector<std::unique_ptr<SpanUnion>> unions;
  std::size_t depth = 0;
};

Pool& pool() {
  thread_local Pool p;
  return p;
}

}  // namespace

BorrowedSpanUnion::BorrowedSpanUnion() {
  Pool& p = pool();
  if (p.depth == p.unions.size()) p.unions.push_back(std::make_unique<SpanUnion>());
  union_ = p.unions[p.depth++].get();
  union_->clear();
}

BorrowedSpanUnion::~BorrowedSpanUnion() { --pool().depth; }

}  // namespace csgray::detail
