// Torus::objectTessellate: the torus's mesh, a profile turned about the
// axis (its exact part is torus.cpp).
#include <algorithm>
#include <cmath>
#include <glm/vec2.hpp>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "primitives/torus.h"
#include "tessellation/tessellation.h"

namespace csgray::detail {

// The meridian circle of the tube, centre (R, 0) and radius r in the
// (ρ, z) half-plane, counter-clockwise from v = −v0 to v0, turned about the
// axis. For a ring torus (R > r) it is the whole circle (v0 = π, a closed
// profile). For R < r (the spindle, and the ball at R = 0) the surface is
// the part of the circle at ρ >= 0, cos v >= −R/r, which ends on the axis
// at the dimples z = ±√(r² − R²): poles of the mesh.
//
// The turn about the axis is a cylinder's of radius R + r (circlePolygon),
// so that a torus that rounds the edge of a cylinder of its outer radius
// has its outer equator on the cylinder's rim, point for point, and its
// lower half inside the cylinder: the two meet along the rim's edges
// instead of crossing in slivers all round it. By revolveProfile's bound a
// point of the mesh is within the tube's sagitta plus that polygon's error
// of the surface; the tube gets what the polygon leaves, at least a tenth
// of the tolerance.
TriangleMesh Torus::objectTessellate(double tolerance, const Bounds&) const {
  requireTolerance(kind(), tolerance);
  if (R_ == r_) {
    throw std::invalid_argument(
        "torus: a horn torus (R = r) cannot be tessellated: its surface pinches to a point at "
        "the centre, which no closed 2-manifold mesh can have; make R a little larger or "
        "smaller than r");
  }
  const bool ring = R_ > r_;
  const double v0 = ring ? std::numbers::pi : std::acos(-R_ / r_);
  const CirclePolygon circle = circlePolygon(R_ + r_, tolerance);
  const int segments = circle.segments;
  // At least as many chords per angle as the 8 of a full circle.
  int minChords = std::max(4, int(std::ceil(8.0 * v0 / std::numbers::pi)));
  int chords = arcSegments(r_, 2.0 * v0, tolerance - circle.error, minChords);
  requireTriangleBudget(kind(), revolvedTriangles(chords, segments), tolerance);
  std::vector<glm::dvec2> profile;
  profile.reserve(std::size_t(chords) + 1);
  auto at = [&](double v) { return glm::dvec2(R_ + r_ * std::cos(v), r_ * std::sin(v)); };
  if (ring) {
    for (int k = 0; k < chords; ++k) profile.push_back(at(2.0 * std::numbers::pi * k / chords));
    return revolveProfile(profile, segments, true, &circle);
  }
  const double dimple = std::sqrt(r_ * r_ - R_ * R_);
  profile.emplace_back(0.0, -dimple);
  for (int k = 1; k < chords; ++k) profile.push_back(at(-v0 + 2.0 * v0 * k / chords));
  profile.emplace_back(0.0, dimple);
  return revolveProfile(profile, segments, false, &circle);
}

}  // namespace csgray::detail
