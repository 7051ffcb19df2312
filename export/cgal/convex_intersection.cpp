#include "export/cgal/convex_intersection.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "primitives/box.h"
#include "primitives/convex_polyhedron.h"
#include "primitives/half_space.h"
#include "primitives/linear_extrusion.h"

namespace csgray::detail {

namespace {

// An untwisted extrusion of one convex polygon, scaled alike on both axes
// (a prism or a frustum: a pocket or a key cut by linear_extrude{square}),
// as its planes in object space: the caps, and one side for each edge of
// the polygon, through the edge at the bottom and its scaled copy at the
// top. Nothing for any other extrusion.
std::optional<std::vector<BoundingPlane>> extrusionPlanes(const LinearExtrusion& sweep) {
  const auto loops = sweep.polygonLoops();
  if (!loops || loops->size() != 1 || (*loops)[0].size() < 3) return std::nullopt;
  const std::vector<dvec2>& corners = (*loops)[0];
  const std::size_t n = corners.size();
  // One counterclockwise loop (evaluate's outer loops are) that turns left
  // at every corner is convex.
  dvec2 centroid(0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const dvec2 d0 = corners[(i + 1) % n] - corners[i];
    const dvec2 d1 = corners[(i + 2) % n] - corners[(i + 1) % n];
    if (d0.x * d1.y - d0.y * d1.x < 0.0) return std::nullopt;
    centroid += corners[i] / double(n);
  }
  const double z0 = sweep.bottom(), z1 = z0 + sweep.height(), s = sweep.scale().x;
  const dvec3 inside(centroid * (1.0 + s) / 2.0, (z0 + z1) / 2.0);
  std::vector<BoundingPlane> planes{{dvec3(0.0, 0.0, -1.0), -z0}, {dvec3(0.0, 0.0, 1.0), z1}};
  for (std::size_t i = 0; i < n; ++i) {
    const dvec3 a(corners[i], z0), b(corners[(i + 1) % n], z0), top(s * corners[i], z1);
    dvec3 normal = glm::normalize(glm::cross(b - a, top - a));
    if (!std::isfinite(normal.x)) return std::nullopt;  // an edge of no length
    if (glm::dot(normal, inside - a) > 0.0) normal = -normal;
    planes.push_back({normal, glm::dot(normal, a)});
  }
  return planes;
}

// The object's planes placed by the frame; nothing where the frame is
// singular.
std::optional<std::vector<BoundingPlane>> placedPlanes(const std::vector<BoundingPlane>& object,
                                                       const Affine& frame) {
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

}  // namespace

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
  } else if (auto* sweep = dynamic_cast<const LinearExtrusion*>(&primitive)) {
    std::optional<std::vector<BoundingPlane>> own = extrusionPlanes(*sweep);
    if (!own) return std::nullopt;
    object = std::move(*own);
  } else {
    return std::nullopt;
  }
  return placedPlanes(object, frame);
}

std::optional<std::vector<BoundingPlane>> prismCapPlanes(const Primitive& primitive,
                                                         const Affine& frame) {
  auto* sweep = dynamic_cast<const LinearExtrusion*>(&primitive);
  if (!sweep || !sweep->prism()) return std::nullopt;
  const ProfileBounds& box = sweep->region()->bounds();
  if (box.empty()) return std::nullopt;
  const double z0 = sweep->bottom(), z1 = z0 + sweep->height();
  return placedPlanes({{{0.0, 0.0, -1.0}, -z0},
                       {{0.0, 0.0, 1.0}, z1},
                       {{-1.0, 0.0, 0.0}, -box.lo.x},
                       {{1.0, 0.0, 0.0}, box.hi.x},
                       {{0.0, -1.0, 0.0}, -box.lo.y},
                       {{0.0, 1.0, 0.0}, box.hi.y}},
                      frame);
}

}  // namespace csgray::detail
