#include "profile/region.h"

#include <algorithm>
#include <glm/common.hpp>
#include <stdexcept>
#include <string>

namespace csgray::detail {

RegionPtr Region::leaf(Profile profile) {
  auto r = std::make_shared<Region>();
  r->bounds_ = profile.bounds();
  r->profile_ = std::move(profile);
  return r;
}

RegionPtr Region::boolean(Op op, std::vector<RegionPtr> operands) {
  if (op == Op::Leaf || operands.empty())
    throw std::invalid_argument("a boolean of regions needs at least one region");
  auto r = std::make_shared<Region>();
  r->op_ = op;
  r->bounds_ = operands.front()->bounds();
  for (const RegionPtr& operand : operands) r->depth_ = std::max(r->depth_, operand->depth() + 1);
  if (r->depth_ > kMaxDepth)
    throw std::invalid_argument("2D boolean tree deeper than " + std::to_string(kMaxDepth) +
                                " levels; build long chains with union(list) or "
                                "difference(a, list)");
  for (std::size_t i = 1; i < operands.size(); ++i) {
    const ProfileBounds& b = operands[i]->bounds();
    if (op == Op::Union) {
      r->bounds_.include(b);
    } else if (op == Op::Intersection) {
      r->bounds_.lo = glm::max(r->bounds_.lo, b.lo);
      r->bounds_.hi = glm::min(r->bounds_.hi, b.hi);
    }
  }
  r->operands_ = std::move(operands);
  return r;
}

bool Region::contains(const dvec2& p) const {
  switch (op_) {
    case Op::Leaf:
      return profile_.contains(p);
    case Op::Union:
      for (const RegionPtr& r : operands_)
        if (r->contains(p)) return true;
      return false;
    case Op::Intersection:
      for (const RegionPtr& r : operands_)
        if (!r->contains(p)) return false;
      return true;
    case Op::Difference:
      if (!operands_.front()->contains(p)) return false;
      for (std::size_t i = 1; i < operands_.size(); ++i)
        if (operands_[i]->contains(p)) return false;
      return true;
  }
  return false;
}

RegionPtr Region::transformed(const Affine2& map) const {
  if (op_ == Op::Leaf) return leaf(profile_.transformed(map));
  std::vector<RegionPtr> ops;
  ops.reserve(operands_.size());
  for (const RegionPtr& r : operands_) ops.push_back(r->transformed(map));
  return boolean(op_, std::move(ops));
}

void Region::forEachLeaf(const std::function<void(const Profile&)>& f) const {
  if (op_ == Op::Leaf) {
    f(profile_);
    return;
  }
  for (const RegionPtr& r : operands_) r->forEachLeaf(f);
}

}  // namespace csgray::detail
