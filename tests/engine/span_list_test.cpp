// The span-list engine: unite/intersect/subtract are the regularised
// booleans of the point sets on the line, checked against a brute-force
// reference on random lists; plus the boundary bookkeeping (which operand a
// boundary comes from, flip in a difference) and the container itself.
#include "engine/span_list.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "primitives/sphere.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

// Two real primitives used only as tags: a boundary's primitive says which
// operand it came from. Their geometry is irrelevant here.
const Primitive* tagA() {
  static auto a = Primitive::create<Sphere>(1.0);
  return a.get();
}
const Primitive* tagB() {
  static auto b = Primitive::create<Sphere>(1.0);
  return b.get();
}

// A boundary as a primitive reports it; infinite ends carry no primitive.
Boundary bound(double t, const Primitive* tag, int face = 0, bool flip = false) {
  if (std::isinf(t)) tag = nullptr;
  return Boundary{t, tag, static_cast<std::uint8_t>(face), flip};
}

using Intervals = std::vector<std::pair<double, double>>;

// Spans whose boundary k (2·span + 0/1) has face k, so each is identifiable.
SpanList makeList(const Intervals& intervals, const Primitive* tag,
                  const std::vector<bool>& flips = {}) {
  SpanList list;
  for (size_t i = 0; i < intervals.size(); ++i) {
    bool flipIn = flips.empty() ? false : flips[2 * i];
    bool flipOut = flips.empty() ? false : flips[2 * i + 1];
    list.push_back(bound(intervals[i].first, tag, static_cast<int>(2 * i), flipIn),
                   bound(intervals[i].second, tag, static_cast<int>(2 * i + 1), flipOut));
  }
  return list;
}

bool member(const SpanList& list, double t) {
  for (const Span& s : list)
    if (s.in.t <= t && t <= s.out.t) return true;
  return false;
}

Intervals intervalsOf(const SpanList& list) {
  Intervals out;
  for (const Span& s : list) out.emplace_back(s.in.t, s.out.t);
  return out;
}

bool sameBoundary(const Boundary& x, const Boundary& y) {
  return x.t == y.t && x.primitive == y.primitive && x.face == y.face;
}

// A random valid list: 0..6 spans with integer endpoints on a small grid
// (so that the two operands often share or touch endpoints), sometimes a
// zero-length span (a tangent ray), sometimes unbounded at either end.
Intervals randomIntervals(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> count(0, 6), gap(1, 2), len(0, 2), start(0, 3), die(0, 5);
  Intervals out;
  int n = count(rng);
  double t = start(rng);
  for (int i = 0; i < n; ++i) {
    if (i > 0) t += gap(rng);
    double in = t;
    // len 0 is a zero-length span; keep those rarer than real ones.
    double l = len(rng);
    if (l == 0 && die(rng) > 1) l = 1;
    t += l;
    out.emplace_back(in, t);
  }
  if (n > 0 && die(rng) == 0) out.front().first = -kInfinity;
  if (n > 0 && die(rng) == 0) out.back().second = kInfinity;
  return out;
}

std::vector<bool> randomFlips(std::mt19937_64& rng, size_t spans) {
  std::bernoulli_distribution coin(0.5);
  std::vector<bool> flips(2 * spans);
  for (size_t i = 0; i < flips.size(); ++i) flips[i] = coin(rng);
  return flips;
}

enum class Op { Unite, Intersect, Subtract };

const char* opName(Op op) {
  return op == Op::Unite ? "unite" : op == Op::Intersect ? "intersect" : "subtract";
}

bool apply(Op op, bool inA, bool inB) {
  switch (op) {
    case Op::Unite:
      return inA || inB;
    case Op::Intersect:
      return inA && inB;
    case Op::Subtract:
      return inA && !inB;
  }
  return false;
}

void run(Op op, const SpanList& a, const SpanList& b, SpanList& out) {
  switch (op) {
    case Op::Unite:
      unite(a, b, out);
      break;
    case Op::Intersect:
      intersect(a, b, out);
      break;
    case Op::Subtract:
      subtract(a, b, out);
      break;
  }
}

