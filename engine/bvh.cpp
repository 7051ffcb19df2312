#include "engine/bvh.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace csgray::detail {

namespace {

constexpr int kBins = 16;
// One item a leaf: a node tests its children's boxes at once
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

// The binary SAH tree, built first and then folded into Bvh's 4-wide nodes.
struct BinaryNode {
  Bounds box;
  std::uint32_t start;  // leaf: first entry in items; inner: index of the left child
  std::uint32_t count;  // leaf: number of items; inner: 0 (right child is start + 1)
};

}  // namespace

class BvhBuilder {
 public:
  BvhBuilder(std::span<const Bounds> boxes, std::vector<std::uint32_t>& items)
      : boxes_(boxes), items_(items), centres_(boxes.size()) {
    for (std::uint32_t item : items_) centres_[item] = boxes_[item].center();
    binary_.reserve(2 * items_.size());
    binary_.push_back({});
    build(0, 0, std::uint32_t(items_.size()), 0);
  }

  // Bvh's nodes: the binary root's children, the grandchildren of those of
  // them that are inner nodes, and so on (fold).
  std::vector<Bvh::Node> wideNodes() {
    std::vector<Bvh::Node> nodes;
    // Each wide node takes at least one inner node of the binary tree, of
    // which there are fewer than half its nodes: room for all at once, so
    // that a tree of millions is not copied again at each doubling.
    nodes.reserve(binary_.size() / 2 + 1);
    std::vector<std::uint32_t> root{0};
    if (binary_[0].count == 0) root = {binary_[0].start, binary_[0].start + 1};
    fold(root, nodes);
    nodes.shrink_to_fit();  // memoryBytes counts the capacity
    return nodes;
  }

 private:
  void build(std::uint32_t node, std::uint32_t begin, std::uint32_t end, int depth);
  static int bin(double c, double lo, double extent);
  std::uint32_t fold(std::vector<std::uint32_t> children, std::vector<Bvh::Node>& nodes) const;

  std::span<const Bounds> boxes_;
  std::vector<std::uint32_t>& items_;
  std::vector<dvec3> centres_;
  std::vector<BinaryNode> binary_;
};

Bvh::Bvh(std::span<const Bounds> boxes) {
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    if (boxes[i].empty()) continue;
    if (!boxes[i].finite()) {
      unbounded_.push_back(i);
      continue;
    }
    items_.push_back(i);
  }
  if (items_.empty()) return;
  if (items_.size() == 1) onlyBox_ = boxes[items_[0]];
  nodes_ = BvhBuilder(boxes, items_).wideNodes();
}

// Makes a wide node of the binary nodes given (one or two), and the nodes
// below it; returns its index. While there is room, the inner child of
// largest area gives way to its two children, in its place, so that the
// children keep the binary tree's left-to-right order.
std::uint32_t BvhBuilder::fold(std::vector<std::uint32_t> children,
                               std::vector<Bvh::Node>& nodes) const {
  while (children.size() < Bvh::kWidth) {
    int widest = -1;
    for (int c = 0; c < int(children.size()); ++c)
      if (binary_[children[c]].count == 0 &&
          (widest < 0 ||
           halfArea(binary_[children[c]].box) > halfArea(binary_[children[widest]].box)))
        widest = c;
    if (widest < 0) break;
    std::uint32_t left = binary_[children[widest]].start;
    children[widest] = left;
    children.insert(children.begin() + widest + 1, left + 1);
  }
  const std::uint32_t index = std::uint32_t(nodes.size());
  nodes.emplace_back();
  for (int c = 0; c < Bvh::kWidth; ++c) {
    Bounds box;  // an unused slot: empty, never met
    std::uint32_t first = 0, count = 0;
    if (c < int(children.size())) {
      const BinaryNode& child = binary_[children[c]];
      box = child.box;
      if (child.count > 0) {
        first = child.start, count = child.count;
      } else {
        first = fold({child.start, child.start + 1}, nodes), count = Bvh::kInner;
      }
    }
    Bvh::Node& node = nodes[index];  // (fold may have moved it)
    for (int a = 0; a < 3; ++a) node.lo[a][c] = box.lo[a], node.hi[a][c] = box.hi[a];
    node.first[c] = first;
    node.count[c] = count;
  }
  return index;
}

