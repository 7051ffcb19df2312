#include "export/prism_booleans.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "engine/boolean.h"
#include "primitives/box.h"
#include "primitives/linear_extrusion.h"
#include "profile/pinch_points.h"
#include "profile/region_evaluation.h"
#include "profile/shapes.h"
#include "scene/material.h"

namespace csgray::detail {

namespace {

// How far a prism's frame may stray from the slab's plane and axis,
// relative to the size of the coordinates, and still be taken as on it:
// rounding of frames composed in doubles, far below any step a part has.
constexpr double kHair = 0x1p-40;

// A box or straight linear extrusion: its region, and its extent along
// its own axis (object z).
struct Prism {
  const Primitive* primitive = nullptr;
  double bottom = 0.0, top = 0.0;

  RegionPtr region() const {
    if (auto* box = dynamic_cast<const Box*>(primitive))
      return rectangleRegion("box", box->size().x, box->size().y, false);
    return static_cast<const LinearExtrusion*>(primitive)->region();
  }
};

std::optional<Prism> prismOf(const Solid& solid) {
  if (auto* box = dynamic_cast<const Box*>(&solid)) return Prism{box, 0.0, box->size().z};
  if (auto* prism = dynamic_cast<const LinearExtrusion*>(&solid); prism && prism->prism())
    return Prism{prism, prism->bottom(), prism->bottom() + prism->height()};
  return std::nullopt;
}

const Solid* firstLeaf(const Solid& solid) {
  const Solid* s = &solid;
  while (const Boolean* node = s->asBoolean()) s = node->children().front().get();
  return s;
}

// The slab of the first prism: booleans under it are prisms of it.
class Slab {
 public:
  explicit Slab(const Prism& first) : first_(first) {}

  // What a solid is within the slab: the prism of `region`, and exactly
  // that (it lies within the slab) or only within it (it passes through);
  // whether two operands of a boolean in it lie within the slab, so that
  // their faces on its planes meet face on face; and whether it is a
  // union of prisms within the slab, and nothing else.
  struct Flat {
    RegionPtr region;
    bool exact = false;
    bool faceOnFace = false;
    bool unionOnly = false;
  };

  // flatOf(solid), only for one that lies within the slab (exact).
  std::optional<Flat> exactFlatOf(const Solid& solid) const {
    if (solid.asBoolean() == nullptr) {
      // A prism's place, checked before its region is made.
      const std::optional<Prism> prism = prismOf(solid);
      const std::optional<Placement> at = prism ? placed(*prism) : std::nullopt;
      if (!at || !at->exact) return std::nullopt;
    }
    std::optional<Flat> flat = flatOf(solid);
    return flat && flat->exact ? flat : std::nullopt;
  }

  std::optional<Flat> flatOf(const Solid& solid) const {
    if (const Boolean* node = solid.asBoolean()) return booleanFlat(*node);
    const std::optional<Prism> prism = prismOf(solid);
    if (!prism) return std::nullopt;
    const std::optional<Placement> at = placed(*prism);
    if (!at) return std::nullopt;
    const bool moved = at->toPlane.linear != dmat2(1.0) || at->toPlane.offset != dvec2(0.0);
    const RegionPtr region = prism->region();
    return Flat{moved ? region->transformed(at->toPlane) : region, at->exact, false, at->exact};
  }

 private:
  // Where a prism stands in the slab: its map into the first's profile
  // plane, and whether it lies within the slab (else it passes through).
  struct Placement {
    Affine2 toPlane;
    bool exact = false;
  };

  std::optional<Placement> placed(const Prism& prism) const {
    const MaterialPtr &ma = first_.primitive->material(), &mb = prism.primitive->material();
    if (ma != mb && !(ma && mb && *ma == *mb)) return std::nullopt;
    // The prism's frame seen from the first's: x and y to the plane, z
    // along the axis.
    const glm::dmat4 m =
        first_.primitive->frame().objectFromWorld() * prism.primitive->frame().worldFromObject();
    const double size = std::max({1.0, std::abs(m[3].x), std::abs(m[3].y), std::abs(m[3].z),
                                  std::abs(first_.bottom), std::abs(first_.top)});
    if (!(std::abs(m[0].z) <= kHair && std::abs(m[1].z) <= kHair && std::abs(m[2].x) <= kHair &&
          std::abs(m[2].y) <= kHair && m[2].z != 0.0))
      return std::nullopt;
    const double a = m[3].z + m[2].z * prism.bottom, b = m[3].z + m[2].z * prism.top;
    const double lo = std::min(a, b), hi = std::max(a, b), hair = kHair * size;
    if (!(lo <= first_.bottom + hair && hi >= first_.top - hair)) return std::nullopt;
    const bool exact = lo >= first_.bottom - hair && hi <= first_.top + hair;
    return Placement{Affine2{dmat2(m[0].x, m[0].y, m[1].x, m[1].y), dvec2(m[3].x, m[3].y)}, exact};
  }

