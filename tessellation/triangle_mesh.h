// An indexed triangle mesh: what a primitive tessellates itself to, what the
// exporter's booleans work on, and what mesh files are read into.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "engine/bounds.h"

namespace csgray::detail {

struct TriangleMesh {
  using Triangle = std::array<std::uint32_t, 3>;

  std::vector<dvec3> points;
  // Counter-clockwise seen from outside: (b − a) × (c − a) points out.
  std::vector<Triangle> triangles;
  // A sweep of a region that touches itself at a point
  // (profile/pinch_points.h): the solid is pinched along a line there,
  // where the mesh has two points at one place, or faces that cross where
  // polygons of tangent circles meet. The export's booleans refuse it.
  bool pinched = false;

  std::size_t size() const { return triangles.size(); }
  bool empty() const { return triangles.empty(); }

  // Adds other's points and triangles (a disjoint union of shells).
  void append(const TriangleMesh& other);
  // Reverses every triangle, turning the mesh inside out.
  void flip();
  Bounds bounds() const;
  // The signed enclosed volume by the divergence theorem (positive for a
  // closed, outward-oriented mesh).
  double volume() const;
  // The summed triangle areas.
  double area() const;
};

// The distance from p to the nearest point of the triangle abc.
double pointTriangleDistance(const dvec3& p, const dvec3& a, const dvec3& b, const dvec3& c);

}  // namespace csgray::detail
