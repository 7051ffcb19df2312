// Cylinder::objectTessellate: the mesh of a cylinder or cone frustum (its
// exact part is cylinder.cpp).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>
#include <vector>

#include "primitives/cylinder.h"
#include "tessellation/polygon_triangulation.h"
#include "tessellation/tessellation.h"

namespace csgray::detail {

namespace {

// The triangles between two rims of n0 (bottom) and n1 (top) points that
// both start at angle 0: a zipper that takes the next point, below or
// above, whose angle comes first, so each triangle spans at most one step
// of either rim. first0/first1 are the rims' first vertices.
void zipSides(std::uint32_t n0, std::uint32_t n1, std::uint32_t first0, std::uint32_t first1,
              std::vector<TriangleMesh::Triangle>& triangles) {
  std::uint32_t i = 0, j = 0;
  while (i < n0 || j < n1) {
    // Is the bottom's next angle 2π(i+1)/n0 at most the top's 2π(j+1)/n1?
    if (j == n1 || (i < n0 && std::uint64_t(i + 1) * n1 <= std::uint64_t(j + 1) * n0)) {
      triangles.push_back({first0 + i % n0, first0 + (i + 1) % n0, first1 + j % n1});
      ++i;
    } else {
      triangles.push_back({first0 + i % n0, first1 + (j + 1) % n1, first1 + j % n1});
      ++j;
    }
  }
}

}  // namespace

// Two rims (one point where a radius is 0, a cone's apex), the side
// between them, and each rim's disc as a cap. A rim is the polygon
// circlePolygon makes for its own radius where that keeps the side within
// the tolerance, so that a frustum standing on another's top rim meets it
// on the same points (a vase of stacked frustums is glued rather than
// corefined); else both rims take the polygon of the larger radius (a
// steep cone, whose rims' steps differ too much for the side between
// them). With one polygon every cross-section of the side is a regular
// n-gon about a circle of radius ρ(z), so the whole error is that of the
// n-gon; the caps and the generators stay exact, and the same step on both
// rims has the same factor, which keeps each side quad planar. With two,
// the side's triangles are sampled on a grid of 45 points each and their
// distance from the cone measured, which must stay within 97 % of the
// tolerance.
//
// A cap is cut as a zig-zag strip, not as a fan about its centre: a fan's
// triangles all meet at the centre, so two cylinders stacked face to face
// put every triangle of one cap against every triangle of the other, and
// CGAL's corefinement of such coplanar fans grows as n⁴ (a shaft on a hub,
// r = 30: 40 s; as strips each triangle meets a few; docs/performance.md).
std::shared_ptr<const Cylinder> Cylinder::withPolygon(const CirclePolygon& polygon) const {
  auto copy = std::make_shared<Cylinder>(*this);
  copy->polygon_ = polygon;
  return copy;
}

std::shared_ptr<const Cylinder> Cylinder::withRadiiSwapped() const {
  auto copy = std::make_shared<Cylinder>(*this);
  std::swap(copy->r1_, copy->r2_);
  copy->slope_ = -slope_;
  copy->polygon_.reset();
  return copy;
}

TriangleMesh Cylinder::objectTessellate(double tolerance, const Bounds&) const {
  requireTolerance(kind(), tolerance);
  if (polygon_ && r1_ == r2_) {
    requireTriangleBudget(kind(), 4.0 * polygon_->segments, tolerance);
    const CirclePolygon both[2] = {*polygon_, *polygon_};
    return rimsAndSides(both, tolerance);
  }
  const CirclePolygon shared = circlePolygon(std::max(r1_, r2_), tolerance);
  requireTriangleBudget(kind(), 4.0 * shared.segments, tolerance);
  if (r1_ > 0.0 && r2_ > 0.0) {
    const CirclePolygon own[2] = {circlePolygon(r1_, tolerance), circlePolygon(r2_, tolerance)};
    if (own[0].segments != own[1].segments) {
      TriangleMesh mesh = rimsAndSides(own, tolerance);
      if (!mesh.empty()) return mesh;
    }
  }
  const CirclePolygon both[2] = {shared, shared};
  return rimsAndSides(both, tolerance);
}

// The mesh on these rim polygons, or an empty one when two different
// polygons leave the side farther than 97 % of the tolerance from the cone.
TriangleMesh Cylinder::rimsAndSides(const CirclePolygon rim[2], double tolerance) const {
  TriangleMesh mesh;
  // Rim k (0 bottom, 1 top): its first vertex; a rim of radius 0 is one.
  std::uint32_t first[2], count[2];
  const double radius[2] = {r1_, r2_}, z[2] = {0.0, height_};
  for (int k = 0; k < 2; ++k) {
    first[k] = std::uint32_t(mesh.points.size());
    count[k] = radius[k] == 0.0 ? 1u : std::uint32_t(rim[k].segments);
    if (radius[k] == 0.0) {
      mesh.points.emplace_back(0.0, 0.0, z[k]);
      continue;
    }
    for (std::uint32_t s = 0; s < count[k]; ++s) {
      const glm::dvec2 p = rim[k].pointAt(radius[k], s);
      mesh.points.emplace_back(p.x, p.y, z[k]);
    }
  }
  if (rim[0].segments == rim[1].segments || count[0] == 1 || count[1] == 1) {
    const std::uint32_t n = std::max(count[0], count[1]);
    auto vertex = [&](int k, std::uint32_t s) {
      return count[k] == 1 ? first[k] : first[k] + s % n;
    };
    // The side: the quad a b c d, a → b along the bottom rim (θ growing),
    // then up; (b − a) × (d − a) points out.
    for (std::uint32_t s = 0; s < n; ++s) {
      const std::uint32_t a = vertex(0, s), b = vertex(0, s + 1);
      const std::uint32_t c = vertex(1, s + 1), d = vertex(1, s);
      if (a != b) mesh.triangles.push_back({a, b, c});
      if (c != d) mesh.triangles.push_back({a, c, d});
    }
  } else {
    zipSides(count[0], count[1], first[0], first[1], mesh.triangles);
    // Distance from the cone: in the meridian half-plane, from the line
    // through (r1, 0) and (r2, h).
    const double run = r2_ - r1_, length = std::hypot(run, height_);
    double worst = 0.0;
    for (const TriangleMesh::Triangle& t : mesh.triangles)
      for (int u = 0; u <= 8; ++u)
        for (int v = 0; u + v <= 8; ++v) {
          const dvec3 p = (double(u) * mesh.points[t[0]] + double(v) * mesh.points[t[1]] +
                           double(8 - u - v) * mesh.points[t[2]]) /
                          8.0;
          const double rho = std::hypot(p.x, p.y);
          worst = std::max(worst, std::abs((rho - r1_) * height_ - run * p.z) / length);
        }
    if (worst > 0.97 * tolerance) return {};
  }
  // The caps: the top counter-clockwise seen from above; the bottom is the
  // same strip reversed, so that a cylinder standing on another's top face
  // meets it triangle for triangle.
  auto addTriangle = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    mesh.triangles.push_back({a, b, c});
  };
  for (int k = 0; k < 2; ++k) {
    if (count[k] == 1) continue;
    std::vector<std::uint32_t> ring(count[k]);
    for (std::uint32_t s = 0; s < count[k]; ++s) ring[s] = first[k] + s;
    const std::size_t before = mesh.triangles.size();
    triangulatePolygon(mesh.points, ring, addTriangle);
    if (k == 0)
      for (std::size_t t = before; t < mesh.triangles.size(); ++t)
        std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
  }
  return mesh;
}

}  // namespace csgray::detail
