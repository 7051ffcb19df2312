// A region: the 2D counterpart of a solid. Leaves are profiles; inner nodes
// are booleans of regions. A transform is applied to the leaves when it is
// given, since an affine map takes segments to segments and elliptic arcs to
// elliptic arcs exactly. Sweeps (extrusions, revolutions) are preimages of
// a region under a map, so they commute with its booleans: a sweep of a
// region is evaluated leaf by leaf along a ray and merged as the tree says.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "profile/profile.h"

namespace csgray::detail {

class Region;
using RegionPtr = std::shared_ptr<const Region>;

class Region {
 public:
  enum class Op { Leaf, Union, Intersection, Difference };

  static RegionPtr leaf(Profile profile);
  // Trees deeper than this are refused, as solids' are: every walk over
  // the tree recurses (a chain of 20 000 booleans overflowed the stack).
  static constexpr int kMaxDepth = 1000;

  // Difference: the first operand minus all others. Throws
  // std::invalid_argument for no operands, or a tree deeper than kMaxDepth.
  static RegionPtr boolean(Op op, std::vector<RegionPtr> operands);

  Op op() const { return op_; }
  const Profile& profile() const { return profile_; }  // a leaf's
  const std::vector<RegionPtr>& operands() const { return operands_; }
  int depth() const { return depth_; }  // a leaf's is 0

  bool contains(const dvec2& p) const;
  const ProfileBounds& bounds() const { return bounds_; }
  RegionPtr transformed(const Affine2& map) const;
  // Leaves in depth-first order (the order a sweep numbers them in).
  void forEachLeaf(const std::function<void(const Profile&)>& f) const;

 private:
  Op op_ = Op::Leaf;
  Profile profile_;
  std::vector<RegionPtr> operands_;
  ProfileBounds bounds_;
  int depth_ = 0;
};

}  // namespace csgray::detail
