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
  RegionPtr region;
  double bottom = 0.0, top = 0.0;
};

std::optional<Prism> prismOf(const Solid& solid) {
  if (auto* box = dynamic_cast<const Box*>(&solid)) {
    const dvec3 size = box->size();
    return Prism{box, rectangleRegion("box", size.x, size.y, false), 0.0, size.z};
  }
  if (auto* prism = dynamic_cast<const LinearExtrusion*>(&solid); prism && prism->prism())
    return Prism{prism, prism->region(), prism->bottom(), prism->bottom() + prism->height()};
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
  // and whether two operands of a boolean in it lie within the slab, so
  // that their faces on its planes meet face on face.
  struct Flat {
    RegionPtr region;
    bool exact = false;
    bool faceOnFace = false;
  };

  std::optional<Flat> flatOf(const Solid& solid) const {
    if (const Boolean* node = solid.asBoolean()) return booleanFlat(*node);
    const std::optional<Prism> prism = prismOf(solid);
    if (!prism) return std::nullopt;
    const MaterialPtr &ma = first_.primitive->material(), &mb = prism->primitive->material();
    if (ma != mb && !(ma && mb && *ma == *mb)) return std::nullopt;
    // The prism's frame seen from the first's: x and y to the plane, z
    // along the axis.
    const glm::dmat4 m =
        first_.primitive->frame().objectFromWorld() * prism->primitive->frame().worldFromObject();
    const double size = std::max({1.0, std::abs(m[3].x), std::abs(m[3].y), std::abs(m[3].z),
                                  std::abs(first_.bottom), std::abs(first_.top)});
    if (!(std::abs(m[0].z) <= kHair && std::abs(m[1].z) <= kHair && std::abs(m[2].x) <= kHair &&
          std::abs(m[2].y) <= kHair && m[2].z != 0.0))
      return std::nullopt;
    const double a = m[3].z + m[2].z * prism->bottom, b = m[3].z + m[2].z * prism->top;
    const double lo = std::min(a, b), hi = std::max(a, b), hair = kHair * size;
    if (!(lo <= first_.bottom + hair && hi >= first_.top - hair)) return std::nullopt;
    const bool exact = lo >= first_.bottom - hair && hi <= first_.top + hair;
    const Affine2 toPlane{dmat2(m[0].x, m[0].y, m[1].x, m[1].y), dvec2(m[3].x, m[3].y)};
    const bool moved = toPlane.linear != dmat2(1.0) || toPlane.offset != dvec2(0.0);
    return Flat{moved ? prism->region->transformed(toPlane) : prism->region, exact};
  }

 private:
  std::optional<Flat> booleanFlat(const Boolean& node) const {
    std::vector<RegionPtr> regions;
    std::vector<bool> exact;
    bool faceOnFace = false;
    for (const SolidPtr& child : node.children()) {
      std::optional<Flat> flat = flatOf(*child);
      if (!flat) return std::nullopt;
      regions.push_back(std::move(flat->region));
      exact.push_back(flat->exact);
      faceOnFace = faceOnFace || flat->faceOnFace;
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
    return Flat{Region::boolean(op, std::move(regions)), within, faceOnFace};
  }

  Prism first_;
};

// The boolean as one prism in the slab of `first`, or nothing.
SolidPtr asOnePrismOn(const Boolean& node, const Prism& first) {
  try {
    const std::optional<Slab::Flat> flat = Slab(first).flatOf(node);
    if (!flat || !flat->exact || !flat->faceOnFace) return nullptr;
    if (touchesItself(evaluate(*flat->region, evaluationTolerance(*flat->region)))) return nullptr;
    const Primitive& at = *first.primitive;
    if (auto* prism = dynamic_cast<const LinearExtrusion*>(&at))
      return prism->sweepOf(flat->region);
    // A box: the extrusion from its bottom face, as it is placed.
    SolidPtr made =
        Primitive::create<LinearExtrusion>(flat->region, first.top, false, 0.0, dvec2(1.0))
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
SolidPtr asOnePrism(const Boolean& node) {
  if (node.children().size() < 2) return nullptr;
  const std::size_t slabs = node.op() == Boolean::Op::Intersection ? node.children().size() : 1;
  for (std::size_t i = 0; i < slabs; ++i)
    if (const std::optional<Prism> first = prismOf(*firstLeaf(*node.children()[i])))
      if (SolidPtr prism = asOnePrismOn(node, *first)) return prism;
  return nullptr;
}

SolidPtr merged(const SolidPtr& solid) {
  const Boolean* node = solid->asBoolean();
  if (node == nullptr) return solid;
  if (SolidPtr prism = asOnePrism(*node)) return prism;
  bool changed = false;
  std::vector<SolidPtr> operands;
  for (const SolidPtr& child : node->children()) {
    operands.push_back(merged(child));
    changed = changed || operands.back() != child;
  }
  return changed ? std::make_shared<Boolean>(node->op(), std::move(operands)) : solid;
}

}  // namespace

SolidPtr prismBooleansMerged(const SolidPtr& part) { return merged(part); }

}  // namespace csgray::detail
