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
#if defined(__AVX__)
#include <immintrin.h>
#elif defined(__SSE2__)
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
    return nodes_.capacity() * sizeof(Node) + items_.capacity() * sizeof(std::uint32_t) +
           unbounded_.capacity() * sizeof(std::uint32_t);
  }

  // Calls visit(item, tEnter) for every item whose box the ray meets within
  // [ray.tMin, tMax], depth first with the nearer children first (unbounded
  // items first of all, with tEnter = ray.tMin). visit may lower tMax to prune boxes beyond it,
  // and returns false to stop the traversal. No allocation.
  template <class Visit>
  void traverse(const Ray& ray, double& tMax, Visit&& visit) const;

  // Calls visit(item) for every item whose box holds p, or comes within
  // `slack` of it (a box rounded inward by a hair still holds its solid's
  // points), unbounded items first; visit returns false to stop. No
  // allocation.
  template <class Visit>
  void forEachHolding(const dvec3& p, double slack, Visit&& visit) const;

  static constexpr int kWidth = 4;

 private:
  // A node of up to four children: the binary SAH tree collapsed, each
  // node taking its children's children while it has room (multi-branching
  // BVHs for single-ray SIMD traversal: Wald, Benthin and Boulos, "Getting
  // rid of packets", IEEE Symposium on Interactive Ray Tracing 2008), so
  // that one AVX test of four boxes replaces up to three tests of two. The
  // boxes stay in double precision: each child's entry t is the one
  // Bounds::entry gives.
  struct Node {
    // The children's boxes axis by axis: lo[axis][child].
    alignas(32) double lo[3][kWidth];
    alignas(32) double hi[3][kWidth];
    // A leaf child: its first entry in items_ and the number of items;
    // an inner child: its node and kInner. An unused slot is a leaf of no
    // items with an empty box.
    std::uint32_t first[kWidth];
    std::uint32_t count[kWidth];
  };
  static constexpr std::uint32_t kInner = ~std::uint32_t(0);
  // Where the ray enters each child of a node (+inf: missed).
  static void childEntries(const Node& node, const Ray& ray, const bool negative[3], double tMin,
                           double tMax, double t[kWidth]);
  static constexpr int kMaxDepth = 64;

  std::vector<Node> nodes_;           // nodes_[0] is the root
  std::vector<std::uint32_t> items_;  // in leaf order
  std::vector<std::uint32_t> unbounded_;
  Bounds onlyBox_;  // the box of the one bounded item, when there is one only

  friend class BvhBuilder;
};

template <class Visit>
void Bvh::traverse(const Ray& ray, double& tMax, Visit&& visit) const {
  for (std::uint32_t item : unbounded_)
    if (!visit(item, ray.tMin)) return;
  if (nodes_.empty()) return;
  // One bounded item (a scene of one part over a ground plane): its slab
  // test alone, the one the node's would give (childEntries), without the
  // node's other three slots, the ordering and the stack.
  if (items_.size() == 1) {
    const double t = boxEntry(onlyBox_, ray, ray.tMin, tMax);
    if (t != kInfinity) visit(items_[0], t);
    return;
  }
  // A child that is met lies on the stack until it is visited: a node or a
  // leaf's items, and where the ray enters its box.
  struct Entry {
    std::uint32_t first, count;
    double t;
  };
  // Each node pushes at most three children, and the tree is at most
  // kMaxDepth deep.
  Entry stack[(kWidth - 1) * kMaxDepth + 1];
  // Which face of a slab the ray meets first: the low one unless it runs
  // towards negative coordinates.
  const bool negative[3] = {std::signbit(ray.invDir.x), std::signbit(ray.invDir.y),
                            std::signbit(ray.invDir.z)};
  int top = 0;
  Entry e{0, kInner, ray.tMin};
  for (;;) {
    if (e.count != kInner) {
      for (std::uint32_t i = e.first; i < e.first + e.count; ++i)
        if (!visit(items_[i], e.t)) return;
    } else {
      const Node& node = nodes_[e.first];
      double t[kWidth];
      childEntries(node, ray, negative, ray.tMin, tMax, t);
      // The children met, nearest first; children met at the same t keep
      // their order in the tree (insertion sort: stable, and short).
      Entry met[kWidth];
      int n = 0;
      for (int c = 0; c < kWidth; ++c) {
        if (t[c] == kInfinity) continue;
        int j = n++;
        for (; j > 0 && met[j - 1].t > t[c]; --j) met[j] = met[j - 1];
        met[j] = {node.first[c], node.count[c], t[c]};
      }
      if (n > 0) {
        // The nearest is visited next without going through the stack.
        for (int j = n - 1; j > 0; --j) stack[top++] = met[j];
        e = met[0];
        continue;
      }
    }
    do {  // the next child on the stack not pruned since it was pushed
      if (top == 0) return;
      e = stack[--top];
    } while (e.t > tMax);
  }
}

