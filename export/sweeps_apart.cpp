#include "export/sweeps_apart.h"

#include <vector>

#include "engine/boolean.h"
#include "engine/primitive.h"
#include "primitives/profile_sweep.h"
#include "profile/bezier.h"

namespace csgray::detail {

namespace {

// A point on the edge away from its ends: where two loops touch at a
// corner, not there.
dvec2 middleOf(const ProfileEdge& edge) {
  switch (edge.kind) {
    case ProfileEdge::Kind::Segment:
      return 0.5 * (edge.from + edge.to);
    case ProfileEdge::Kind::Arc:
      return edge.arcPoint(0.5 * (edge.angle0 + edge.angle1));
    case ProfileEdge::Kind::Quadratic:
    case ProfileEdge::Kind::Cubic:
      break;
  }
  return bezierPoint(edge, 0.5);
}

// A leaf of several loops (a polygon{} with paths, a letter) as the union
// of each loop at an even depth less the loops directly inside it: the
// even-odd fill of loops that do not cross, whose touching (a hole's
// corner on the outline) is then between regions. Nothing when that is
// not so: loops that cross, where the union differs from the leaf at a
// point of a grid over it.
RegionPtr loopsApart(const RegionPtr& leaf) {
  const std::vector<ProfileLoop>& loops = leaf->profile().loops;
  const std::size_t n = loops.size();
  if (n < 2) return nullptr;
  std::vector<Profile> single(n);
  for (std::size_t i = 0; i < n; ++i) single[i].loops = {loops[i]};
  // inside[i][j]: loop i lies in loop j, by the middle of its first edge.
  std::vector<std::vector<bool>> inside(n, std::vector<bool>(n, false));
  std::vector<int> depth(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      if (i != j && !loops[i].edges.empty() &&
          single[j].contains(middleOf(loops[i].edges.front()))) {
        inside[i][j] = true;
        ++depth[i];
      }
  std::vector<RegionPtr> kept;
  for (std::size_t i = 0; i < n; ++i) {
    if (depth[i] % 2 != 0) continue;
    std::vector<RegionPtr> operands = {Region::leaf(single[i])};
    for (std::size_t c = 0; c < n; ++c)
      if (inside[c][i] && depth[c] == depth[i] + 1) operands.push_back(Region::leaf(single[c]));
    kept.push_back(operands.size() == 1 ? operands[0]
                                        : Region::boolean(Region::Op::Difference, operands));
  }
  RegionPtr made = Region::boolean(Region::Op::Union, kept);
  const ProfileBounds box = leaf->bounds();
  constexpr int kSide = 64;
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x) {
      // Off the grid's lines by odd fractions, so as not to sit on edges
      // that lie on round coordinates.
      const dvec2 p = box.lo + (box.hi - box.lo) * dvec2((x + 0.37) / kSide, (y + 0.61) / kSide);
      if (made->contains(p) != leaf->contains(p)) return nullptr;
    }
  return made;
}

SolidPtr apart(const RegionSweep& sweep, const RegionPtr& region) {
  if (region->op() == Region::Op::Leaf) {
    const RegionPtr loops = loopsApart(region);
    return loops ? apart(sweep, loops) : sweep.sweepOf(region);
  }
  std::vector<SolidPtr> operands;
  for (const RegionPtr& operand : region->operands()) operands.push_back(apart(sweep, operand));
  switch (region->op()) {
    case Region::Op::Union:
      return unionOf(std::move(operands));
    case Region::Op::Intersection:
      return intersectionOf(std::move(operands));
    case Region::Op::Difference:
    case Region::Op::Leaf:
      break;
  }
  return differenceOf(std::move(operands));
}

}  // namespace

SolidPtr sweepsTakenApart(const SolidPtr& part) {
  bool any = false;
  SolidPtr mapped = part->mapPrimitives([&](const Primitive& primitive) -> SolidPtr {
    auto* sweep = dynamic_cast<const RegionSweep*>(&primitive);
    if (sweep == nullptr) return primitive.shared_from_this();
    RegionPtr region = sweep->sweptRegion();
    // A leaf that cannot be taken apart into its loops stays as it is:
    // the last try is made only where something changed.
    if (region->op() == Region::Op::Leaf && !(region = loopsApart(region)))
      return primitive.shared_from_this();
    any = true;
    return apart(*sweep, region);
  });
  return any ? mapped : part;
}

}  // namespace csgray::detail
