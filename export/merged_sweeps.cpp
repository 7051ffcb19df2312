#include "export/merged_sweeps.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include "engine/boolean.h"
#include "primitives/linear_extrusion.h"
#include "primitives/revolution.h"
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

// The sweeps that merge with a first one: their regions moved into the
// first's profile plane, and the box of those.
struct Group {
  Sweep first;
  std::vector<RegionPtr> regions;
  ProfileBounds box;

  // Takes the region if its box meets the group's (within a hair):
  // sweeps apart are joined without a boolean anyway.
  bool take(RegionPtr region) {
    const ProfileBounds& b = region->bounds();
    const double hair = kHair * std::max({1.0, std::abs(box.lo.x), std::abs(box.lo.y),
                                          std::abs(box.hi.x), std::abs(box.hi.y)});
    if (b.lo.x > box.hi.x + hair || b.hi.x < box.lo.x - hair || b.lo.y > box.hi.y + hair ||
        b.hi.y < box.lo.y - hair)
      return false;
    box.include(b);
    regions.push_back(std::move(region));
    return true;
  }
};

glm::dmat3 linearPart(const Primitive& p) { return glm::dmat3(p.frame().worldFromObject()); }

// Do the two sweep alike but for their regions?
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

// Does the region's boundary pass through one point twice (two loops,
// or one loop with itself, meeting at a corner or a tangent point)? Its
// sweep is then pinched along a line there (a circle there, turned),
// which the sweeps apart, as solids that touch, are not: such a group is
// left apart.
bool pinched(const Region& region) {
  const ProfileBounds& box = region.bounds();
  const double size = std::max({1.0, box.hi.x - box.lo.x, box.hi.y - box.lo.y});
  std::set<std::pair<double, double>> corners;
  for (const ProfileLoop& loop : evaluate(region, 1e-6 * size).loops)
    for (const ProfileEdge& e : loop.edges)
      if (!corners.emplace(e.to.x, e.to.y).second) return true;
  return false;
}

// The group's sweep of the union of its regions, or nothing where that
// union is pinched or cannot be swept (a turned region that meets the
// axis at a point only).
SolidPtr sweptAsOne(const Group& group) {
  if (group.regions.size() < 2) return nullptr;
  const RegionPtr region = Region::boolean(Region::Op::Union, group.regions);
  if (pinched(*region)) return nullptr;
  try {
    return group.first.sweep->sweepOf(region);
  } catch (const std::invalid_argument&) {
    return nullptr;
  }
}

SolidPtr merged(const SolidPtr& solid) {
  const Boolean* node = solid->asBoolean();
  if (node == nullptr) return solid;
  bool changed = false;
  std::vector<SolidPtr> operands;
  for (const SolidPtr& child : node->children()) {
    operands.push_back(merged(child));
    changed = changed || operands.back() != child;
  }
  if (node->op() == Boolean::Op::Union) {
    // The group each operand joins (its first sweep's among them), or
    // none; a group that merges takes the place of its first sweep.
    constexpr std::size_t kNone = std::size_t(-1);
    std::vector<Group> groups;
    std::vector<std::size_t> groupOf(operands.size(), kNone);
    for (std::size_t i = 0; i < operands.size(); ++i) {
      const Sweep sweep = sweepOf(*operands[i]);
      if (!sweep.primitive) continue;
      for (std::size_t g = 0; g < groups.size() && groupOf[i] == kNone; ++g)
        if (RegionPtr region = inPlaneOf(groups[g].first, sweep);
            region && groups[g].take(std::move(region)))
          groupOf[i] = g;
      if (groupOf[i] != kNone) continue;
      groupOf[i] = groups.size();
      const RegionPtr& region = sweep.sweep->sweptRegion();
      groups.push_back({sweep, {region}, region->bounds()});
    }
    std::vector<SolidPtr> asOne(groups.size());
    for (std::size_t g = 0; g < groups.size(); ++g) asOne[g] = sweptAsOne(groups[g]);
    if (std::any_of(asOne.begin(), asOne.end(), [](const SolidPtr& m) { return m != nullptr; })) {
      std::vector<SolidPtr> kept;
      for (std::size_t i = 0; i < operands.size(); ++i) {
        const std::size_t g = groupOf[i];
        if (g == kNone || !asOne[g])
          kept.push_back(operands[i]);
        else if (operands[i].get() == groups[g].first.primitive)
          kept.push_back(asOne[g]);
      }
      return kept.size() == 1 ? kept[0] : unionOf(std::move(kept));
    }
  }
  return changed ? std::make_shared<Boolean>(node->op(), std::move(operands)) : solid;
}

}  // namespace

SolidPtr sweepsMerged(const SolidPtr& part) { return merged(part); }

}  // namespace csgray::detail
