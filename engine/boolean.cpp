#include "engine/boolean.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "engine/flat_union.h"
#include "engine/span_union.h"

namespace csgray::detail {

namespace {

// Operands a ray meets that a union unites, or a difference subtracts, one
// at a time before it gathers the rest and unites them at once: below it,
// as before (a difference narrowing its window at each); a lens has one
// hole.
constexpr std::size_t kOperandsOneByOne = 8;

}  // namespace

Boolean::Boolean(Op op, std::vector<SolidPtr> operands) : op_(op) {
  if (operands.empty()) throw std::invalid_argument(kind() + ": needs at least one operand");
  // Union and intersection are associative; a difference is so in its
  // first operand: (a - b) - c = a - b - c. A first operand of this
  // operation is extended (its list shared, engine/operand_list.h); any
  // other such operand's list is copied in.
  const Boolean* base = nullptr;
  std::vector<SolidPtr> more;
  for (size_t i = 0; i < operands.size(); ++i) {
    const SolidPtr& s = operands[i];
    if (!s) throw std::invalid_argument(kind() + ": operand is not a solid");
    const Boolean* same = s->asBoolean();
    if (same && same->op_ == op_ && i == 0) {
      base = same;
      extended_ = s;
    } else if (same && same->op_ == op_ && op_ != Op::Difference) {
      more.insert(more.end(), same->operands_.begin(), same->operands_.end());
    } else {
      more.push_back(s);
    }
  }
  operands_ = base ? OperandList::extended(base->operands_, more) : OperandList(more);
  // The operands' sums, box and flags: base's, then the new operands'. A
  // difference's insideBeyondWindow_ and cutsShort_ are not gathered but
  // derived at the end, so they start afresh here.
  primitives_ = 0;
  booleans_ = 1;
  insideBeyondWindow_ = true;
  cutsShort_ = false;
  std::size_t i = 0;
  if (base) {
    primitives_ = base->primitives_;
    booleans_ = base->booleans_;
    depth_ = base->depth_;
    instances_ = base->instances_;
    insideBeyondWindow_ = base->insideBeyondWindow_;
    holesInsideBeyondWindow_ = base->holesInsideBeyondWindow_;
    cutsShort_ = op_ == Op::Union && base->cutsShort_;
    bounds_ = base->bounds_;
    i = base->operands_.size();
  }
  for (; i < operands_.size(); ++i) {
    const Solid& s = *operands_[i];
    cutsShort_ = cutsShort_ || (op_ == Op::Union && s.firstBoundaryCutsShort());
    insideBeyondWindow_ = insideBeyondWindow_ && s.insideBeyondWindow();
    if (i > 0) holesInsideBeyondWindow_ = holesInsideBeyondWindow_ && s.insideBeyondWindow();
    instances_ = instances_ || s.hasInstances();
    primitives_ += s.primitiveCount();
    booleans_ += s.booleanCount();
    depth_ = std::max(depth_, s.depth() + 1);
    // Checked per operand, before the sums could overflow.
    if (primitives_ > kMaxPrimitives)
      throw std::invalid_argument(kind() + ": the part would have more than " +
                                  std::to_string(kMaxPrimitives) +
                                  " primitives (counting each use of a shared part)");
    if (i == 0)
      bounds_ = s.bounds();
    else if (op_ == Op::Union)
      bounds_.include(s.bounds());
    else if (op_ == Op::Intersection)
      bounds_ = bounds_.intersected(s.bounds());
  }
  if (op_ == Op::Difference) {
    insideBeyondWindow_ = false;
    cutsShort_ = holesInsideBeyondWindow_;
  }
  firstCutsShort_ = op_ == Op::Difference && operands_[0]->firstBoundaryCutsShort();
  if (depth_ > kMaxDepth)
    throw std::invalid_argument(
        kind() + ": boolean tree deeper than " + std::to_string(kMaxDepth) +
        " levels; build long chains with union(list) or difference(a, list)");
  // An intersection's spans() tests its box, this one's, before anything
  // else (a difference's first operand is never a difference: the chain
  // is flat).
  if (const Boolean* first = operands_[0]->asBoolean())
    firstTestsThisBox_ = op_ == Op::Difference && first->op_ == Op::Intersection;
}

const Bvh& Boolean::bvh() const {
  // Once the tree is built (by prepare, before a render's threads start), a
  // ray pays one flag read: std::call_once costs a library call and
  // thread-local writes every time (2 % of a plate(8) render).
  if (bvhReady_.load(std::memory_order_acquire)) return bvh_;
  std::call_once(bvhBuilt_, [this] {
    const std::size_t limit = op_ == Op::Union ? kBvhUnionOperands : kBvhOperands;
    if (op_ != Op::Intersection && operands_.size() - firstInBvh() > limit) {
      std::vector<Bounds> boxes;
      boxes.reserve(operands_.size() - firstInBvh());
      for (std::size_t i = firstInBvh(); i < operands_.size(); ++i)
        boxes.push_back(operands_[i]->rayBox());
      bvh_ = Bvh(boxes);
    }
    bvhReady_.store(true, std::memory_order_release);
  });
  return bvh_;
}

Bounds Boolean::boundsUnder(const Affine& outer) const {
  if (outer.isTranslation() || primitiveCount() > kTightPrimitives || !bounds_.finite())
    return Solid::boundsUnder(outer);
  Bounds box = operands_[0]->boundsUnder(outer);
  for (std::size_t i = 1; i < operands_.size() && op_ != Op::Difference; ++i) {
    const Bounds b = operands_[i]->boundsUnder(outer);
    if (op_ == Op::Union)
      box.include(b);
    else
      box = box.intersected(b);
  }
  // Each is a box of the solid: the smaller of the two on each axis.
  return box.intersected(Solid::boundsUnder(outer));
}

SolidPtr Boolean::forRays() const {
  if (op_ != Op::Union) return shared_from_this();
  return keptFlatUnion(*this, flatMade_, flat_);
}

void Boolean::prepare() const {
  bvh();
  for (const SolidPtr& s : operands_) s->prepare();
}

std::string Boolean::kind() const {
  switch (op_) {
    case Op::Union:
      return "union";
    case Op::Intersection:
      return "intersection";
    case Op::Difference:
      return "difference";
  }
  return "boolean";
}

void Boolean::spans(const Ray& ray, SpanList& out) const {
  out.clear();
  // (A union with a BVH tests its box as the BVH's root; a difference whose
  // first operand tests this same box first leaves the test to it.)
  if ((op_ != Op::Union || bvh().empty()) && !firstTestsThisBox_ && !bounds_.hitBy(ray)) return;
  // The result so far is *result; each operand's spans are merged into the
  // other list and the two swap roles, so nothing is copied per operand.
  SpanList operand, spare;
  SpanList* result = &out;
  SpanList* other = &spare;
  auto fold = [&](const SpanList& in) {
    switch (op_) {
      case Op::Union:
        unite(*result, in, *other);
        break;
      case Op::Intersection:
        intersect(*result, in, *other);
        break;
      case Op::Difference:
        subtract(*result, in, *other);
        break;
    }
    std::swap(result, other);
  };
  auto finish = [&] {
    if (result != &out) out = *result;
  };

  if (op_ == Op::Union) {
    // The first operands one by one; past them the rest gathered and
    // united at once (engine/span_union.h: a row of balls met by a ray
    // along it).
    std::size_t met = 0;
    std::optional<BorrowedSpanUnion> rest;
    auto add = [&](const Solid& s, const Ray& r) {
      if (result->empty()) {
        s.spans(r, *result);
        return;
      }
      s.spans(r, operand);
      if (operand.empty()) return;
      if (met++ < kOperandsOneByOne) {
        fold(operand);
        return;
      }
      if (!rest) rest.emplace();
      (*rest)->add(operand);
    };
    if (const Bvh& tree = bvh(); tree.empty()) {
      for (const SolidPtr& s : operands_)
        if (s->bounds().hitBy(ray)) add(*s, ray);
    } else {
      double tMax = ray.tMax;
      tree.traverse(ray, tMax, [&](std::uint32_t i, double) {
        add(*operands_[i], ray);
        return true;
      });
    }
    if (rest && !(*rest)->empty()) fold((*rest)->united());
    finish();
    return;
  }

  // Intersection and difference: the result lies within the first
  // operand's spans, so the others are asked only about the stretch from
  // its first boundary to its last (a window that shrinks as the result
  // does), and the fold stops once the result is empty.
  // (A difference's box is its first operand's, tested above.)
  // (The first operand's box is not tested: an intersection's box lies
  // within it, and the slab test of a box within another, on the same
  // ray, rounds to a stretch within the other's, so the test above has
  // answered it.)
  const Solid& first = *operands_[0];
  first.spans(ray, out);
  Ray window = ray;
  auto narrow = [&] {
    if (result->empty()) return false;
    window.tMin = std::max(ray.tMin, result->front().in.t);
    window.tMax = std::min(ray.tMax, result->back().out.t);
    return true;
  };
  if (!narrow()) return;
  if (op_ == Op::Intersection) {
    for (std::size_t i = 1; i < operands_.size(); ++i) {
      const Solid& s = *operands_[i];
      if (!s.bounds().hitBy(window)) {
        out.clear();
        return;
      }
      s.spans(window, operand);
      if (!intersectSingleSpansInPlace(*result, operand)) fold(operand);
      if (!narrow()) break;
    }
    finish();
    return;
  }
  // The first holes one by one, as a lens's; past them the rest united
  // and subtracted once (engine/span_union.h: a ray across a drilled plate
  // meets its holes by the hundred).
  std::size_t cut = 0;
  std::optional<BorrowedSpanUnion> holes;
  forEachHole(window, [&](const Solid& s) {
    s.spans(window, operand);
    if (operand.empty()) return true;
    if (cut++ < kOperandsOneByOne) {
      fold(operand);
      return narrow();
    }
    if (!holes) holes.emplace();
    (*holes)->add(operand);
    return true;
  });
  if (holes && !(*holes)->empty()) fold((*holes)->united());
  finish();
}

template <class Cut>
void Boolean::forEachHole(Ray& window, Cut&& cut) const {
  if (const Bvh& tree = bvh(); tree.empty()) {
    for (std::size_t i = 1; i < operands_.size(); ++i)
      if (operands_[i]->bounds().hitBy(window) && !cut(*operands_[i])) return;
  } else {
    tree.traverse(window, window.tMax,
                  [&](std::uint32_t i, double) { return cut(*operands_[i + 1]); });
  }
}

void Boolean::spansToFirstBoundary(const Ray& ray, SpanList& out) const {
  if (op_ == Op::Union) {
    unionToFirstBoundary(ray, out);
    return;
  }
  if (op_ != Op::Difference || !holesInsideBeyondWindow_) {
    spans(ray, out);
    return;
  }
  out.clear();
  if (!firstTestsThisBox_ && !bounds_.hitBy(ray)) return;
  // The first operand's first boundary is the answer unless a hole covers
  // it: then its spans beyond are needed, and one that cuts them short is
  // asked for them all.
  bool whole = !firstCutsShort_;
  if (whole) {
    operands_[0]->spans(ray, out);
  } else {
    operands_[0]->spansToFirstBoundary(ray, out);
  }
  SpanList operand, spare;
  SpanList* result = &out;
  SpanList* other = &spare;
  double reach = 0.0;
  while (!result->empty()) {
    // The result starts where the first operand's spans, less the holes
    // cut so far, start: the answer, unless a hole covers that point.
    const double start = result->front().in.t;
    if (!(start > ray.tMin)) {  // the ray starts inside: where it leaves needs every hole
      spans(ray, out);
      return;
    }
    if (start > ray.tMax) break;  // no boundary within the window
    // The holes that meet the start, or lie within the distance at which
    // boundaries are one point (span_list.h); the spans they give are
    // theirs beyond that, so the cut is exact as far as it reaches. A
    // sweep ends its spans just past the window (profile_sweep.h), so a
    // hole may move the start only that far: the window doubles each time
    // the start moves, which crosses a sweep in a few steps rather than
    // creeping through it (a box less an extruded circle rendered 500×
    // slower without it).
    reach = std::max(2.0 * kSameT * std::abs(start), 2.0 * reach);
    Ray point = ray;
    point.tMin = start;
    point.tMax = std::min(ray.tMax, start + reach);
    forEachHole(point, [&](const Solid& hole) {
      hole.spans(point, operand);
      if (operand.empty()) return true;
      subtract(*result, operand, *other);
      std::swap(result, other);
      return !result->empty();
    });
    if (!result->empty() && result->front().in.t == start) break;
    if (!whole) {
      whole = true;
      operands_[0]->spans(ray, out);
      result = &out;
      other = &spare;
      reach = 0.0;
    }
  }
  if (result != &out) out = *result;
}

void Boolean::unionToFirstBoundary(const Ray& ray, SpanList& out) const {
  out.clear();
  const Bvh& tree = bvh();
  if (tree.empty() && !bounds_.hitBy(ray)) return;
  // A ray that starts outside every operand first meets the union where it
  // first enters one of them: the operands are asked for their first
  // boundaries only, and those whose boxes it enters beyond the best so far
  // not at all. An operand the ray starts inside makes that an exit, which
  // needs all of them.
  SpanList operand;
  double best = ray.tMax;
  bool startsInside = false;
  Ray window = ray;
  auto visit = [&](const Solid& s) {
    window.tMax = best;
    s.spansToFirstBoundary(window, operand);
    for (const Span& span : operand) {
      if (span.out.t <= ray.tMin) continue;
      if (!(span.in.t > ray.tMin)) {
        startsInside = true;
        return false;
      }
      // Entries within the distance at which boundaries are one point go
      // to the operand met first, as in the merge of the whole spans
      // (span_list.h), so that coplanar faces show the same operand.
      if (span.in.t <= best && span.in.t + kSameT * std::abs(span.in.t) < best) {
        best = span.in.t;
        out = operand;
      }
      break;
    }
    return true;
  };
  if (tree.empty()) {
    for (const SolidPtr& s : operands_) {
      window.tMax = best;
      if (s->bounds().hitBy(window) && !visit(*s)) break;
    }
  } else {
    tree.traverse(window, best, [&](std::uint32_t i, double) { return visit(*operands_[i]); });
  }
  if (startsInside) spans(ray, out);
}

bool Boolean::meetsWindow(const Ray& ray, SpanList& scratch) const {
  if (op_ != Op::Union) return Solid::meetsWindow(ray, scratch);
  // (A union without a BVH tests its operands' boxes, not its own.)
  bool met = false;
  forEachOperandHitBy(ray, [&](const Solid& s) {
    met = s.meetsWindow(ray, scratch);
    return !met;
  });
  return met;
}

bool Boolean::contains(const dvec3& p) const {
  if (op_ == Op::Intersection) {
    for (const SolidPtr& s : operands_)
      if (!s->contains(p)) return false;
    return true;
  }
  if (op_ == Op::Difference && !operands_[0]->contains(p)) return false;
  // Whether an operand of a union, or a cutter, holds p: only those whose
  // boxes hold it are asked, through the tree where there is one (a union
  // of thousands, asked of a hundred thousand points by csgray check).
  bool held = false;
  const std::size_t first = firstInBvh();
  if (const Bvh& tree = bvh(); tree.empty()) {
    for (std::size_t i = first; i < operands_.size() && !held; ++i)
      held = operands_[i]->contains(p);
  } else {
    // Boxes are rounded outward or inward by a unit in the last place.
    const double slack = 1e-12 * (1.0 + std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}));
    tree.forEachHolding(p, slack, [&](std::uint32_t item) {
      held = operands_[first + item]->contains(p);
      return !held;
    });
  }
  return op_ == Op::Union ? held : !held;
}

