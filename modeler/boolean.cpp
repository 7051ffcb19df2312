#include "modeler/boolean.h"

#include <stdexcept>
#include <utility>

namespace csgray {

Boolean::Boolean(Op op, std::vector<SolidPtr> operands) : op_(op), operands_(std::move(operands)) {
  if (operands_.empty()) throw std::invalid_argument(kind() + ": needs at least one operand");
  for (const SolidPtr& s : operands_)
    if (!s) throw std::invalid_argument(kind() + ": operand is not a solid");
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