  std::optional<Flat> booleanFlat(const Boolean& node) const {
    std::vector<RegionPtr> regions;
    std::vector<bool> exact;
    bool faceOnFace = false, unionOnly = node.op() == Boolean::Op::Union;
    for (const SolidPtr& child : node.children()) {
      std::optional<Flat> flat = flatOf(*child);
      if (!flat) return std::nullopt;
      regions.push_back(std::move(flat->region));
      exact.push_back(flat->exact);
      faceOnFace = faceOnFace || flat->faceOnFace;
      unionOnly = unionOnly && flat->unionOnly;
    }
    faceOnFace = faceOnFace || std::count(exact.begin(), exact.end(), true) > 1;
    // Within the slab: a union if all its operands are, an intersection if
    // one is, a difference if what it cuts from is.
    bool within = exact.front();
    Region::Op op = Region::Op::Difference;
    if (node.op() == Boolean::Op::Union) {
      within = std::all_of(exact.begin(), exact.end(), [](bool e) { return e; });
      op = Region::Op::Union;
    } else if (node.op() == Boolean::Op::Intersection) {
      within = std::any_of(exact.begin(), exact.end(), [](bool e) { return e; });
      op = Region::Op::Intersection;
    }
    return Flat{Region::boolean(op, std::move(regions)), within, faceOnFace, unionOnly};
  }

