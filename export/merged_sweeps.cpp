#include "export/merged_sweeps.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <stdexcept>
#include <utility>
#include <vector>

#include "engine/boolean.h"
#include "primitives/linear_extrusion.h"
#include "primitives/revolution.h"
#include "profile/pinch_points.h"
#include "profile/region_evaluation.h"
#include "scene/material.h"

namespace csgray::detail {

namespace {

// How far off the first sweep's plane (or axis) another's frame may be
// moved, relative to the size of the coordinates, and still be taken as
// in it: rounding of frames composed in doubles (a part turned as a
// whole), far below any step a part has.
constexpr double kHair = 0x1p-40;

// A sweep that may merge: a straight linear extrusion, moved within its
// profile plane (object x, y: the region's x, y), or a rotate_extrude,
// moved along its axis (object z: the region's y).
struct Sweep {
  const Primitive* primitive = nullptr;
  const RegionSweep* sweep = nullptr;
  bool turned = false;
};

Sweep sweepOf(const Solid& solid) {
  if (auto* prism = dynamic_cast<const LinearExtrusion*>(&solid); prism && prism->prism())
    return {prism, prism, false};
  if (auto* turn = dynamic_cast<const Revolution*>(&solid)) return {turn, turn, true};
  return {};
}

// Do two boxes in the plane meet (within a hair)?
bool meet(const ProfileBounds& a, const ProfileBounds& b) {
  const double hair = kHair * std::max({1.0, std::abs(a.lo.x), std::abs(a.lo.y), std::abs(a.hi.x),
                                        std::abs(a.hi.y)});
  return !(b.lo.x > a.hi.x + hair || b.hi.x < a.lo.x - hair || b.lo.y > a.hi.y + hair ||
           b.hi.y < a.lo.y - hair);
}

// The root of i's set in a disjoint-set forest (path halving).
std::size_t rootOf(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

glm::dmat3 linearPart(const Primitive& p) { return glm::dmat3(p.frame().worldFromObject()); }

// Are the two sweeps alike but for their regions?
bool alike(const Sweep& a, const Sweep& b) {
  if (a.turned != b.turned) return false;
  const MaterialPtr &ma = a.primitive->material(), &mb = b.primitive->material();
  if (ma != mb && !(ma && mb && *ma == *mb)) return false;
  if (linearPart(*a.primitive) != linearPart(*b.primitive)) return false;
  if (a.turned)
    return static_cast<const Revolution*>(a.sweep)->angleDegrees() ==
           static_cast<const Revolution*>(b.sweep)->angleDegrees();
  auto *pa = static_cast<const LinearExtrusion*>(a.sweep),
       *pb = static_cast<const LinearExtrusion*>(b.sweep);
  return pa->bottom() == pb->bottom() && pa->height() == pb->height();
}

// b's region moved into a's profile plane, or nothing when b does not
// stand as a does.
RegionPtr inPlaneOf(const Sweep& a, const Sweep& b) {
  if (!alike(a, b)) return nullptr;
  const dvec3 at = dvec3(b.primitive->frame().worldFromObject()[3]);
  const dvec3 from = dvec3(a.primitive->frame().worldFromObject()[3]);
  const dvec3 offset = a.primitive->frame().pointToObject(at);
  const double size = std::max({1.0, glm::abs(at).x, glm::abs(at).y, glm::abs(at).z,
                                glm::abs(from).x, glm::abs(from).y, glm::abs(from).z});
  const double hair = kHair * size;
  // The move within the profile's plane; what is left must be rounding.
  dvec2 move(offset.x, offset.y);
  double off = std::abs(offset.z);
  if (a.turned) {
    move = dvec2(0.0, offset.z);
    off = std::max(std::abs(offset.x), std::abs(offset.y));
  }
  if (!(off <= hair)) return nullptr;
  const RegionPtr& region = b.sweep->sweptRegion();
  if (move == dvec2(0.0)) return region;
  return region->transformed(Affine2{dmat2(1.0), move});
}

// The sweep of the union of the regions, made as `first` is, or nothing
// where that union touches itself at a point (unless evenTouching: its
// sweep would be pinched there, profile/pinch_points.h) or cannot be
// swept (a turned region that meets the axis at a point only).
SolidPtr sweptAsOne(const Sweep& first, std::vector<RegionPtr> regions, bool evenTouching) {
  const RegionPtr region = Region::boolean(Region::Op::Union, std::move(regions));
  if (!evenTouching && touchesItself(evaluate(*region, evaluationTolerance(*region))))
    return nullptr;
  try {
    return first.sweep->sweepOf(region);
  } catch (const std::invalid_argument&) {
    return nullptr;
  }
}

SolidPtr merged(const SolidPtr& solid, bool evenTouching) {
  const Boolean* node = solid->asBoolean();
  if (node == nullptr) return solid;
  std::vector<SolidPtr> operands;
  for (const SolidPtr& child : node->children()) operands.push_back(merged(child, evenTouching));
  if (node->op() == Boolean::Op::Union) {
    // Each sweep's region in the plane of the first sweep it is alike
    // (its class), and the sets of those whose boxes meet, directly or
    // through others (whatever the order the union lists them in).
    const std::size_t n = operands.size();
    std::vector<Sweep> sweeps(n);
    std::vector<RegionPtr> regions(n);
    std::vector<std::size_t> parent(n);
    std::vector<std::size_t> classOf(n);
    for (std::size_t i = 0; i < n; ++i) {
      parent[i] = classOf[i] = i;
      sweeps[i] = sweepOf(*operands[i]);
      if (!sweeps[i].primitive) continue;
      regions[i] = sweeps[i].sweep->sweptRegion();
      for (std::size_t j = 0; j < i; ++j)
        if (regions[j] && classOf[j] == j) {
          if (RegionPtr moved = inPlaneOf(sweeps[j], sweeps[i])) {
            regions[i] = std::move(moved);
            classOf[i] = j;
            break;
          }
        }
    }
    // The pairs whose boxes meet, by a sweep along x over the boxes in
    // order of their left sides (all pairs were n²/2 tests whatever the
    // operands: 5·10¹¹ for the million tetrahedra of a Sierpinski
    // tetrahedron of level 10, none of them a sweep).
    std::vector<std::size_t> order;
    std::vector<ProfileBounds> boxes(n);
    double reach = 0.0;  // the largest hair meet() allows
    for (std::size_t i = 0; i < n; ++i)
      if (regions[i]) {
        order.push_back(i);
        const ProfileBounds& box = boxes[i] = regions[i]->bounds();
        reach = std::max(reach, kHair * std::max({1.0, std::abs(box.lo.x), std::abs(box.lo.y),
                                                  std::abs(box.hi.x), std::abs(box.hi.y)}));
      }
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return std::pair(boxes[a].lo.x, a) < std::pair(boxes[b].lo.x, b);
    });
    for (std::size_t k = 0; k < order.size(); ++k)
      for (std::size_t m = k + 1; m < order.size(); ++m) {
        const std::size_t i = std::max(order[k], order[m]), j = std::min(order[k], order[m]);
        if (boxes[order[m]].lo.x > boxes[order[k]].hi.x + reach) break;
        if (classOf[i] == classOf[j] && meet(boxes[i], boxes[j]))
          parent[rootOf(parent, i)] = rootOf(parent, j);
      }
    // Each set of two or more, swept as one, takes the place of its first.
    std::vector<std::vector<std::size_t>> members(n);
    for (std::size_t i = 0; i < n; ++i)
      if (regions[i]) members[rootOf(parent, i)].push_back(i);
    std::vector<SolidPtr> asOne(n);
    for (std::size_t root = 0; root < n; ++root) {
      if (members[root].size() < 2) continue;
      std::vector<RegionPtr> set;
      for (std::size_t i : members[root]) set.push_back(regions[i]);
      asOne[root] = sweptAsOne(sweeps[classOf[root]], std::move(set), evenTouching);
    }
    if (std::any_of(asOne.begin(), asOne.end(), [](const SolidPtr& m) { return m != nullptr; })) {
      std::vector<SolidPtr> kept;
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t root = regions[i] ? rootOf(parent, i) : i;
        if (!asOne[root])
          kept.push_back(operands[i]);
        else if (members[root].front() == i)
          kept.push_back(asOne[root]);
      }
      return node->withOperands(std::move(kept));
    }
  }
  return node->withOperands(std::move(operands));
}

}  // namespace

SolidPtr sweepsMerged(const SolidPtr& part, bool evenTouching) {
  return merged(part, evenTouching);
}

}  // namespace csgray::detail
