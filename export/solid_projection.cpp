#include "export/solid_projection.h"

#include <algorithm>
#include <stdexcept>

#include "engine/boolean.h"
#include "engine/instance.h"
#include "engine/primitive.h"
#include "export/cgal/mesh_boolean.h"
#include "profile/mesh_projection.h"
#include "profile/region_evaluation.h"
#include "scene/modifiers.h"

namespace csgray::detail {

namespace {

double largestExtent(const Solid& solid) {
  const Bounds box = solid.bounds();
  if (!box.finite())
    throw std::invalid_argument(
        "the solid is unbounded, or bounded only by half-spaces, whose reach csgray does not "
        "work out; clip it with a box, clip(s, {lo=, hi=}), to project it");
  const dvec3 extent = box.hi - box.lo;
  return std::max({extent.x, extent.y, extent.z});
}

Region::Op regionOp(Boolean::Op op) {
  return op == Boolean::Op::Union          ? Region::Op::Union
         : op == Boolean::Op::Intersection ? Region::Op::Intersection
                                           : Region::Op::Difference;
}

// The section of a tree in the plane moved down and in the plane moved up
// (mesh_projection.h), as trees of regions with the solid's booleans.
struct Sections {
  RegionPtr down, up;
  bool touches = false;  // does a primitive's mesh have a point on z = 0?
};

Sections sections(const Solid& solid, const Bounds& outer, double tolerance) {
  if (const auto* primitive = dynamic_cast<const Primitive*>(&solid)) {
    const Bounds box = solid.bounds().intersected(outer);
    if (box.empty() || box.lo.z > 0.0 || box.hi.z < 0.0) {
      RegionPtr none = Region::leaf({});
      return {none, none, false};
    }
    // An unbounded primitive is meshed within the whole solid's box.
    const TriangleMesh mesh = primitive->tessellate(tolerance, outer);
    return {Region::leaf(meshSection(mesh, PlaneShift::Down)),
            Region::leaf(meshSection(mesh, PlaneShift::Up)), touchesPlane(mesh)};
  }
  const auto* node = dynamic_cast<const Boolean*>(&solid);
  if (!node) throw std::logic_error("a solid of an unknown kind: " + solid.kind());
  std::vector<RegionPtr> down, up;
  bool touches = false;
  for (const SolidPtr& operand : node->children()) {
    Sections s = sections(*operand, outer, tolerance);
    down.push_back(s.down);
    up.push_back(s.up);
    touches = touches || s.touches;
  }
  return {Region::boolean(regionOp(node->op()), std::move(down)),
          Region::boolean(regionOp(node->op()), std::move(up)), touches};
}

// The shadow as a tree of regions: unions stay unions, a primitive is
// cast from its own mesh, and a difference or an intersection is meshed
// whole by the exporter's booleans.
RegionPtr shadow(const SolidPtr& solid, const Solid& model) {
  if (const auto* primitive = dynamic_cast<const Primitive*>(solid.get()))
    return Region::leaf(
        meshShadow(primitive->tessellate(projectionTolerance(model), model.bounds())));
  const auto* node = dynamic_cast<const Boolean*>(solid.get());
  if (node && node->op() == Boolean::Op::Union) {
    std::vector<RegionPtr> operands;
    for (const SolidPtr& operand : node->children()) operands.push_back(shadow(operand, model));
    return Region::boolean(Region::Op::Union, std::move(operands));
  }
  return Region::leaf(meshShadow(meshOfSolid(*solid, shadowBooleanTolerance(model)).mesh));
}

}  // namespace

double projectionTolerance(const Solid& solid) {
  const double size = largestExtent(solid);
  return size > 0.0 ? std::min(1e-4 * size, 1e-3) : 1e-3;
}

double shadowBooleanTolerance(const Solid& solid) { return 10.0 * projectionTolerance(solid); }

Profile solidProjection(const SolidPtr& solid, bool cut) {
  const SolidPtr model = modelOf(solid);
  if (!model) return {};
  if (model->hasInstances()) return solidProjection(flattened(model), cut);
  const double tolerance = projectionTolerance(*model);
  // The regions' edges are segments: the 2D booleans need no tolerance of
  // their own, but evaluate() asks for one.
  if (!cut) return evaluate(*shadow(model, *model), tolerance);
  const Sections s = sections(*model, model->bounds(), tolerance);
  // Where no mesh touches the plane both shifts cut alike; where one does,
  // the closed solid's section is what is in either.
  if (!s.touches) return evaluate(*s.down, tolerance);
  return evaluate(*Region::boolean(Region::Op::Union, {s.down, s.up}), tolerance);
}

}  // namespace csgray::detail