std::string describe(const SpanList& list) {
  std::string s;
  for (const Span& span : list) {
    s += '[';
    s += std::to_string(span.in.t);
    s += ", ";
    s += std::to_string(span.out.t);
    s += "] ";
  }
  return s.empty() ? "(empty)" : s;
}

// The reference: on the line, result = op(A, B) as point sets up to measure
// zero; every result boundary is a boundary of the operand whose state
// changes there, with flip toggled iff it comes from b of a difference.
void expectMatchesReference(Op op, const SpanList& a, const SpanList& b) {
  SpanList out;
  run(op, a, b, out);
  SCOPED_TRACE(std::string(opName(op)) + " a = " + describe(a) + " b = " + describe(b) + " -> " +
               describe(out));
  ASSERT_TRUE(out.valid());
  for (const Span& s : out) EXPECT_GT(s.length(), 0.0) << "zero-length span produced";

  // Membership at every midpoint between consecutive distinct endpoints and
  // beyond both ends.
  std::vector<double> ends;
  for (const SpanList* list : {&a, &b, static_cast<const SpanList*>(&out)})
    for (const Span& s : *list)
      for (double t : {s.in.t, s.out.t})
        if (std::isfinite(t)) ends.push_back(t);
  std::sort(ends.begin(), ends.end());
  ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
  std::vector<double> samples;
  if (ends.empty()) {
    samples = {-1e6, 0.0, 1e6};
  } else {
    samples.push_back(ends.front() - 1.0);
    samples.push_back(-1e300);
    for (size_t i = 1; i < ends.size(); ++i) samples.push_back(0.5 * (ends[i - 1] + ends[i]));
    samples.push_back(ends.back() + 1.0);
    samples.push_back(1e300);
  }
  for (double t : samples)
    EXPECT_EQ(member(out, t), apply(op, member(a, t), member(b, t))) << "at t = " << t;

  // Boundary provenance. Endpoints are integers, so t ± 0.5 lies strictly
  // inside the neighbouring pieces.
  for (const Span& s : out) {
    for (const Boundary* r : {&s.in, &s.out}) {
      if (std::isinf(r->t)) {
        EXPECT_EQ(r->primitive, nullptr) << "infinite end has a primitive";
        EXPECT_TRUE(r->t == (r == &s.in ? -kInfinity : kInfinity));
        continue;
      }
      bool changedA = member(a, r->t - 0.5) != member(a, r->t + 0.5);
      bool changedB = member(b, r->t - 0.5) != member(b, r->t + 0.5);
      const Boundary* fromA = nullptr;
      const Boundary* fromB = nullptr;
      for (const Span& x : a)
        for (const Boundary* c : {&x.in, &x.out})
          if (sameBoundary(*c, *r)) fromA = c;
      for (const Span& x : b)
        for (const Boundary* c : {&x.in, &x.out})
          if (sameBoundary(*c, *r)) fromB = c;
      ASSERT_TRUE(changedA || changedB)
          << "result boundary at " << r->t << " where nothing changes";
      if (changedA && !changedB) {
        ASSERT_NE(fromA, nullptr) << "boundary at t=" << r->t << " should come from a";
      } else if (changedB && !changedA) {
        ASSERT_NE(fromB, nullptr) << "boundary at t=" << r->t << " should come from b";
      } else {
        ASSERT_TRUE(fromA || fromB) << "boundary at t=" << r->t << " comes from neither operand";
      }
      if (fromA) {
        EXPECT_EQ(r->flip, fromA->flip) << "a's boundary at t=" << r->t << " changed flip";
      } else {
        bool expected = op == Op::Subtract ? !fromB->flip : fromB->flip;
        EXPECT_EQ(r->flip, expected) << "b's boundary at t=" << r->t << " has the wrong flip";
      }
    }
  }
}

TEST(SpanList, BooleansMatchBruteForceOnRandomLists) {
  std::mt19937_64 rng(20240611);
  for (int i = 0; i < 2000; ++i) {
    Intervals ia = randomIntervals(rng), ib = randomIntervals(rng);
    SpanList a = makeList(ia, tagA(), randomFlips(rng, ia.size()));
    SpanList b = makeList(ib, tagB(), randomFlips(rng, ib.size()));
    ASSERT_TRUE(a.valid() && b.valid());
    for (Op op : {Op::Unite, Op::Intersect, Op::Subtract}) {
      expectMatchesReference(op, a, b);
      if (::testing::Test::HasFailure()) return;
    }
  }
}

