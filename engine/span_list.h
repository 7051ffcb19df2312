// Spans: where a ray is inside a solid. A SpanList is the answer to "where is
// the solid along this line?" that rendering, volumes and classification all
// ask. Booleans on solids become linear merges of their span lists.
#pragma once

#include <cmath>
#include <cstdint>
#include <memory>

#include "engine/ray.h"

namespace csgray::detail {

class Primitive;

// Boundaries this close (relative to t) are one point: faces that coincide
// in the model differ by rounding once each primitive has computed t in its
// own frame. Far above that rounding (~1e-15), far below any feature.
inline constexpr double kSameT = 1e-10;

// One end of a span: the ray parameter, the primitive whose surface lies
// there (null at ±infinity) and which face of it. Normals and materials are
// looked up from the primitive only for the boundary that is finally shaded.
struct Boundary {
  double t = 0.0;
  const Primitive* primitive = nullptr;
  std::uint32_t face = 0;  // primitive-specific face index (box side, cylinder cap, plane, ...)
  bool flip = false;       // the surface of a subtracted solid faces the other way
};

struct Span {
  Boundary in, out;
  double length() const { return out.t - in.t; }
};

// Sorted, disjoint spans with in.t <= out.t. Holds a few spans inline, so
// the common case allocates nothing; grows on the heap past that.
class SpanList {
 public:
  static constexpr std::uint32_t kInline = 8;

  SpanList() = default;
  SpanList(const SpanList& other) { *this = other; }
  SpanList& operator=(const SpanList& other);

  void clear() { size_ = 0; }
  bool empty() const { return size_ == 0; }
  std::uint32_t size() const { return size_; }
  const Span& operator[](std::uint32_t i) const { return data_[i]; }
  const Span* begin() const { return data_; }
  const Span* end() const { return data_ + size_; }
  const Span& front() const { return data_[0]; }
  const Span& back() const { return data_[size_ - 1]; }

  void push_back(const Span& s) {
    if (size_ == capacity_) grow();
    data_[size_++] = s;
  }
  void push_back(const Boundary& in, const Boundary& out) { push_back(Span{in, out}); }

  // Sum of span lengths clipped to [t0, t1].
  double lengthWithin(double t0, double t1) const;
  // Does some span reach into the open window (t0, t1)?
  bool meetsOpenWindow(double t0, double t1) const;

  // Are all the invariants true: sorted, disjoint, in <= out, no NaN?
  bool valid() const;

 private:
  void grow();

  // Inline storage left uninitialised: a list is made for every ray and
  // every boolean node, and only its first size_ spans are ever read.
  union Storage {
    Storage() {}
    Span spans[kInline];
  } inline_;
  std::unique_ptr<Span[]> heap_;
  Span* data_ = inline_.spans;
  std::uint32_t size_ = 0;
  std::uint32_t capacity_ = kInline;
};

// Is y after x by more than kSameT, the distance at which the booleans
// below make boundaries one point? False for NaN, and for x = −∞ or
// y = x = +∞.
inline bool clearlyBefore(double x, double y) { return y > x + kSameT * std::abs(x); }

// Are no two of the four boundaries of a and b within that distance? Then
// the booleans of the two single spans come down to comparisons.
inline bool apartSingleSpans(const Span& a, const Span& b) {
  auto apart = [](double x, double y) { return x < y ? clearlyBefore(x, y) : clearlyBefore(y, x); };
  return clearlyBefore(a.in.t, a.out.t) && clearlyBefore(b.in.t, b.out.t) &&
         apart(a.in.t, b.in.t) && apart(a.out.t, b.out.t) && apart(a.in.t, b.out.t) &&
         apart(a.out.t, b.in.t);
}

// intersect()'s result for two single spans whose boundaries are apart:
// from the later entry to the earlier exit, if that comes after it.
enum class ApartIntersection { NotApart, Empty, One };
inline ApartIntersection intersectApartSingleSpans(const Span& a, const Span& b, Span& both) {
  if (!apartSingleSpans(a, b)) return ApartIntersection::NotApart;
  const Boundary& in = a.in.t < b.in.t ? b.in : a.in;
  const Boundary& exit = a.out.t < b.out.t ? a.out : b.out;
  if (!(in.t < exit.t)) return ApartIntersection::Empty;
  both = Span{in, exit};
  return ApartIntersection::One;
}

// a ∩ b written over a, when both are single spans whose boundaries are
// apart: what intersect() gives, without its call and a second list (the
// operands of a lens: 0.7 % of lens_field). False, a untouched, otherwise.
inline bool intersectSingleSpansInPlace(SpanList& a, const SpanList& b) {
  if (a.size() != 1 || b.size() != 1) return false;
  Span both;
  const ApartIntersection result = intersectApartSingleSpans(a[0], b[0], both);
  if (result == ApartIntersection::NotApart) return false;
  a.clear();
  if (result == ApartIntersection::One) a.push_back(both);
  return true;
}

// Regularised booleans of two span lists, written to out (which must not be
// a or b). Spans of zero length that a boolean produces are dropped; the
// boundaries of b in a difference have their flip toggled.
void unite(const SpanList& a, const SpanList& b, SpanList& out);
void intersect(const SpanList& a, const SpanList& b, SpanList& out);
void subtract(const SpanList& a, const SpanList& b, SpanList& out);

}  // namespace csgray::detail
