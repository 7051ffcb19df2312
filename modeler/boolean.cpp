#include "modeler/boolean.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace csgray {

Boolean::Boolean(Op op, std::vector<SolidPtr> operands) : op_(op) {
  if (operands.empty()) throw std::invalid_argument(kind() + ": needs at least one operand");
  for (size_t i = 0; i < operands.size(); ++i) {
    const SolidPtr& s = operands[i];
    if (!s) throw std::invalid_argument(kind() + ": operand is not a solid");
    // Union and intersection are associative; a difference is so in its
    // first operand: (a - b) - c = a - b - c.
    auto* same = dynamic_cast<const Boolean*>(s.get());
    bool splice = same && same->op_ == op_ && (op_ != Op::Difference || i == 0);
    if (splice) {
      operands_.insert(operands_.end(), same->operands_.begin(), same->operands_.end());
    } else {
      operands_.push_back(s);
    }
  }
  primitives_ = 0;
  booleans_ = 1;
  for (const SolidPtr& s : operands_) {
    primitives_ += s->primitiveCount();
    booleans_ += s->booleanCount();
    depth_ = std::max(depth_, s->depth() + 1);
    // Checked per operand, before the sums could overflow.
    if (primitives_ > kMaxPrimitives)
      throw std::invalid_argument(kind() + ": the part would have more than " +
                                  std::to_string(kMaxPrimitives) +
                                  " primitives (counting each use of a shared part)");
  }
  if (depth_ > kMaxDepth)
    throw std::invalid_argument(
        kind() + ": boolean tree deeper than " + std::to_string(kMaxDepth) +
        " levels; build long chains with union(list) or difference(a, list)");
  switch (op_) {
    case Op::Union:
      for (const SolidPtr& s : operands_) bounds_.include(s->bounds());
      break;
    case Op::Intersection:
      bounds_ = operands_[0]->bounds();
      for (const SolidPtr& s : operands_) bounds_ = bounds_.intersected(s->bounds());
      break;
    case Op::Difference:
      bounds_ = operands_[0]->bounds();
      break;
  }
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
  if (!bounds_.hitBy(ray)) return;
  // Fold the operands into out, merging through a scratch list.
  SpanList operand, merged;
  bool first = true;
  for (const SolidPtr& s : operands_) {
    bool hit = s->bounds().hitBy(ray);
    if (!hit) {
      if (op_ == Op::Union) continue;
      if (op_ == Op::Intersection || first) {
        out.clear();
        return;
      }
      continue;  // a subtracted operand that the ray misses removes nothing
    }
    if (first) {
      s->spans(ray, out);
      first = false;
    } else {
      s->spans(ray, operand);
      if (operand.empty()) {
        if (op_ == Op::Intersection) {
          out.clear();
          return;
        }
        continue;
      }
      if (out.empty() && op_ == Op::Union) {
        out = operand;
        continue;
      }
      switch (op_) {
        case Op::Union:
          unite(out, operand, merged);
          break;
        case Op::Intersection:
          intersect(out, operand, merged);
          break;
        case Op::Difference:
          subtract(out, operand, merged);
          break;
      }
      out = merged;
    }
    if (out.empty() && op_ != Op::Union) return;
  }
}

bool Boolean::contains(const dvec3& p) const {
  switch (op_) {
    case Op::Union:
      for (const SolidPtr& s : operands_)
        if (s->contains(p)) return true;
      return false;
    case Op::Intersection:
      for (const SolidPtr& s : operands_)
        if (!s->contains(p)) return false;
      return true;
    case Op::Difference:
      if (!operands_[0]->contains(p)) return false;
      for (size_t i = 1; i < operands_.size(); ++i)
        if (operands_[i]->contains(p)) return false;
      return true;
  }
  return false;
}

SolidPtr Boolean::mapPrimitives(const PrimitiveMap& f) const {
  std::vector<SolidPtr> mapped;
  mapped.reserve(operands_.size());
  for (const SolidPtr& s : operands_) mapped.push_back(s->mapPrimitives(f));
  return std::make_shared<Boolean>(op_, std::move(mapped));
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

}  // namespace csgray