SolidPtr Boolean::mapPrimitives(const PrimitiveMap& f) const {
  std::vector<SolidPtr> mapped;
  mapped.reserve(operands_.size());
  for (const SolidPtr& s : operands_) mapped.push_back(s->mapPrimitives(f));
  auto copy = std::make_shared<Boolean>(op_, std::move(mapped));
  copy->setOrigin(origin());
  return copy;
}

SolidPtr Boolean::withOperands(std::vector<SolidPtr> operands) const {
  if (std::equal(operands.begin(), operands.end(), operands_.begin(), operands_.end()))
    return shared_from_this();
  if (operands.size() == 1) return std::move(operands.front());
  auto copy = std::make_shared<Boolean>(op_, std::move(operands));
  copy->setOrigin(origin());
  return copy;
}

SolidPtr Boolean::mapSharedPrimitives(const PrimitiveMap& f, SharedMap& done) const {
  // A node used many times (under instances) is mapped once.
  if (auto found = done.find(this); found != done.end()) return found->second;
  std::vector<SolidPtr> mapped;
  mapped.reserve(operands_.size());
  for (const SolidPtr& s : operands_) mapped.push_back(s->mapSharedPrimitives(f, done));
  auto copy = std::make_shared<Boolean>(op_, std::move(mapped));
  copy->setOrigin(origin());
  done.emplace(this, copy);
  return copy;
}

SolidPtr unionOf(std::vector<SolidPtr> operands) {
  return std::make_shared<Boolean>(Boolean::Op::Union, std::move(operands));
}
SolidPtr intersectionOf(std::vector<SolidPtr> operands) {
  return std::make_shared<Boolean>(Boolean::Op::Intersection, std::move(operands));
}
SolidPtr differenceOf(std::vector<SolidPtr> operands) {
  return std::make_shared<Boolean>(Boolean::Op::Difference, std::move(operands));
}

}  // namespace csgray::detail
