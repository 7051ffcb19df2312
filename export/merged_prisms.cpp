#include "export/merged_prisms.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <set>
#include <utility>
#include <vector>

#include "engine/boolean.h"
#include "primitives/linear_extrusion.h"
#include "profile/region_evaluation.h"
#include "scene/material.h"

namespace csgray::detail {

namespace {

// How far off the first prism's profile plane another's frame may be
// moved, relative to the size of the coordinates, and still be taken as
// in it: rounding of frames composed in doubles (a part turned as a
// whole), far below any step a part has.
constexpr double kHair = 0x1p-40;

// The prisms that merge with a first one: their regions moved into the
// first's profile plane, and the box of those.
struct Group {
  const LinearExtrusion* first;
  std::vector<RegionPtr> regions;
  ProfileBounds box;

  // Takes the region if its box meets the group's (within a hair):
  // prisms apart are joined without a boolean anyway.
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

const LinearExtrusion* prismOf(const Solid& solid) {
  auto* prism = dynamic_cast<const LinearExtrusion*>(&solid);
  return prism != nullptr && prism->prism() ? prism : nullptr;
}

glm::dmat3 linearPart(const Primitive& p) { return glm::dmat3(p.frame().worldFromObject()); }

// b's region moved into a's profile plane, or nothing when b does not
// stand as a does.
RegionPtr inPlaneOf(const LinearExtrusion& a, const LinearExtrusion& b) {
  const bool sameLook = a.material() == b.material() ||
                        (a.material() && b.material() && *a.material() == *b.material());
  if (!sameLook || a.bottom() != b.bottom() || a.height() != b.height() ||
      linearPart(a) != linearPart(b))
    return nullptr;
  const dvec3 at = dvec3(b.frame().worldFromObject()[3]);
  const dvec3 offset = a.frame().pointToObject(at);
  const dvec3 from = dvec3(a.frame().worldFromObject()[3]);
  const double size = std::max({1.0, glm::abs(at).x, glm::abs(at).y, glm::abs(at).z,
                                glm::abs(from).x, glm::abs(from).y, glm::abs(from).z});
  if (!(std::abs(offset.z) <= kHair * size)) return nullptr;
  if (offset.x == 0.0 && offset.y == 0.0) return b.region();
  return b.region()->transformed(Affine2{dmat2(1.0), dvec2(offset.x, offset.y)});
}

// Does the region's boundary pass through one point twice (two loops,
// or one loop with itself, meeting at a corner or a tangent point)? Its
// sweep is then pinched along a line there, which the prisms apart, as
// solids that touch, are not: such a group is left apart.
bool pinched(const Region& region) {
  const ProfileBounds& box = region.bounds();
  const double size = std::max({1.0, box.hi.x - box.lo.x, box.hi.y - box.lo.y});
  std::set<std::pair<double, double>> corners;
  for (const ProfileLoop& loop : evaluate(region, 1e-6 * size).loops)
    for (const ProfileEdge& e : loop.edges)
      if (!corners.emplace(e.to.x, e.to.y).second) return true;
  return false;
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
    // The group each operand joins (its first prism's among them), or
    // none; a group that merges takes the place of its first prism.
    constexpr std::size_t kNone = std::size_t(-1);
    std::vector<Group> groups;
    std::vector<std::size_t> groupOf(operands.size(), kNone);
    for (std::size_t i = 0; i < operands.size(); ++i) {
      const LinearExtrusion* prism = prismOf(*operands[i]);
      if (!prism) continue;
      for (std::size_t g = 0; g < groups.size() && groupOf[i] == kNone; ++g)
        if (RegionPtr region = inPlaneOf(*groups[g].first, *prism);
            region && groups[g].take(std::move(region)))
          groupOf[i] = g;
      if (groupOf[i] != kNone) continue;
      groupOf[i] = groups.size();
      groups.push_back({prism, {prism->region()}, prism->region()->bounds()});
    }
    std::vector<SolidPtr> asOne(groups.size());
    for (std::size_t g = 0; g < groups.size(); ++g)
      if (groups[g].regions.size() > 1) {
        const RegionPtr region = Region::boolean(Region::Op::Union, groups[g].regions);
        if (!pinched(*region)) asOne[g] = groups[g].first->sweepOf(region);
      }
    if (std::any_of(asOne.begin(), asOne.end(), [](const SolidPtr& m) { return m != nullptr; })) {
      std::vector<SolidPtr> kept;
      for (std::size_t i = 0; i < operands.size(); ++i) {
        const std::size_t g = groupOf[i];
        if (g == kNone || !asOne[g])
          kept.push_back(operands[i]);
        else if (operands[i].get() == groups[g].first)
          kept.push_back(asOne[g]);
      }
      return kept.size() == 1 ? kept[0] : unionOf(std::move(kept));
    }
  }
  return changed ? std::make_shared<Boolean>(node->op(), std::move(operands)) : solid;
}

}  // namespace

SolidPtr prismsMerged(const SolidPtr& part) { return merged(part); }

}  // namespace csgray::detail
