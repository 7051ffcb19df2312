#include "engine/span_list.h"

#include <algorithm>
#include <cmath>

namespace csgray::detail {

SpanList& SpanList::operator=(const SpanList& other) {
  if (this == &other) return *this;
  size_ = 0;
  while (capacity_ < other.size_) grow();
  std::copy(other.begin(), other.end(), data_);
  size_ = other.size_;
  return *this;
}

void SpanList::grow() {
  std::uint32_t capacity = capacity_ * 2;
  auto heap = std::make_unique<Span[]>(capacity);
  std::copy(begin(), end(), heap.get());
  heap_ = std::move(heap);
  data_ = heap_.get();
  capacity_ = capacity;
}

double SpanList::lengthWithin(double t0, double t1) const {
  double sum = 0.0;
  for (const Span& s : *this) {
    double a = std::max(s.in.t, t0), b = std::min(s.out.t, t1);
    if (b > a) sum += b - a;
  }
  return sum;
}

bool SpanList::meetsOpenWindow(double t0, double t1) const {
  for (const Span& s : *this)
    if (s.out.t > t0 && s.in.t < t1) return true;
  return false;
}

bool SpanList::valid() const {
  for (std::uint32_t i = 0; i < size_; ++i) {
    const Span& s = data_[i];
    if (std::isnan(s.in.t) || std::isnan(s.out.t) || s.in.t > s.out.t) return false;
    if (i > 0 && data_[i - 1].out.t >= s.in.t) return false;
  }
  return true;
}

namespace {

enum class Op { Union, Intersection, Difference };

bool combine(Op op, bool inA, bool inB) {
  switch (op) {
    case Op::Union:
      return inA || inB;
    case Op::Intersection:
      return inA && inB;
    case Op::Difference:
      return inA && !inB;
  }
  return false;
}

// A cursor over the 2n boundaries of a span list, in order.
struct Cursor {
  const SpanList& list;
  std::uint32_t index = 0;  // boundary index: span index * 2 + (0: in, 1: out)

  bool done() const { return index >= 2 * list.size(); }
  double t() const { return done() ? kInfinity : boundary().t; }
  const Boundary& boundary() const {
    const Span& s = list[index / 2];
    return index % 2 ? s.out : s.in;
  }
};

// Sweep both lists' boundaries in order of t, grouping equal t, and emit a
// boundary wherever the combined inside/outside state changes. Grouping
// makes the result regular: spans that touch merge, and spans that only
// touch produce no zero-length intersection.
void merge(Op op, const SpanList& a, const SpanList& b, SpanList& out) {
  out.clear();
  Cursor ca{a}, cb{b};
  bool inA = false, inB = false, inside = false;
  Boundary start;
  while (!ca.done() || !cb.done()) {
    // Nothing later can be inside an intersection once either list has
    // ended, nor inside a difference once a has.
    if (!inside &&
        (op == Op::Intersection ? ca.done() || cb.done() : op == Op::Difference && ca.done()))
      break;
    double t = std::min(ca.t(), cb.t());
    // Infinite boundaries group only with themselves (inf <= inf + inf).
    double last = std::isinf(t) ? t : t + kSameT * std::abs(t);
    bool wasA = inA;
    Boundary lastA, lastB;
    // "Not after" rather than "at or before": a NaN boundary (a solid of
    // 10³⁰⁰ seen from as far) is taken with everything after it, where
    // "at or before" took nothing and the sweep never ended.
    while (!ca.done() && !(ca.t() > last)) {
      lastA = ca.boundary();
      inA = !inA;
      ++ca.index;
    }
    while (!cb.done() && !(cb.t() > last)) {
      lastB = cb.boundary();
      if (op == Op::Difference) lastB.flip = !lastB.flip;
      inB = !inB;
      ++cb.index;
    }
    bool now = combine(op, inA, inB);
    if (now == inside) continue;
    // The boundary of the result is that of whichever operand changed state
    // (a zero-length span of a at this t, a tangent ray, changes nothing);
    // when both did at the same t, either is the same point, so prefer a.
    const Boundary& here = inA != wasA ? lastA : lastB;
    // Boundaries at (nearly) equal t were grouped, so a span that ends here
    // started clearly before: the result has no zero-length spans.
    if (now) {
      start = here;
    } else {
      out.push_back(start, here);
    }
    inside = now;
  }
}

// merge's result for two single spans, the common case of booleans of
// convex solids (a lens: two balls and a cylinder, less an ellipsoid), when
// no two of the four boundaries are within that distance (apartSingleSpans).
// Returns false, leaving out alone, when they are not so far apart.
bool mergeApartSingleSpans(Op op, const Span& a, const Span& b, SpanList& out) {
  if (op == Op::Intersection) {
    Span both;
    const ApartIntersection result = intersectApartSingleSpans(a, b, both);
    if (result == ApartIntersection::NotApart) return false;
    out.clear();
    if (result == ApartIntersection::One) out.push_back(both);
    return true;
  }
  if (!apartSingleSpans(a, b)) return false;
  out.clear();
  // Difference: a where b is not, b's boundaries facing the other way.
  if (b.out.t < a.in.t || a.out.t < b.in.t) {
    out.push_back(a);
    return true;
  }
  Boundary holeIn = b.in, holeOut = b.out;
  holeIn.flip = !holeIn.flip;
  holeOut.flip = !holeOut.flip;
  if (a.in.t < b.in.t) out.push_back(a.in, holeIn);
  if (b.out.t < a.out.t) out.push_back(holeOut, a.out);
  return true;
}

}  // namespace

void unite(const SpanList& a, const SpanList& b, SpanList& out) { merge(Op::Union, a, b, out); }
void intersect(const SpanList& a, const SpanList& b, SpanList& out) {
  if (a.size() == 1 && b.size() == 1 && mergeApartSingleSpans(Op::Intersection, a[0], b[0], out))
    return;
  merge(Op::Intersection, a, b, out);
}
void subtract(const SpanList& a, const SpanList& b, SpanList& out) {
  if (a.size() == 1 && b.size() == 1 && mergeApartSingleSpans(Op::Difference, a[0], b[0], out))
    return;
  merge(Op::Difference, a, b, out);
}

}  // namespace csgray::detail