// Two single spans are intersected and subtracted by comparisons when their
// boundaries are clearly apart, and by the sweep otherwise: both give the
// same spans, boundary for boundary. The sweep's answer is the one for the
// same two spans with a far span added to a (which the shortcut does not
// take, and which meets nothing of b). Ends on a grid of 8 points, each
// moved by 0, ±kSameT/2 or ±2·kSameT relative, so that boundaries coincide,
// are one point to the sweep, or are just apart. The intersection written
// over a gives the same where it answers.
TEST(SpanList, SingleSpansGiveWhatTheSweepGives) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> grid(0, 7), nudge(0, 4), coin(0, 1);
  const double nudges[5] = {0.0, 0.5 * kSameT, -0.5 * kSameT, 2 * kSameT, -2 * kSameT};
  auto sameSpans = [](const SpanList& x, const SpanList& y) {
    if (x.size() != y.size()) return false;
    for (std::uint32_t i = 0; i < x.size(); ++i)
      if (!sameBoundary(x[i].in, y[i].in) || !sameBoundary(x[i].out, y[i].out) ||
          x[i].in.flip != y[i].in.flip || x[i].out.flip != y[i].out.flip)
        return false;
    return true;
  };
  // The sweep's spans less the far one, its last.
  auto withoutLast = [](const SpanList& list) {
    SpanList near;
    for (std::uint32_t i = 0; i + 1 < list.size(); ++i) near.push_back(list[i]);
    return near;
  };
  int apart = 0, close = 0, inPlaceAnswers = 0;
  for (int i = 0; i < 20000; ++i) {
    int cells[4];
    double t[4];
    for (int k = 0; k < 4; ++k) {
      cells[k] = grid(rng);
      t[k] = (cells[k] + 1.0) * (1.0 + nudges[nudge(rng)]);
    }
    if (t[0] > t[1]) std::swap(t[0], t[1]);
    if (t[2] > t[3]) std::swap(t[2], t[3]);
    std::sort(cells, cells + 4);
    (std::unique(cells, cells + 4) == cells + 4 ? apart : close) += 1;
    const std::vector<bool> flips{bool(coin(rng)), bool(coin(rng))};
    SpanList a = makeList({{t[0], t[1]}}, tagA(), flips);
    SpanList b = makeList({{t[2], t[3]}}, tagB(), flips);
    SpanList aAndFar =
        makeList({{t[0], t[1]}, {100, 101}}, tagA(), {flips[0], flips[1], false, false});
    SpanList fast, sweep;
    intersect(a, b, fast);
    intersect(aAndFar, b, sweep);
    ASSERT_TRUE(sameSpans(fast, sweep))
        << "[" << t[0] << ", " << t[1] << "] ∩ [" << t[2] << ", " << t[3] << "]";
    // Written over a (Boolean's intersections): the same, where it answers.
    SpanList inPlace = a;
    if (intersectSingleSpansInPlace(inPlace, b)) {
      ++inPlaceAnswers;
      ASSERT_TRUE(sameSpans(inPlace, sweep))
          << "in place: [" << t[0] << ", " << t[1] << "] ∩ [" << t[2] << ", " << t[3] << "]";
    } else {
      ASSERT_TRUE(sameSpans(inPlace, a)) << "left alone";
    }
    subtract(a, b, fast);
    subtract(aAndFar, b, sweep);
    ASSERT_TRUE(sameSpans(fast, withoutLast(sweep)))
        << "[" << t[0] << ", " << t[1] << "] − [" << t[2] << ", " << t[3] << "]";
  }
  // Both kinds are common: four ends in different cells are clearly apart.
  EXPECT_GT(apart, 2000);
  EXPECT_GT(close, 2000);
  EXPECT_GT(inPlaceAnswers, 2000);
}

