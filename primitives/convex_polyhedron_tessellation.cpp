// ConvexPolyhedron::objectTessellate: the polyhedron's mesh (its exact part
// is convex_polyhedron.cpp).
#include <algorithm>
#include <glm/geometric.hpp>
#include <vector>

#include "primitives/convex_polyhedron.h"
#include "tessellation/tessellation.h"

namespace csgray::detail {

namespace {

// Each point of the mesh within `reach` of one of the known vertices takes
// that vertex's place, where no two points would take one vertex's. A
// corner that convexPolytopeMesh finds where three planes meet is off the
// polyhedron's vertex by rounding (an octahedron of radius 10 had its tips
// at ±9.9999999999999982), which puts a tip that stands exactly on a face
// a hair above it: the boxes of the two are then apart, the solids are
// joined without a boolean, and the file's rounding makes them touch.
void snapToVertices(TriangleMesh& mesh, const std::vector<dvec3>& vertices, double reach) {
  std::vector<dvec3> sorted = vertices;
  std::sort(sorted.begin(), sorted.end(), [](const dvec3& a, const dvec3& b) { return a.x < b.x; });
  std::vector<dvec3> snapped = mesh.points;
  std::vector<int> taken(sorted.size(), 0);
  for (dvec3& p : snapped) {
    auto it = std::lower_bound(sorted.begin(), sorted.end(), p.x - reach,
                               [](const dvec3& v, double x) { return v.x < x; });
    std::size_t nearest = sorted.size();
    double best = reach;
    for (; it != sorted.end() && it->x <= p.x + reach; ++it) {
      const double d = glm::length(*it - p);
      if (d <= best) best = d, nearest = std::size_t(it - sorted.begin());
    }
    if (nearest == sorted.size()) continue;
    if (++taken[nearest] > 1) return;
    p = sorted[nearest];
  }
  mesh.points = std::move(snapped);
}

}  // namespace

// Exact: the faces' polygons from the planes (convexPolytopeMesh), their
// corners on the known vertices (a Platonic solid's, a hull's points). A
// bounded solid is cut from its own box grown a little, whose faces then lie
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
  TriangleMesh mesh = convexPolytopeMesh(planes, box);
  if (box_.finite() && !vertices_->empty())
    snapToVertices(mesh, *vertices_, 1e-12 * glm::length(box_.size()));
  return mesh;
}

}  // namespace csgray::detail
