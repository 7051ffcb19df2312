// ConvexPolyhedron::objectTessellate: the polyhedron's mesh (its exact part
// is convex_polyhedron.cpp).
#include <glm/geometric.hpp>
#include <vector>

#include "primitives/convex_polyhedron.h"
#include "tessellation/tessellation.h"

namespace csgray::detail {

// Exact: the faces' polygons from the planes (convexPolytopeMesh). A bounded
// solid is cut from its own box grown a little, whose faces then lie
// outside it; an unbounded one from the region's box grown by a margin.
TriangleMesh ConvexPolyhedron::objectTessellate(double tolerance, const Bounds& region) const {
  requireTolerance(kind(), tolerance);
  Bounds box = box_;
  if (!box_.finite()) {
    requireFiniteRegion(kind(), region);
    if (region.empty()) return {};
    box = regionWithMargin(region, tolerance);
  } else {
    double margin = 0.01 * glm::length(box_.size()) + tolerance;
    box = {box_.lo - dvec3(margin), box_.hi + dvec3(margin)};
  }
  std::vector<BoundingPlane> planes;
  planes.reserve(planes_->size());
  for (const Plane& q : *planes_) planes.push_back({q.normal, q.offset});
  return convexPolytopeMesh(planes, box);
}

}  // namespace csgray::detail