template <class Visit>
void Bvh::forEachHolding(const dvec3& p, double slack, Visit&& visit) const {
  for (std::uint32_t item : unbounded_)
    if (!visit(item)) return;
  if (nodes_.empty()) return;
  auto holds = [&](const dvec3& lo, const dvec3& hi) {
    for (int a = 0; a < 3; ++a)
      if (!(p[a] >= lo[a] - slack && p[a] <= hi[a] + slack)) return false;
    return true;
  };
  if (items_.size() == 1) {
    if (holds(onlyBox_.lo, onlyBox_.hi)) visit(items_[0]);
    return;
  }
  // Nodes whose box holds p, waiting to be opened: each pushes at most
  // four, and the tree is at most kMaxDepth deep.
  std::uint32_t stack[kWidth * kMaxDepth + 1];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    for (int c = 0; c < kWidth; ++c) {
      if (!holds(dvec3(node.lo[0][c], node.lo[1][c], node.lo[2][c]),
                 dvec3(node.hi[0][c], node.hi[1][c], node.hi[2][c])))
        continue;
      if (node.count[c] == kInner) {
        stack[top++] = node.first[c];
        continue;
      }
      for (std::uint32_t i = node.first[c]; i < node.first[c] + node.count[c]; ++i)
        if (!visit(items_[i])) return;
    }
  }
}

inline void Bvh::childEntries(const Node& node, const Ray& ray, const bool negative[3], double tMin,
                              double tMax, double t[kWidth]) {
  // The slab test with the near and far planes chosen by the ray's
  // direction, so no swap is needed. A ray parallel to a slab and on one of
  // its planes gives NaN (0·inf); max and min below then keep the other
  // operand, so the ray counts as within that slab (as in Bounds::entry).
#if defined(__AVX__)
  __m256d t0 = _mm256_set1_pd(tMin), t1 = _mm256_set1_pd(tMax);
  for (int a = 0; a < 3; ++a) {
    __m256d o = _mm256_set1_pd(ray.origin[a]), inv = _mm256_set1_pd(ray.invDir[a]);
    __m256d lo = _mm256_load_pd(node.lo[a]), hi = _mm256_load_pd(node.hi[a]);
    __m256d near = _mm256_mul_pd(_mm256_sub_pd(negative[a] ? hi : lo, o), inv);
    __m256d far = _mm256_mul_pd(_mm256_sub_pd(negative[a] ? lo : hi, o), inv);
    t0 = _mm256_max_pd(near, t0);  // NaN near: keeps t0
    t1 = _mm256_min_pd(far, t1);   // NaN far: keeps t1
  }
  __m256d hit = _mm256_cmp_pd(t0, t1, _CMP_LE_OQ);
  _mm256_storeu_pd(t, _mm256_blendv_pd(_mm256_set1_pd(kInfinity), t0, hit));
#elif defined(__SSE2__)
  for (int pair = 0; pair < kWidth; pair += 2) {
    __m128d t0 = _mm_set1_pd(tMin), t1 = _mm_set1_pd(tMax);
    for (int a = 0; a < 3; ++a) {
      __m128d o = _mm_set1_pd(ray.origin[a]), inv = _mm_set1_pd(ray.invDir[a]);
      __m128d lo = _mm_load_pd(node.lo[a] + pair), hi = _mm_load_pd(node.hi[a] + pair);
      __m128d near = _mm_mul_pd(_mm_sub_pd(negative[a] ? hi : lo, o), inv);
      __m128d far = _mm_mul_pd(_mm_sub_pd(negative[a] ? lo : hi, o), inv);
      t0 = _mm_max_pd(near, t0);  // NaN near: keeps t0
      t1 = _mm_min_pd(far, t1);   // NaN far: keeps t1
    }
    __m128d hit = _mm_cmple_pd(t0, t1);
    __m128d entry = _mm_or_pd(_mm_and_pd(hit, t0), _mm_andnot_pd(hit, _mm_set1_pd(kInfinity)));
    _mm_storeu_pd(t + pair, entry);
  }
#else
  for (int i = 0; i < kWidth; ++i) {
    double t0 = tMin, t1 = tMax;
    for (int a = 0; a < 3; ++a) {
      double near = ((negative[a] ? node.hi : node.lo)[a][i] - ray.origin[a]) * ray.invDir[a];
      double far = ((negative[a] ? node.lo : node.hi)[a][i] - ray.origin[a]) * ray.invDir[a];
      t0 = near > t0 ? near : t0;
      t1 = far < t1 ? far : t1;
    }
    t[i] = t0 <= t1 ? t0 : kInfinity;
  }
#endif
}

}  // namespace csgray::detail