TEST(SpanList, BooleansWithEmptyOperands) {
  SpanList empty, out;
  SpanList a = makeList({{1, 2}, {4, 5}}, tagA());
  unite(a, empty, out);
  EXPECT_EQ(intervalsOf(out), intervalsOf(a));
  unite(empty, a, out);
  EXPECT_EQ(intervalsOf(out), intervalsOf(a));
  intersect(a, empty, out);
  EXPECT_TRUE(out.empty());
  subtract(a, empty, out);
  EXPECT_EQ(intervalsOf(out), intervalsOf(a));
  subtract(empty, a, out);
  EXPECT_TRUE(out.empty());
  unite(empty, empty, out);
  EXPECT_TRUE(out.empty());
}

// [0,1] ∪ [1,2] = [0,2]: touching spans merge into one, and the result's
// ends are a's start and b's end.
TEST(SpanList, TouchingSpansMergeInUnion) {
  SpanList a = makeList({{0, 1}}, tagA()), b = makeList({{1, 2}}, tagB()), out;
  unite(a, b, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].in.t, 0.0);
  EXPECT_EQ(out[0].out.t, 2.0);
  EXPECT_EQ(out[0].in.primitive, tagA());
  EXPECT_EQ(out[0].out.primitive, tagB());
  // Same the other way round.
  unite(b, a, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].in.primitive, tagA());
  EXPECT_EQ(out[0].out.primitive, tagB());
}

// Regular booleans: spans that only touch have an empty (zero-length)
// intersection, and subtracting [1,2] from [1,2] leaves nothing.
TEST(SpanList, TouchingOrEqualSpansLeaveNoZeroLengthSpans) {
  SpanList a = makeList({{0, 1}}, tagA()), b = makeList({{1, 2}}, tagB()), out;
  intersect(a, b, out);
  EXPECT_TRUE(out.empty());
  SpanList c = makeList({{1, 2}}, tagA());
  subtract(c, b, out);
  EXPECT_TRUE(out.empty());
  // A zero-length span in a is not material: a ∩ b of [1,1] and [0,2] is empty.
  SpanList point = makeList({{1, 1}}, tagA()), wide = makeList({{0, 2}}, tagB());
  intersect(point, wide, out);
  EXPECT_TRUE(out.empty());
  unite(point, SpanList(), out);
  EXPECT_TRUE(out.empty());
}

// [0,3] − [1,2] = [0,1] ∪ [2,3]; the hole's ends come from b with flip
// toggled, the outer ends from a unchanged.
TEST(SpanList, SubtractTakesHoleBoundariesFromBAndFlipsThem) {
  SpanList a = makeList({{0, 3}}, tagA()), b = makeList({{1, 2}}, tagB()), out;
  subtract(a, b, out);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(intervalsOf(out), (Intervals{{0, 1}, {2, 3}}));
  EXPECT_EQ(out[0].in.primitive, tagA());
  EXPECT_FALSE(out[0].in.flip);
  EXPECT_EQ(out[0].out.primitive, tagB());
  EXPECT_EQ(out[0].out.face, 0);  // b's entry is the hole's first wall
  EXPECT_TRUE(out[0].out.flip);
  EXPECT_EQ(out[1].in.primitive, tagB());
  EXPECT_EQ(out[1].in.face, 1);
  EXPECT_TRUE(out[1].in.flip);
  EXPECT_EQ(out[1].out.primitive, tagA());
  EXPECT_FALSE(out[1].out.flip);

  // A boundary already flipped (b was itself subtracted somewhere) flips back.
  SpanList flipped = makeList({{1, 2}}, tagB(), {true, true});
  subtract(a, flipped, out);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_FALSE(out[0].out.flip);
  EXPECT_FALSE(out[1].in.flip);
}

// Union and intersection never touch flip.
TEST(SpanList, UniteAndIntersectKeepFlip) {
  SpanList a = makeList({{0, 2}}, tagA(), {true, false});
  SpanList b = makeList({{1, 3}}, tagB(), {false, true});
  SpanList out;
  unite(a, b, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(out[0].in.flip);   // a's in
  EXPECT_TRUE(out[0].out.flip);  // b's out
  intersect(a, b, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].in.primitive, tagB());
  EXPECT_FALSE(out[0].in.flip);  // b's in
  EXPECT_EQ(out[0].out.primitive, tagA());
  EXPECT_FALSE(out[0].out.flip);  // a's out
}