  Prism first_;
};

// The region, or nothing where it touches itself at a point; for a union
// of prisms alone, with a square `bridge` wide over each such point
// instead, as a union joins solids that share only an edge.
RegionPtr unpinched(const Slab::Flat& flat, double bridge) {
  const std::vector<dvec2> pinches =
      pinchPoints(evaluate(*flat.region, evaluationTolerance(*flat.region)));
  if (pinches.empty()) return flat.region;
  if (!flat.unionOnly || !(bridge > 0.0)) return nullptr;
  std::vector<RegionPtr> bridged{flat.region};
  const RegionPtr square = rectangleRegion("box", bridge, bridge, true);
  for (const dvec2& p : pinches) bridged.push_back(square->transformed(Affine2{dmat2(1.0), p}));
  RegionPtr region = Region::boolean(Region::Op::Union, std::move(bridged));
  if (touchesItself(evaluate(*region, evaluationTolerance(*region)))) return nullptr;
  return region;
}

// The boolean as one prism in the slab of `first`, or nothing.
SolidPtr asOnePrismOn(const Boolean& node, const Prism& first, double bridge) {
  try {
    const std::optional<Slab::Flat> flat = Slab(first).flatOf(node);
    if (!flat || !flat->exact || !flat->faceOnFace) return nullptr;
    const RegionPtr region = unpinched(*flat, bridge);
    if (!region) return nullptr;
    const Primitive& at = *first.primitive;
    if (auto* prism = dynamic_cast<const LinearExtrusion*>(&at)) return prism->sweepOf(region);
    // A box: the extrusion from its bottom face, as it is placed.
    SolidPtr made = Primitive::create<LinearExtrusion>(region, first.top, false, 0.0, dvec2(1.0))
                        ->withFrame(at.frame());
    if (at.material()) made = static_cast<const Primitive&>(*made).withMaterial(at.material());
    made->setOrigin(at.origin());
    return made;
  } catch (const std::invalid_argument&) {  // a region too deep, or one that cannot be swept
    return nullptr;
  }
}

// The boolean as one prism, or nothing: in the slab of its first prism,
// and for an intersection, whose operand within the slab may come later
// (a block as tall as anything clipped to a plate), in that of each
// operand's first.
SolidPtr asOnePrism(const Boolean& node, double bridge) {
  if (node.children().size() < 2) return nullptr;
  const std::size_t slabs = node.op() == Boolean::Op::Intersection ? node.children().size() : 1;
  for (std::size_t i = 0; i < slabs; ++i)
    if (const std::optional<Prism> first = prismOf(*firstLeaf(*node.children()[i])))
      if (SolidPtr prism = asOnePrismOn(node, *first, bridge)) return prism;
  return nullptr;
}

// Does every operand of the union but the set's lie off the set's slab,
// across one of its planes (the plate under a QR code's pixels)? Others
// that reach into the slab (the spheres and cylinders that round a box
// whose middle two boxes share a slab) meet the set in 3D anyway, where
// the booleans of the operands as written fared better. Only for a slab
// whose axis is one of the world's.
bool othersOffSlab(const Prism& first, const std::vector<SolidPtr>& operands,
                   const std::vector<std::size_t>& group) {
  const glm::dmat4& m = first.primitive->frame().worldFromObject();
  int axis = -1;
  for (int k = 0; k < 3; ++k)
    if (m[2][k] != 0.0) axis = axis < 0 ? k : 3;
  if (axis < 0 || axis > 2 || m[0][axis] != 0.0 || m[1][axis] != 0.0) return false;
  const double a = m[3][axis] + m[2][axis] * first.bottom, b = m[3][axis] + m[2][axis] * first.top;
  const double lo = std::min(a, b), hi = std::max(a, b);
  const double hair = kHair * std::max({1.0, std::abs(lo), std::abs(hi)});
  std::vector<bool> member(operands.size(), false);
  for (std::size_t k : group) member[k] = true;
  for (std::size_t k = 0; k < operands.size(); ++k) {
    if (member[k]) continue;
    const Bounds box = operands[k]->bounds();
    if (!(box.hi[axis] <= lo + hair || box.lo[axis] >= hi - hair)) return false;
  }
  return true;
}

// A union's operands with those that lie within one slab (each set, in
// the slab of its first) made one prism, in the place of the first: the
// tiles of a QR code on its base plate, which the script's union lists
// beside the plate, where the others lie off the slab.
std::vector<SolidPtr> unionGrouped(std::vector<SolidPtr> operands, double bridge) {
  // Each operand joins at most one set: made one, it is gone; refused, it
  // stays and starts no other (its slab's set would be refused again).
  std::vector<bool> gone(operands.size(), false), tried(operands.size(), false);
  std::vector<SolidPtr> grouped;
  for (std::size_t i = 0; i < operands.size(); ++i) {
    if (gone[i]) continue;
    std::vector<std::size_t> group{i};
    const std::optional<Prism> first = prismOf(*firstLeaf(*operands[i]));
    if (first && !tried[i]) {
      const Slab slab(*first);
      for (std::size_t j = i + 1; j < operands.size(); ++j)
        if (!gone[j] && !tried[j] && slab.exactFlatOf(*operands[j])) group.push_back(j);
    }
    for (std::size_t k : group) tried[k] = true;
    SolidPtr prism;
    // (The whole union was tried as one already.)
    if (group.size() > 1 && group.size() < operands.size() &&
        othersOffSlab(*first, operands, group)) {
      std::vector<SolidPtr> members;
      for (std::size_t k : group) members.push_back(operands[k]);
      prism =
          asOnePrism(*std::make_shared<Boolean>(Boolean::Op::Union, std::move(members)), bridge);
    }
    if (!prism) {
      grouped.push_back(operands[i]);
      continue;
    }
    for (std::size_t k : group) gone[k] = true;
    grouped.push_back(std::move(prism));
  }
  return grouped;
}

SolidPtr merged(const SolidPtr& solid, double bridge) {
  const Boolean* node = solid->asBoolean();
  if (node == nullptr) return solid;
  if (SolidPtr prism = asOnePrism(*node, bridge)) return prism;
  std::vector<SolidPtr> operands;
  for (const SolidPtr& child : node->children()) operands.push_back(merged(child, bridge));
  if (node->op() == Boolean::Op::Union) operands = unionGrouped(std::move(operands), bridge);
  return node->withOperands(std::move(operands));
}

}  // namespace

SolidPtr prismBooleansMerged(const SolidPtr& part, double bridge) { return merged(part, bridge); }

}  // namespace csgray::detail
