#include "engine/bvh.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace csgray::detail {

namespace {

constexpr int kBins = 16;
// One item a leaf: an inner node tests both children's boxes at once
// (Bvh::childEntries), so an item's box is tested there, never in a leaf.
constexpr std::uint32_t kLeafSize = 1;
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
  // The boxes of the nodes are needed while building; traversal keeps
  // only each inner node's pair of child boxes.
  std::vector<Bounds> nodeBoxes;
  nodes_.reserve(2 * items_.size());
  nodeBoxes.reserve(2 * items_.size());
  nodes_.push_back({});
  nodeBoxes.push_back({});
  build(0, boxes, centres, nodeBoxes, 0, std::uint32_t(items_.size()), 0);
  rootBox_ = nodeBoxes[0];
  children_.resize(nodes_.size());
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    if (nodes_[n].count > 0) continue;
    for (int child = 0; child < 2; ++child) {
      const Bounds& b = nodeBoxes[nodes_[n].start + child];
      for (int a = 0; a < 3; ++a) {
        children_[n].lo[a][child] = b.lo[a];
        children_[n].hi[a][child] = b.hi[a];
      }
    }
  }
}

void Bvh::build(std::uint32_t node, std::span<const Bounds> boxes,
                const std::vector<dvec3>& centres, std::vector<Bounds>& nodeBoxes,
                std::uint32_t begin, std::uint32_t end, int depth) {
  Bounds box, centreBox;
  for (std::uint32_t i = begin; i < end; ++i) {
    box.include(boxes[items_[i]]);
    centreBox.include(centres[items_[i]]);
  }
  nodes_[node] = {begin, end - begin};
  nodeBoxes[node] = box;
  std::uint32_t n = end - begin;
  if (n <= kLeafSize || depth + 1 >= kMaxDepth) return;

  // Binned SAH: the cost of a split is A(left)·n(left) + A(right)·n(right)
  // over A(node), plus the traversal; the best plane over three axes and
  // kBins − 1 candidate planes; the cheapest wins.
  double bestCost = kInfinity;
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
  if (bestAxis >= 0) {
    double lo = centreBox.lo[bestAxis], extent = centreBox.hi[bestAxis] - lo;
    auto right =
        std::partition(items_.begin() + begin, items_.begin() + end, [&](std::uint32_t item) {
          return std::min(kBins - 1, int((centres[item][bestAxis] - lo) / extent * kBins)) <=
                 bestBin;
        });
    mid = std::uint32_t(right - items_.begin());
  } else {
    // Boxes that SAH cannot separate (all centres alike): split in the
    // middle anyway, so that leaves stay single.
    mid = begin + n / 2;
  }
  std::uint32_t left = std::uint32_t(nodes_.size());
  nodes_.push_back({});
  nodes_.push_back({});
  nodeBoxes.resize(nodes_.size());
  nodes_[node].start = left;
  nodes_[node].count = 0;
  build(left, boxes, centres, nodeBoxes, begin, mid, depth + 1);
  build(left + 1, boxes, centres, nodeBoxes, mid, end, depth + 1);
}

}  // namespace csgray::detail
