#include "modeler/bvh.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace csgray {

namespace {

constexpr int kBins = 16;
constexpr std::uint32_t kLeafSize = 2;
// Cost of visiting a node relative to testing an item (an item is a whole
// solid or a triangle, so it costs several box tests).
constexpr double kTraversalCost = 0.5;

double halfArea(const Bounds& b) {
  if (b.empty()) return 0.0;
  dvec3 s = b.size();
  return s.x * s.y + s.y * s.z + s.z * s.x;
}

}  // namespace

Bvh::Bvh(std::span<const Bounds> boxes) {
  std::vector<dvec3> centres(boxes.size());
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    if (boxes[i].empty()) continue;
    if (!boxes[i].finite()) {
      unbounded_.push_back(i);
      continue;
    }
    items_.push_back(i);
    centres[i] = boxes[i].center();
  }
  if (items_.empty()) return;
  nodes_.reserve(2 * items_.size());
  nodes_.push_back({});
  build(0, boxes, centres, 0, std::uint32_t(items_.size()), 0);
  itemBoxes_.reserve(items_.size());
  for (std::uint32_t item : items_) itemBoxes_.push_back(boxes[item]);
}

void Bvh::build(std::uint32_t node, std::span<const Bounds> boxes,
                const std::vector<dvec3>& centres, std::uint32_t begin, std::uint32_t end,
                int depth) {
  Bounds box, centreBox;
  for (std::uint32_t i = begin; i < end; ++i) {
    box.include(boxes[items_[i]]);
    centreBox.include(centres[items_[i]]);
  }
  nodes_[node] = {box, begin, end - begin};
  std::uint32_t n = end - begin;
  if (n <= kLeafSize || depth + 1 >= kMaxDepth) return;

  // Binned SAH: the cost of a split is A(left)·n(left) + A(right)·n(right)
  // over A(node), plus the traversal; the best plane over three axes and
  // kBins − 1 candidate planes each wins if it beats a leaf.
  double bestCost = n, leafCost = n;
  int bestAxis = -1, bestBin = 0;
  for (int axis = 0; axis < 3; ++axis) {
    double lo = centreBox.lo[axis], extent = centreBox.hi[axis] - lo;
    if (!(extent > 0.0)) continue;
    std::array<Bounds, kBins> binBox;
    std::array<std::uint32_t, kBins> binCount{};
    auto binOf = [&](std::uint32_t item) {
      return std::min(kBins - 1, int((centres[item][axis] - lo) / extent * kBins));
    };
    for (std::uint32_t i = begin; i < end; ++i) {
      int b = binOf(items_[i]);
      binBox[b].include(boxes[items_[i]]);
      ++binCount[b];
    }
    // Sweep from the right for the right-hand areas, then from the left.
    std::array<double, kBins> rightArea{};
    std::array<std::uint32_t, kBins> rightCount{};
    Bounds acc;
    std::uint32_t count = 0;
    for (int b = kBins - 1; b > 0; --b) {
      acc.include(binBox[b]);
      count += binCount[b];
      rightArea[b] = halfArea(acc);
      rightCount[b] = count;
    }
    acc = Bounds{};
    count = 0;
    double area = halfArea(box);
    for (int b = 0; b < kBins - 1; ++b) {
      acc.include(binBox[b]);
      count += binCount[b];
      if (count == 0 || rightCount[b + 1] == 0) continue;
      double cost =
          kTraversalCost + (halfArea(acc) * count + rightArea[b + 1] * rightCount[b + 1]) / area;
      if (cost < bestCost) bestCost = cost, bestAxis = axis, bestBin = b;
    }
  }
  std::uint32_t mid;
  if (bestAxis >= 0 && bestCost < leafCost) {
    double lo = centreBox.lo[bestAxis], extent = centreBox.hi[bestAxis] - lo;
    auto right =
        std::partition(items_.begin() + begin, items_.begin() + end, [&](std::uint32_t item) {
          return std::min(kBins - 1, int((centres[item][bestAxis] - lo) / extent * kBins)) <=
                 bestBin;
        });
    mid = std::uint32_t(right - items_.begin());
  } else if (n > 4 * kLeafSize) {
    // Boxes that SAH cannot separate (all centres alike): split in the
    // middle anyway, so that a leaf stays small.
    mid = begin + n / 2;
  } else {
    return;
  }
  std::uint32_t left = std::uint32_t(nodes_.size());
  nodes_.push_back({});
  nodes_.push_back({});
  nodes_[node].start = left;
  nodes_[node].count = 0;
  build(left, boxes, centres, begin, mid, depth + 1);
  build(left + 1, boxes, centres, mid, end, depth + 1);
}

}  // namespace csgray
