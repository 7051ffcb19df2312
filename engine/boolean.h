// An n-ary boolean node: union, intersection or difference (the first
// operand minus all others). Each node keeps its bounding box, skips
// operands whose box the ray misses, and stops as soon as an intersection
// or difference is empty. A node with many operands keeps a BVH over them
// (over the subtracted ones, for a difference), so that a ray visits only
// the operands it can hit; the operands that cut the first are asked only
// about the stretch of the ray where the first has spans.
#pragma once

#include <atomic>
#include <mutex>
#include <vector>

#include "engine/bvh.h"
#include "engine/operand_list.h"
#include "engine/solid.h"

namespace csgray::detail {

class Boolean : public Solid {
 public:
  enum class Op { Union, Intersection, Difference };

  // Limits that keep rays and destructors off the end of the stack, and
  // trees whose shared subtrees multiply out within reach.
  static constexpr int kMaxDepth = 1000;
  static constexpr std::size_t kMaxPrimitives = 2'000'000;
  // Nodes with more operands than this keep a BVH over them. A union of
  // two or more keeps one too: a ray's first boundary in it is a walk
  // nearest first (unionToFirstBoundary), and one BVH node tests up to
  // four operands' boxes at once.
  static constexpr std::size_t kBvhOperands = 4;
  static constexpr std::size_t kBvhUnionOperands = 1;

  // A chain of the same operation is kept flat: (a - b) - c becomes
  // a - b - c, and a union operand of a union is spliced in, so a script
  // that drills holes one at a time in a loop builds a wide node, not a
  // deep one. Throws std::invalid_argument for an empty operand list, a
  // tree deeper than kMaxDepth or larger than kMaxPrimitives.
  Boolean(Op op, std::vector<SolidPtr> operands);

  Op op() const { return op_; }
  const Bounds& bounds() const override { return bounds_; }
  // From the operands' boxes under outer, by the rules of bounds_, for a
  // node of at most kTightPrimitives primitives; moved corners otherwise (a
  // shared subtree is not walked once per use).
  Bounds boundsUnder(const Affine& outer) const override;
  static constexpr std::size_t kTightPrimitives = 16;
  void spans(const Ray& ray, SpanList& out) const override;
  // For a difference: the first operand's spans, cut only by the holes that
  // cover the point where the result would start, again from where a cut
  // moved it, so that a ray meets the holes at a point or two rather than
  // along all of the first operand. For a union: the first boundary of the
  // operand the ray enters first, the others asked only up to it.
  void spansToFirstBoundary(const Ray& ray, SpanList& out) const override;
  bool firstBoundaryCutsShort() const override { return cutsShort_; }
  // For a union: does any operand meet the window? The first one that does
  // ends the search.
  bool meetsWindow(const Ray& ray, SpanList& scratch) const override;
  bool contains(const dvec3& p) const override;
  std::span<const SolidPtr> children() const override { return operands_.span(); }
  const OperandList& operands() const { return operands_; }
  // The node whose operands this one's begin with, shared with it (the last
  // node of a chain built one operand at a time, extended), while it
  // lives; null when there is none.
  SolidPtr extended() const { return extended_.lock(); }
  // Calls visit(operand) for each operand whose box the ray meets within
  // its window (through the BVH where there is one) until it returns false.
  template <class Visit>
  void forEachOperandHitBy(const Ray& ray, Visit&& visit) const;
  std::string kind() const override;
  const Boolean* asBoolean() const override { return this; }
  SolidPtr mapPrimitives(const PrimitiveMap& f) const override;
  // This node over other operands, for the rewrites of a tree: itself
  // where they are its own (the same pointers, in order), else a new node
  // of its operation and origin. A single operand is returned as it is.
  SolidPtr withOperands(std::vector<SolidPtr> operands) const;
  SolidPtr mapSharedPrimitives(const PrimitiveMap& f, SharedMap& done) const override;
  void prepare() const override;
  SolidPtr forRays() const override;

 private:
  // Operands from this index on are found through the BVH.
  std::size_t firstInBvh() const { return op_ == Op::Difference ? 1 : 0; }
  // Calls cut(hole) for each subtracted operand whose box meets the window
  // until it returns false; cut may narrow the window as it goes.
  template <class Cut>
  void forEachHole(Ray& window, Cut&& cut) const;
  void unionToFirstBoundary(const Ray& ray, SpanList& out) const;

  Op op_;
  OperandList operands_;
  std::weak_ptr<const Solid> extended_;
  Bounds bounds_;
  // spansToFirstBoundary takes each hole's spans beyond the point it asks
  // about as they come, so they must lie inside the hole there (solid.h).
  bool holesInsideBeyondWindow_ = true;
  // firstBoundaryCutsShort: a difference's first boundary leaves out the
  // holes beyond it. A union's leaves out the operands beyond it, but that
  // saves less than asking again where a hole covers the boundary costs
  // (plate(8) and plate(32) ran 3 % more instructions), unless an operand
  // cuts short itself.
  bool cutsShort_ = false;
  // A difference whose first operand cuts short (asked once, here).
  bool firstCutsShort_ = false;
  // A difference whose first operand's spans() begins with the test of
  // this node's box (the same box, on the same ray): no need to test it
  // twice (a lens's shadow and camera rays: 1.5 % of lens_field).
  bool firstTestsThisBox_ = false;
  // Built on first use (or by prepare), so that the intermediate nodes of a
  // script that adds operands one at a time never build one.
  const Bvh& bvh() const;
  mutable std::once_flag bvhBuilt_;
  mutable std::atomic<bool> bvhReady_{false};
  mutable Bvh bvh_;  // empty for few operands, and for intersections (every operand counts)
  // forRays()'s union (keptFlatUnion) when it is not this node (which it cannot hold).
  mutable std::once_flag flatMade_;
  mutable SolidPtr flat_;
};

template <class Visit>
void Boolean::forEachOperandHitBy(const Ray& ray, Visit&& visit) const {
  const Bvh& tree = bvh();
  const std::size_t first = tree.empty() ? operands_.size() : firstInBvh();
  for (std::size_t i = 0; i < first; ++i)
    if (operands_[i]->bounds().hitBy(ray) && !visit(*operands_[i])) return;
  if (tree.empty()) return;
  double tMax = ray.tMax;
  tree.traverse(ray, tMax, [&](std::uint32_t i, double) { return visit(*operands_[first + i]); });
}

SolidPtr unionOf(std::vector<SolidPtr> operands);
SolidPtr intersectionOf(std::vector<SolidPtr> operands);
SolidPtr differenceOf(std::vector<SolidPtr> operands);

}  // namespace csgray::detail
