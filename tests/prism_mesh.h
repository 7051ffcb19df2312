// Prisms over polygons as triangle meshes, for the tests of the steps
// that join or align meshes.
#pragma once

#include <cmath>
#include <cstdint>
#include <glm/vec2.hpp>
#include <numbers>
#include <vector>

#include "tessellation/triangle_mesh.h"

namespace csgray::detail::test {

using glm::dvec2;

// A prism along z over a convex polygon (counter-clockwise), from z0 to z1.
inline TriangleMesh prism(const std::vector<dvec2>& polygon, double z0, double z1) {
  TriangleMesh mesh;
  const auto n = static_cast<std::uint32_t>(polygon.size());
  for (const dvec2& p : polygon) mesh.points.push_back({p.x, p.y, z0});
  for (const dvec2& p : polygon) mesh.points.push_back({p.x, p.y, z1});
  for (std::uint32_t k = 1; k + 1 < n; ++k) {
    mesh.triangles.push_back({0, k + 1, k});
    mesh.triangles.push_back({n, n + k, n + k + 1});
  }
  for (std::uint32_t k = 0; k < n; ++k) {
    const std::uint32_t next = (k + 1) % n;
    mesh.triangles.push_back({k, next, n + next});
    mesh.triangles.push_back({k, n + next, n + k});
  }
  return mesh;
}

// A regular polygon of `sides` about `center`, its corners moved by
// `off` each (alternately along x and y).
inline std::vector<dvec2> polygon(int sides, const dvec2& center, double radius, double off = 0.0) {
  std::vector<dvec2> corners;
  for (int k = 0; k < sides; ++k) {
    const double a = 2.0 * std::numbers::pi * k / sides;
    corners.push_back(center + radius * dvec2(std::cos(a), std::sin(a)) +
                      (k % 2 ? dvec2(0.0, off) : dvec2(off, 0.0)));
  }
  return corners;
}

}  // namespace csgray::detail::test
