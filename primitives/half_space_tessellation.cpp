// HalfSpace::objectTessellate: the half-space's mesh within a region (its
// exact part is half_space.cpp).
#include <glm/geometric.hpp>
#include <vector>

#include "primitives/half_space.h"
#include "tessellation/tessellation.h"

namespace csgray::detail {

// The region's box, grown by a margin, cut by the plane: exact, and every
// face but the plane's lies outside the region. A region wholly inside the
// half-space gives that box, one wholly outside gives nothing.
TriangleMesh HalfSpace::objectTessellate(double tolerance, const Bounds& region) const {
  requireTolerance(kind(), tolerance);
  requireFiniteRegion(kind(), region);
  if (region.empty()) return {};
  // The plane is left out only if the whole box the mesh is made in lies
  // inside: a plane on the region's side (a part made of half-spaces alone,
  // whose box their planes make) still bounds the mesh, which reaches a
  // little past the region.
  const Bounds box = regionWithMargin(region, tolerance);
  bool anyInside = false, anyOutside = false;
  for (int i = 0; i < 8; ++i) {
    dvec3 corner(i & 1 ? box.hi.x : box.lo.x, i & 2 ? box.hi.y : box.lo.y,
                 i & 4 ? box.hi.z : box.lo.z);
    (glm::dot(normal_, corner) <= offset_ ? anyInside : anyOutside) = true;
  }
  if (!anyInside) return {};
  std::vector<BoundingPlane> planes;
  if (anyOutside) planes.push_back({normal_, offset_});
  return convexPolytopeMesh(planes, box);
}

}  // namespace csgray::detail
