#include "export/cgal/box_pairs.h"

#include <CGAL/box_intersection_d.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <atomic>
#include <span>

#include "engine/cancellation.h"

namespace csgray::detail {

namespace {

// FaceBox as CGAL's box intersection reads a box (its Box_traits_d: the
// coordinates, and the face as the id that breaks ties and tells a box
// from itself).
struct Traits {
  using NT = double;
  using ID = std::size_t;
  using Box_parameter = const FaceBox&;
  static int dimension() { return 3; }
  static double min_coord(const FaceBox& b, int d) { return b.lo[d]; }
  static double max_coord(const FaceBox& b, int d) { return b.hi[d]; }
  static std::size_t id(const FaceBox& b) { return std::size_t(b.mesh) << 32 | b.face; }
};
// Fewer boxes than kSmallestSplit go to CGAL whole, which scans ranges of
// fewer than kCutoff rather than split them. Splitting down to about a
// thousand boxes pays on one thread too: a mesh's faces are small against
// the part, so few straddle a split. Instructions for the pairs of
// plate(16)'s 174 220 faces and their tests, both checks of an imported
// mesh (callgrind): CGAL alone over all boxes, cutoff 2000 (its own
// self-intersection test's, which did best of 10 to 10⁶ there), 2.45 G
// without the tests; split to leaves of 3000 with that cutoff, 1.58 G
// with them; leaves of 1000 and a cutoff of 100, 1.35 G (cutoffs of 10,
// 30, 500 and 2000, leaves of 300 to 3000: 1.37 G to 1.60 G).
constexpr std::ptrdiff_t kCutoff = 100;
constexpr std::size_t kSmallestSplit = 1000;

using Report = std::function<void(std::uint32_t, std::uint32_t)>;

void selfPairs(std::span<FaceBox> boxes, const Report& report) {
  CGAL::box_self_intersection_d<CGAL::Sequential_tag>(
      boxes.begin(), boxes.end(),
      [&](const FaceBox& a, const FaceBox& b) { report(a.face, b.face); }, Traits(), kCutoff,
      CGAL::Box_intersection_d::CLOSED);
}

// The pairs of a box of a and a box of b, reported in that order or
// (swapped) the other way round.
void crossPairs(std::span<FaceBox> a, std::span<FaceBox> b, const Report& report,
                bool swapped = false) {
  if (a.empty() || b.empty()) return;
  CGAL::box_intersection_d<CGAL::Sequential_tag>(
      a.begin(), a.end(), b.begin(), b.end(),
      [&](const FaceBox& x, const FaceBox& y) {
        swapped ? report(y.face, x.face) : report(x.face, y.face);
      },
      Traits(), kCutoff, CGAL::Box_intersection_d::CLOSED, CGAL::Box_intersection_d::BIPARTITE);
}

// The axis along which the boxes' lower corners spread most.
int widestAxis(std::span<const FaceBox> one, std::span<const FaceBox> two) {
  double lo[3], hi[3];
  const FaceBox& first = one.empty() ? two[0] : one[0];
  for (int d = 0; d < 3; ++d) lo[d] = hi[d] = first.lo[d];
  for (auto boxes : {one, two})
    for (const FaceBox& b : boxes)
      for (int d = 0; d < 3; ++d)
        lo[d] = std::min(lo[d], b.lo[d]), hi[d] = std::max(hi[d], b.lo[d]);
  int axis = 0;
  for (int d = 1; d < 3; ++d)
    if (hi[d] - lo[d] > hi[axis] - lo[axis]) axis = d;
  return axis;
}

// The boxes below the plane x_axis = m first, the others after; where
// they part.
std::span<FaceBox>::iterator splitAt(std::span<FaceBox> boxes, int axis, double m) {
  return std::partition(boxes.begin(), boxes.end(),
                        [&](const FaceBox& b) { return b.lo[axis] < m; });
}

// The boxes of `below` that reach the plane x_axis = m, and the boxes of
// `above` (all at m or beyond) within their reach: of the pairs between
// the two, the only ones that can meet.
void straddlers(std::span<const FaceBox> below, std::span<const FaceBox> above, int axis, double m,
                std::vector<FaceBox>& reaching, std::vector<FaceBox>& reached) {
  double reach = m;
  for (const FaceBox& b : below)
    if (b.hi[axis] >= m) reaching.push_back(b), reach = std::max(reach, b.hi[axis]);
  if (reaching.empty()) return;
  for (const FaceBox& b : above)
    if (b.lo[axis] <= reach) reached.push_back(b);
}

// Are halves of n boxes, one of `lower`, fair enough to split at?
bool balanced(std::size_t lower, std::size_t n) { return lower >= n / 4 && lower <= n - n / 4; }

// The pairs among boxes, split until few. A split at a plane
// x_axis = m puts the boxes whose lower side is below m in one half, the
// rest in the other: a box of the second half lies wholly at m or above,
// so it meets a box of the first only if that one reaches m (a straddler).
// The pairs are then those within each half and those between the
// straddlers and the second half, each reported once, by one of three
// independent tasks.
void pairsSplit(std::span<FaceBox> boxes, const Report& report) {
  if (boxes.size() < kSmallestSplit) return selfPairs(boxes, report);
  const int axis = widestAxis(boxes, {});
  // The median lower side: the halves hold about as many boxes.
  const auto middle = boxes.begin() + std::ptrdiff_t(boxes.size() / 2);
  std::nth_element(boxes.begin(), middle, boxes.end(),
                   [axis](const FaceBox& a, const FaceBox& b) { return a.lo[axis] < b.lo[axis]; });
  const double m = middle->lo[axis];
  const auto second = splitAt(boxes, axis, m);
  // Many boxes at one lower side: halves that are not halves.
  if (!balanced(std::size_t(second - boxes.begin()), boxes.size())) return selfPairs(boxes, report);
  const std::span<FaceBox> below(boxes.begin(), second), above(second, boxes.end());
  std::vector<FaceBox> reaching, reached;
  straddlers(below, above, axis, m, reaching, reached);
  tbb::parallel_invoke([&] { pairsSplit(below, report); }, [&] { pairsSplit(above, report); },
                       [&] { crossPairs(reaching, reached, report); });
}

// The same between two sets, appended to `pairs`: split both at one plane,
// the pairs are those between the straddlers of either below it and the
// other's above, then those between a's and b's boxes below it, then
// above it. The two halves are split on threads of their own, each into a
// vector of its own, so the order is the same whatever the threads. The
// caller's cancel is read at each split (engine/cancellation.h).
void pairsSplit(std::span<FaceBox> a, std::span<FaceBox> b, std::vector<FacePair>& pairs,
                const std::atomic<bool>* cancel) {
  stopIfCancelled(cancel);
  // (Also at each pair: boxes that reach across most of the part, a long
  // rod's faces, leave halves that cannot be split, and CGAL takes seconds.)
  const Report append = [&pairs, cancel](std::uint32_t f, std::uint32_t g) {
    stopIfCancelled(cancel);
    pairs.emplace_back(f, g);
  };
  const std::size_t n = a.size() + b.size();
  if (n < kSmallestSplit || a.empty() || b.empty()) return crossPairs(a, b, append);
  const int axis = widestAxis(a, b);
  std::vector<double> sides;
  sides.reserve(n);
  for (auto boxes : {a, b})
    for (const FaceBox& box : boxes) sides.push_back(box.lo[axis]);
  std::nth_element(sides.begin(), sides.begin() + std::ptrdiff_t(n / 2), sides.end());
  const double m = sides[n / 2];
  const auto aSecond = splitAt(a, axis, m), bSecond = splitAt(b, axis, m);
  const std::span<FaceBox> aBelow(a.begin(), aSecond), aAbove(aSecond, a.end());
  const std::span<FaceBox> bBelow(b.begin(), bSecond), bAbove(bSecond, b.end());
  if (!balanced(aBelow.size() + bBelow.size(), n)) return crossPairs(a, b, append);
  std::vector<FaceBox> reaching, reached;
  straddlers(aBelow, bAbove, axis, m, reaching, reached);
  crossPairs(reaching, reached, append);
  reaching.clear(), reached.clear();
  straddlers(bBelow, aAbove, axis, m, reaching, reached);
  crossPairs(reaching, reached, append, true);
  std::vector<FacePair> above;
  tbb::parallel_invoke([&] { pairsSplit(aBelow, bBelow, pairs, cancel); },
                       [&] { pairsSplit(aAbove, bAbove, above, cancel); });
  pairs.insert(pairs.end(), above.begin(), above.end());
}

// Few boxes on one side (a box's twelve faces against a grid of balls'
// hundreds of thousands): each box of a tested against each of b, in
// blocks of a on all threads, the pairs in a's order and then b's. Split,
// the few boxes would straddle every plane, and each level would copy the
// many that they reach (plate(32)'s union: 0.1 s, against 0.01 s so).
constexpr std::size_t kFewBoxes = 32;

bool meet(const FaceBox& x, const FaceBox& y) {
  for (int d = 0; d < 3; ++d)
    if (x.hi[d] < y.lo[d] || y.hi[d] < x.lo[d]) return false;
  return true;
}

std::vector<FacePair> fewAgainstMany(const std::vector<FaceBox>& a, const std::vector<FaceBox>& b,
                                     const std::atomic<bool>* cancel) {
  constexpr std::size_t kBlock = 4096;
  std::vector<std::vector<FacePair>> found((a.size() + kBlock - 1) / kBlock);
  tbb::parallel_for(std::size_t(0), found.size(), [&](std::size_t block) {
    stopIfCancelled(cancel);
    const std::size_t end = std::min(a.size(), (block + 1) * kBlock);
    for (std::size_t i = block * kBlock; i < end; ++i)
      for (const FaceBox& y : b)
        if (meet(a[i], y)) found[block].emplace_back(a[i].face, y.face);
  });
  std::vector<FacePair> pairs;
  for (const std::vector<FacePair>& block : found)
    pairs.insert(pairs.end(), block.begin(), block.end());
  return pairs;
}

}  // namespace

void forEachMeetingPair(std::vector<FaceBox>& boxes, const Report& report) {
  pairsSplit(boxes, report);
}

std::vector<FacePair> meetingPairs(std::vector<FaceBox>& a, std::vector<FaceBox>& b) {
  const std::atomic<bool>* cancel = cancelFlag();
  if (std::min(a.size(), b.size()) <= kFewBoxes) return fewAgainstMany(a, b, cancel);
  std::vector<FacePair> pairs;
  pairsSplit(a, b, pairs, cancel);
  return pairs;
}

}  // namespace csgray::detail
