#include "export/cgal/convex_intersection.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "primitives/box.h"
#include "primitives/convex_polyhedron.h"
#include "primitives/half_space.h"

namespace csgray::detail {

std::optional<std::vector<BoundingPlane>> boundingPlanes(const Primitive& primitive,
                                                         const Affine& frame) {
  std::vector<BoundingPlane> object;
  if (auto* box = dynamic_cast<const Box*>(&primitive)) {
    for (int axis = 0; axis < 3; ++axis) {
      dvec3 n(0.0);
      n[axis] = 1.0;
      object.push_back({n, box->size()[axis]});
      object.push_back({-n, 0.0});
    }
  } else if (auto* half = dynamic_cast<const HalfSpace*>(&primitive)) {
    object.push_back({half->planeNormal(), half->planeOffset()});
  } else if (auto* convex = dynamic_cast<const ConvexPolyhedron*>(&primitive)) {
    for (const ConvexPolyhedron::Plane& plane : convex->planes())
      object.push_back({plane.normal, plane.offset});
  } else {
    return std::nullopt;
  }
  // n·x_o <= d with x_o = A x + b (objectFromWorld): (Aᵀn)·x <= d − n·b.
  const glm::dmat3 a(frame.objectFromWorld());
  const dvec3 b(frame.objectFromWorld()[3]);
  std::vector<BoundingPlane> placed;
  placed.reserve(object.size());
  for (const BoundingPlane& plane : object) {
    const dvec3 normal = glm::transpose(a) * plane.normal;
    const double length = glm::length(normal);
    if (!(length > 0.0) || !std::isfinite(length)) return std::nullopt;
    placed.push_back({normal / length, (plane.offset - glm::dot(plane.normal, b)) / length});
  }
  return placed;
}

}  // namespace csgray::detail
