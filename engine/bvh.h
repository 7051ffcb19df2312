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
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <cmath>

#include "engine/bounds.h"

namespace csgray::detail {

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
    return nodes_.capacity() * sizeof(Node) + children_.capacity() * sizeof(ChildBoxes) +
           items_.capacity() * sizeof(std::uint32_t) +
           unbounded_.capacity() * sizeof(std::uint32_t);
  }

  // Calls visit(item, tEnter) for every item whose box the ray meets within
  // [ray.tMin, tMax], depth first with the nearer child first (unbounded
  // items first of all, with tEnter = ray.tMin). visit may lower tMax to prune boxes beyond it,
  // and returns false to stop the traversal. No allocation.
  template <class Visit>
  void traverse(const Ray& ray, double& tMax, Visit&& visit) const;

 private:
  struct Node {
    std::uint32_t start;  // leaf: first entry in items_; inner: index of the left child
    std::uint32_t count;  // leaf: number of items; inner: 0 (right child is start + 1)
  };
  // An inner node's two child boxes, axis by axis, so that both are tested
  // at once: lo[axis][child], hi[axis][child].
  struct ChildBoxes {
    alignas(16) double lo[3][2];
    alignas(16) double hi[3][2];
  };
  // Where the ray enters each child of an inner node (+inf: missed).
  static void childEntries(const ChildBoxes& c, const Ray& ray, const bool negative[3], double tMin,
                           double tMax, double t[2]);
  static constexpr int kMaxDepth = 64;

  void build(std::uint32_t node, std::span<const Bounds> boxes, const std::vector<dvec3>& centres,
             std::vector<Bounds>& nodeBoxes, std::uint32_t begin, std::uint32_t end, int depth);

  std::vector<Node> nodes_;
  std::vector<ChildBoxes> children_;  // per node; used for inner nodes
  std::vector<std::uint32_t> items_;  // in leaf order
  Bounds rootBox_;
  std::vector<std::uint32_t> unbounded_;
};

template <class Visit>
void Bvh::traverse(const Ray& ray, double& tMax, Visit&& visit) const {
  for (std::uint32_t item : unbounded_)
    if (!visit(item, ray.tMin)) return;
  if (nodes_.empty()) return;
  double rootEntry = boxEntry(rootBox_, ray, ray.tMin, tMax);
  if (rootEntry == kInfinity) return;
  struct Entry {
    std::uint32_t node;
    double t;
  };
  Entry stack[kMaxDepth * 2];
  // Which face of a slab the ray meets first: the low one unless it runs
  // towards negative coordinates.
  const bool negative[3] = {std::signbit(ray.invDir.x), std::signbit(ray.invDir.y),
                            std::signbit(ray.invDir.z)};
  // The nearer child of a node is visited next without going through the
  // stack: a store and a load less on the path from node to node.
  int top = 0;
  Entry e{0, rootEntry};
  for (;;) {
    const Node& node = nodes_[e.node];
    if (node.count > 0) {
      // A leaf holds one item, whose box is the leaf's (only a tree cut off
      // at kMaxDepth has larger leaves: their items are all visited).
      for (std::uint32_t i = node.start; i < node.start + node.count; ++i)
        if (!visit(items_[i], e.t)) return;
    } else {
      std::uint32_t left = node.start, right = node.start + 1;
      double t[2];
      childEntries(children_[e.node], ray, negative, ray.tMin, tMax, t);
      double tl = t[0], tr = t[1];
      if (tl > tr) std::swap(left, right), std::swap(tl, tr);
      if (tl != kInfinity) {
        if (tr != kInfinity) stack[top++] = {right, tr};
        e = {left, tl};
        continue;
      }
    }
    do {  // the next child on the stack not pruned since it was pushed
      if (top == 0) return;
      e = stack[--top];
    } while (e.t > tMax);
  }
}

inline void Bvh::childEntries(const ChildBoxes& c, const Ray& ray, const bool negative[3],
                              double tMin, double tMax, double t[2]) {
  // The slab test with the near and far planes chosen by the ray's
  // direction, so no swap is needed. A ray parallel to a slab and on one of
  // its planes gives NaN (0·inf); max and min below then keep the other
  // operand, so the ray counts as within that slab (as in Bounds::entry).
#if defined(__SSE2__)
  __m128d t0 = _mm_set1_pd(tMin), t1 = _mm_set1_pd(tMax);
  for (int a = 0; a < 3; ++a) {
    __m128d o = _mm_set1_pd(ray.origin[a]), inv = _mm_set1_pd(ray.invDir[a]);
    __m128d lo = _mm_load_pd(c.lo[a]), hi = _mm_load_pd(c.hi[a]);
    __m128d near = _mm_mul_pd(_mm_sub_pd(negative[a] ? hi : lo, o), inv);
    __m128d far = _mm_mul_pd(_mm_sub_pd(negative[a] ? lo : hi, o), inv);
    t0 = _mm_max_pd(near, t0);  // NaN near: keeps t0
    t1 = _mm_min_pd(far, t1);   // NaN far: keeps t1
  }
  __m128d hit = _mm_cmple_pd(t0, t1);
  __m128d entry = _mm_or_pd(_mm_and_pd(hit, t0), _mm_andnot_pd(hit, _mm_set1_pd(kInfinity)));
  _mm_storeu_pd(t, entry);
#else
  for (int i = 0; i < 2; ++i) {
    double t0 = tMin, t1 = tMax;
    for (int a = 0; a < 3; ++a) {
      double near = ((negative[a] ? c.hi : c.lo)[a][i] - ray.origin[a]) * ray.invDir[a];
      double far = ((negative[a] ? c.lo : c.hi)[a][i] - ray.origin[a]) * ray.invDir[a];
      t0 = near > t0 ? near : t0;
      t1 = far < t1 ? far : t1;
    }
    t[i] = t0 <= t1 ? t0 : kInfinity;
  }
#endif
}

}  // namespace csgray::detail
