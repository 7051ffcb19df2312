// The split box intersection reports exactly the pairs of closed boxes that
// meet, each once, against a test of every pair: boxes on a coarse grid
// (so that many touch, share a lower side or straddle a split), enough of
// them to be split several times, within one set and between two.
#include "export/cgal/box_pairs.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <mutex>
#include <random>
#include <set>
#include <tuple>
#include <utility>

#include "engine/cancellation.h"

namespace csgray::detail {
namespace {

// n boxes with corners on a grid of `cells` per side, each at most `reach`
// cells long (long ones straddle every split).
std::vector<FaceBox> randomBoxes(std::size_t n, int cells, int reach, std::uint32_t mesh,
                                 std::mt19937& random) {
  std::uniform_int_distribution<int> corner(0, cells), length(0, reach);
  std::vector<FaceBox> boxes;
  for (std::uint32_t f = 0; f < n; ++f) {
    FaceBox box{{}, {}, f, mesh};
    for (int d = 0; d < 3; ++d) {
      box.lo[d] = corner(random);
      box.hi[d] = box.lo[d] + (f % 97 == 0 ? 10 * reach : length(random));
    }
    boxes.push_back(box);
  }
  return boxes;
}

bool meet(const FaceBox& a, const FaceBox& b) {
  for (int d = 0; d < 3; ++d)
    if (a.hi[d] < b.lo[d] || b.hi[d] < a.lo[d]) return false;
  return true;
}

using Pairs = std::multiset<std::pair<std::uint32_t, std::uint32_t>>;

TEST(BoxPairs, WithinOneSetEveryPairThatMeetsOnce) {
  std::mt19937 random(20261126);
  for (int reach : {1, 4}) {
    const std::vector<FaceBox> boxes = randomBoxes(9000, 60, reach, 0, random);
    Pairs expected;
    for (std::size_t i = 0; i < boxes.size(); ++i)
      for (std::size_t j = i + 1; j < boxes.size(); ++j)
        if (meet(boxes[i], boxes[j])) expected.emplace(boxes[i].face, boxes[j].face);
    std::vector<FaceBox> work = boxes;
    Pairs found;
    std::mutex lock;
    forEachMeetingPair(work, [&](std::uint32_t f, std::uint32_t g) {
      std::lock_guard guard(lock);
      found.emplace(std::min(f, g), std::max(f, g));
    });
    EXPECT_GT(expected.size(), 1000u);
    EXPECT_EQ(found, expected) << "reach " << reach;
  }
}

TEST(BoxPairs, BetweenTwoSetsEveryPairThatMeetsOnceInOrder) {
  std::mt19937 random(20261127);
  // Two sets that are split; a few long boxes against many, each way
  // round, which are not.
  for (auto [na, nb, reachB] :
       {std::tuple(5000, 4000, 3), std::tuple(20000, 12, 40), std::tuple(12, 20000, 3)}) {
    const std::vector<FaceBox> a = randomBoxes(std::size_t(na), 60, na < nb ? 40 : 3, 0, random);
    const std::vector<FaceBox> b = randomBoxes(std::size_t(nb), 60, reachB, 1, random);
    Pairs expected;
    for (const FaceBox& x : a)
      for (const FaceBox& y : b)
        if (meet(x, y)) expected.emplace(x.face, y.face);
    std::vector<FaceBox> workA = a, workB = b;
    const std::vector<FacePair> order = meetingPairs(workA, workB);
    EXPECT_GT(expected.size(), std::size_t(std::min(na, nb)));
    EXPECT_EQ(Pairs(order.begin(), order.end()), expected) << na << " against " << nb;
    // The same boxes again, on one thread and on four: the same pairs in
    // the same order (the double boolean numbers its new points in it).
    for (int threads : {1, 4}) {
      std::vector<FaceBox> againA = a, againB = b;
      std::vector<FacePair> again;
      tbb::task_arena(threads).execute([&] { again = meetingPairs(againA, againB); });
      EXPECT_EQ(again, order) << threads << " threads, " << na << " against " << nb;
    }
  }
}

// The pairs between two sets read the caller's cancel (the boolean in
// doubles asks for them on large meshes): set, they stop, split or few
// against many alike; clear, they are found.
TEST(BoxPairs, BetweenTwoSetsTheyStopWhenCancelled) {
  std::mt19937 random(20261129);
  const std::vector<FaceBox> a = randomBoxes(5000, 60, 3, 0, random);
  const std::vector<FaceBox> b = randomBoxes(4000, 60, 3, 1, random);
  const std::vector<FaceBox> few = randomBoxes(12, 60, 40, 1, random);
  std::atomic<bool> cancel = true;
  const CancelScope scope(&cancel);
  for (const std::vector<FaceBox>* other : {&b, &few}) {
    std::vector<FaceBox> workA = a, workB = *other;
    EXPECT_THROW(meetingPairs(workA, workB), Cancelled);
  }
  cancel = false;
  std::vector<FaceBox> workA = a, workB = b;
  EXPECT_FALSE(meetingPairs(workA, workB).empty());
}

TEST(BoxPairs, BoxesThatShareOneLowerSideAreNotSplitForever) {
  // Every box starts at x = 0: no median splits them.
  std::vector<FaceBox> boxes;
  for (std::uint32_t f = 0; f < 5000; ++f) boxes.push_back({{0, 0, 0}, {1, 1, 1}, f, 0});
  std::size_t count = 0;
  std::mutex lock;
  forEachMeetingPair(boxes, [&](std::uint32_t, std::uint32_t) {
    std::lock_guard guard(lock);
    ++count;
  });
  EXPECT_EQ(count, 5000u * 4999u / 2);
}

}  // namespace
}  // namespace csgray::detail