// The bin of a centre c along an axis whose centres start at lo and
// extend `extent`: the last bin holds the far end. Where the quotient is
// not a number (an extent that overflowed), the last bin too: int() of NaN
// is undefined, and the index it gave once crashed.
int BvhBuilder::bin(double c, double lo, double extent) {
  const double f = (c - lo) / extent * kBins;
  return f < kBins - 1 ? (f > 0.0 ? int(f) : 0) : kBins - 1;
}

void BvhBuilder::build(std::uint32_t node, std::uint32_t begin, std::uint32_t end, int depth) {
  Bounds box, centreBox;
  for (std::uint32_t i = begin; i < end; ++i) {
    box.include(boxes_[items_[i]]);
    centreBox.include(centres_[items_[i]]);
  }
  binary_[node] = {box, begin, end - begin};
  std::uint32_t n = end - begin;
  if (n <= kLeafSize || depth + 1 >= Bvh::kMaxDepth) return;

  // Binned SAH: the cost of a split is A(left)·n(left) + A(right)·n(right)
  // over A(node), plus the traversal; the best plane over three axes and
  // kBins − 1 candidate planes; the cheapest wins.
  double bestCost = kInfinity;
  int bestAxis = -1, bestBin = 0;
  for (int axis = 0; axis < 3; ++axis) {
    double lo = centreBox.lo[axis], extent = centreBox.hi[axis] - lo;
    if (!(extent > 0.0)) continue;
    // A bin's box is set by its first item (binCount 0 before), so that
    // the bins need no clearing.
    std::array<Bounds, kBins> binBox;
    std::array<std::uint32_t, kBins> binCount{};
    auto binOf = [&](std::uint32_t item) { return bin(centres_[item][axis], lo, extent); };
    for (std::uint32_t i = begin; i < end; ++i) {
      int b = binOf(items_[i]);
      if (binCount[b]++ == 0)
        binBox[b] = boxes_[items_[i]];
      else
        binBox[b].include(boxes_[items_[i]]);
    }
    // Only the bins with items: a plane after an empty bin splits the
    // items as the plane before it does, at the same cost, which the
    // strict comparison below never takes over the first. (Most nodes
    // hold a few items: sweeping all kBins bins cost 3 000 instructions a
    // node, three quarters of a 4 096-part union's build.)
    std::array<int, kBins> used;
    int usedCount = 0;
    for (int b = 0; b < kBins; ++b)
      if (binCount[b] > 0) used[usedCount++] = b;
    // Sweep from the right for the right-hand areas, then from the left:
    // right*[k] is of the used bins from k on.
    std::array<double, kBins> rightArea;
    std::array<std::uint32_t, kBins> rightCount;
    Bounds acc;
    std::uint32_t count = 0;
    for (int k = usedCount - 1; k > 0; --k) {
      acc.include(binBox[used[k]]);
      count += binCount[used[k]];
      rightArea[k] = halfArea(acc);
      rightCount[k] = count;
    }
    acc = Bounds{};
    count = 0;
    double area = halfArea(box);
    for (int k = 0; k < usedCount - 1; ++k) {
      acc.include(binBox[used[k]]);
      count += binCount[used[k]];
      double cost =
          kTraversalCost + (halfArea(acc) * count + rightArea[k + 1] * rightCount[k + 1]) / area;
      if (cost < bestCost) bestCost = cost, bestAxis = axis, bestBin = used[k];
    }
  }
  std::uint32_t mid;
  if (bestAxis >= 0) {
    double lo = centreBox.lo[bestAxis], extent = centreBox.hi[bestAxis] - lo;
    auto right = std::partition(
        items_.begin() + begin, items_.begin() + end,
        [&](std::uint32_t item) { return bin(centres_[item][bestAxis], lo, extent) <= bestBin; });
    mid = std::uint32_t(right - items_.begin());
  } else {
    // Boxes that SAH cannot separate (all centres alike): split in the
    // middle anyway, so that leaves stay single.
    mid = begin + n / 2;
  }
  std::uint32_t left = std::uint32_t(binary_.size());
  binary_.push_back({});
  binary_.push_back({});
  binary_[node].start = left;
  binary_[node].count = 0;
  build(left, begin, mid, depth + 1);
  build(left + 1, mid, end, depth + 1);
}

}  // namespace csgray::detail