// A result boundary belongs to the operand whose inside/outside state
// changes there: a zero-length span of a at t (a tangent ray) must not
// stand in for b's entry at the same t.
TEST(SpanList, BoundaryComesFromOperandThatChanges) {
  SpanList a = makeList({{1, 1}}, tagA()), b = makeList({{1, 3}}, tagB()), out;
  unite(a, b, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].in.primitive, tagB());
  EXPECT_EQ(out[0].in.face, 0);
  SpanList c = makeList({{-1, 1}}, tagB());
  SpanList d = makeList({{1, 1}}, tagA());
  unite(d, c, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].out.primitive, tagB());
  EXPECT_EQ(out[0].out.face, 1);
}

// Unbounded spans: (-inf, 2] ∪ [5, inf) minus [0, 6] is (-inf, 0] ∪ [6, inf).
TEST(SpanList, UnboundedEnds) {
  SpanList a = makeList({{-kInfinity, 2}, {5, kInfinity}}, tagA());
  SpanList b = makeList({{0, 6}}, tagB());
  SpanList out;
  subtract(a, b, out);
  EXPECT_EQ(intervalsOf(out), (Intervals{{-kInfinity, 0}, {6, kInfinity}}));
  EXPECT_EQ(out[0].in.primitive, nullptr);
  EXPECT_EQ(out[1].out.primitive, nullptr);
  unite(a, b, out);
  EXPECT_EQ(intervalsOf(out), (Intervals{{-kInfinity, kInfinity}}));
  SpanList all = makeList({{-kInfinity, kInfinity}}, tagA());
  intersect(all, b, out);
  EXPECT_EQ(intervalsOf(out), (Intervals{{0, 6}}));
  subtract(b, all, out);
  EXPECT_TRUE(out.empty());
  subtract(all, all, out);
  EXPECT_TRUE(out.empty());
}

// A boundary at NaN (a solid of 10³⁰⁰ seen from as far away) is not in
// order with anything: the booleans still end, each list's boundaries from
// it on taken together, and the result has as many boundaries as the lists.
TEST(SpanList, BooleansOfANaNBoundaryEnd) {
  const double nan = std::nan("");
  for (const Intervals& withNaN :
       {Intervals{{nan, 2}}, Intervals{{0, nan}}, Intervals{{0, 1}, {nan, nan}, {4, 5}}})
    for (const Intervals& other : {Intervals{{0.5, 3}}, Intervals{{-1, 0.5}, {1.5, 6}}}) {
      const SpanList a = makeList(withNaN, tagA()), b = makeList(other, tagB());
      SpanList out;
      unite(a, b, out);
      EXPECT_LE(out.size(), a.size() + b.size());
      unite(b, a, out);
      EXPECT_LE(out.size(), a.size() + b.size());
      intersect(a, b, out);
      EXPECT_LE(out.size(), a.size() + b.size());
      subtract(a, b, out);
      EXPECT_LE(out.size(), a.size() + b.size());
      subtract(b, a, out);
      EXPECT_LE(out.size(), a.size() + b.size());
    }
}

TEST(SpanList, ValidDetectsBrokenInvariants) {
  EXPECT_TRUE(SpanList().valid());
  EXPECT_TRUE(makeList({{0, 1}, {2, 3}}, tagA()).valid());
  EXPECT_TRUE(makeList({{1, 1}}, tagA()).valid());  // zero-length allowed
  EXPECT_TRUE(makeList({{-kInfinity, kInfinity}}, tagA()).valid());
  EXPECT_FALSE(makeList({{1, 0}}, tagA()).valid());          // in > out
  EXPECT_FALSE(makeList({{2, 3}, {0, 1}}, tagA()).valid());  // unsorted
  EXPECT_FALSE(makeList({{0, 2}, {1, 3}}, tagA()).valid());  // overlapping
  EXPECT_FALSE(makeList({{0, 1}, {1, 2}}, tagA()).valid());  // touching: should be merged
  EXPECT_FALSE(makeList({{0, std::nan("")}}, tagA()).valid());
}

