// A bounding volume hierarchy over boxes (the scene's objects, the operands
// of a boolean node, the triangles of a mesh), built with the surface area
// heuristic (MacDonald and Booth 1990; binned as in Wald, "On fast
// construction of SAH-based bounding volume hierarchies", 2007), so that a
// ray visits only the items whose boxes it meets. Items with unbounded boxes
// (half-spaces, most quadrics) are kept aside and always visited.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "modeler/bounds.h"

namespace csgray {

// Where a ray enters a box within [tMin, tMax]: the entry t (tMin if the
// ray starts inside), or +inf if it misses (Bounds::entry).
inline double boxEntry(const Bounds& box, const Ray& ray, double tMin, double tMax) {
  return box.entry(ray, tMin, tMax);
}

class Bvh {
 public:
  Bvh() = default;
  // Builds over the boxes; item i is boxes[i]. Empty boxes are never visited.
  explicit Bvh(std::span<const Bounds> boxes);

  bool empty() const { return nodes_.empty() && unbounded_.empty(); }
  std::size_t memoryBytes() const {
    return nodes_.capacity() * sizeof(Node) + items_.capacity() * sizeof(std::uint32_t) +
           itemBoxes_.capacity() * sizeof(Bounds) + unbounded_.capacity() * sizeof(std::uint32_t);
  }

  // Calls visit(item, tEnter) for every item whose box the ray meets within
  // [ray.tMin, tMax], depth first with the nearer child first (unbounded
  // items first of all, with tEnter = ray.tMin). visit may lower tMax to prune boxes beyond it,
  // and returns false to stop the traversal. No allocation.
  template <class Visit>
  void traverse(const Ray& ray, double& tMax, Visit&& visit) const;

 private:
  struct Node {
    Bounds box;
    std::uint32_t start;  // leaf: first entry in items_; inner: index of the left child
    std::uint32_t count;  // leaf: number of items; inner: 0 (right child is start + 1)
  };
  static constexpr int kMaxDepth = 64;

  void build(std::uint32_t node, std::span<const Bounds> boxes, const std::vector<dvec3>& centres,
             std::uint32_t begin, std::uint32_t end, int depth);

  std::vector<Node> nodes_;
  std::vector<std::uint32_t> items_;  // in leaf order
  std::vector<Bounds> itemBoxes_;     // the boxes of items_, in the same order
  std::vector<std::uint32_t> unbounded_;
};

template <class Visit>
void Bvh::traverse(const Ray& ray, double& tMax, Visit&& visit) const {
  for (std::uint32_t item : unbounded_)
    if (!visit(item, ray.tMin)) return;
  if (nodes_.empty()) return;
  double rootEntry = boxEntry(nodes_[0].box, ray, ray.tMin, tMax);
  if (rootEntry == kInfinity) return;
  struct Entry {
    std::uint32_t node;
    double t;
  };
  Entry stack[kMaxDepth * 2];
  int top = 0;
  stack[top++] = {0, rootEntry};
  while (top > 0) {
    Entry e = stack[--top];
    if (e.t > tMax) continue;  // pruned since it was pushed
    const Node& node = nodes_[e.node];
    if (node.count > 0) {
      for (std::uint32_t i = node.start; i < node.start + node.count; ++i) {
        // A leaf of one item has the item's box; of several, each is tested.
        double t = node.count == 1 ? e.t : boxEntry(itemBoxes_[i], ray, ray.tMin, tMax);
        if (t != kInfinity && !visit(items_[i], t)) return;
      }
      continue;
    }
    std::uint32_t left = node.start, right = node.start + 1;
    double tl = boxEntry(nodes_[left].box, ray, ray.tMin, tMax);
    double tr = boxEntry(nodes_[right].box, ray, ray.tMin, tMax);
    // Push the farther child first, so the nearer one is visited first.
    if (tl > tr) std::swap(left, right), std::swap(tl, tr);
    if (tr != kInfinity) stack[top++] = {right, tr};
    if (tl != kInfinity) stack[top++] = {left, tl};
  }
}

}  // namespace csgray