// Length clipped to a window: [0,2] ∪ [3,7] within [1,4] is 1 + 1.
TEST(SpanList, LengthWithin) {
  SpanList list = makeList({{0, 2}, {3, 7}}, tagA());
  EXPECT_DOUBLE_EQ(list.lengthWithin(1, 4), 2.0);
  EXPECT_DOUBLE_EQ(list.lengthWithin(-kInfinity, kInfinity), 6.0);
  EXPECT_DOUBLE_EQ(list.lengthWithin(2, 3), 0.0);
  SpanList unbounded = makeList({{-kInfinity, 1}}, tagA());
  EXPECT_DOUBLE_EQ(unbounded.lengthWithin(-2, 5), 3.0);
}

Intervals manyIntervals(int n, double offset) {
  Intervals out;
  for (int i = 0; i < n; ++i) out.emplace_back(4.0 * i + offset, 4.0 * i + offset + 1.0);
  return out;
}

// Past kInline spans the list moves to the heap and keeps every span.
TEST(SpanList, GrowsBeyondInlineCapacity) {
  static_assert(SpanList::kInline < 100);
  Intervals iv = manyIntervals(100, 0.0);
  SpanList list = makeList(iv, tagA());
  ASSERT_EQ(list.size(), 100u);
  EXPECT_TRUE(list.valid());
  EXPECT_EQ(intervalsOf(list), iv);
  for (uint32_t i = 0; i < list.size(); ++i) EXPECT_EQ(list[i].in.face, (2 * i) % 256);
  EXPECT_EQ(list.front().in.t, 0.0);
  EXPECT_EQ(list.back().out.t, 397.0);
  list.clear();
  EXPECT_TRUE(list.empty());
  list.push_back(bound(1, tagA()), bound(2, tagA()));
  EXPECT_EQ(intervalsOf(list), (Intervals{{1, 2}}));
}

// Copies are deep and independent, between inline and heap storage both ways.
TEST(SpanList, CopyIsDeepAndIndependent) {
  Intervals big = manyIntervals(100, 0.0), small = {{1, 2}, {3, 4}};
  SpanList heap = makeList(big, tagA());
  SpanList copy(heap);
  EXPECT_EQ(intervalsOf(copy), big);
  heap.clear();
  heap.push_back(bound(-5, tagA()), bound(-4, tagA()));
  EXPECT_EQ(intervalsOf(copy), big);
  EXPECT_EQ(intervalsOf(heap), (Intervals{{-5, -4}}));

  SpanList inl = makeList(small, tagB());
  copy = inl;  // heap-grown list takes a short one
  EXPECT_EQ(intervalsOf(copy), small);
  inl = makeList(big, tagB());  // inline list takes a long one
  EXPECT_EQ(intervalsOf(inl), big);
  EXPECT_EQ(intervalsOf(copy), small);
  SpanList& self = inl;
  inl = self;
  EXPECT_EQ(intervalsOf(inl), big);
  EXPECT_EQ(inl[57].in.primitive, tagB());
}

// Booleans producing more than kInline spans: interleaved lists of 50
// spans each unite to 100 spans, intersect to nothing, subtract to a.
TEST(SpanList, BooleansOnLongLists) {
  SpanList a = makeList(manyIntervals(50, 0.0), tagA());
  SpanList b = makeList(manyIntervals(50, 2.0), tagB());
  SpanList out;
  unite(a, b, out);
  ASSERT_EQ(out.size(), 100u);
  EXPECT_TRUE(out.valid());
  EXPECT_DOUBLE_EQ(out.lengthWithin(-kInfinity, kInfinity), 100.0);
  intersect(a, b, out);
  EXPECT_TRUE(out.empty());
  subtract(a, b, out);
  EXPECT_EQ(intervalsOf(out), intervalsOf(a));
  // Shifting b by half a span: a − b keeps the first half of each span.
  SpanList c = makeList(manyIntervals(50, 0.5), tagB());
  subtract(a, c, out);
  ASSERT_EQ(out.size(), 50u);
  for (const Span& s : out) EXPECT_DOUBLE_EQ(s.length(), 0.5);
  expectMatchesReference(Op::Unite, a, c);
  expectMatchesReference(Op::Intersect, a, c);
}

}  // namespace
}  // namespace csgray::detail
