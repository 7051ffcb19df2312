#include "primitives/half_space.h"

#include <glm/geometric.hpp>
#include <stdexcept>

#include "primitives/check.h"

namespace csgray::detail {

HalfSpace::HalfSpace(const dvec3& normal, double offset) : offset_(offset) {
  requireFinite("half_space", "offset", offset);
  double len = glm::length(normal);
  if (!(len > 0.0) || !std::isfinite(len))
    throw std::invalid_argument("half_space: normal must be a non-zero finite vector");
  normal_ = normal / len;
  offset_ = offset / len;
}

void HalfSpace::objectSpans(const Ray& ray, SpanList& out) const {
  // Ray-plane (docs/theory.md, "Planar surfaces"): n·(o + t d) = offset.
  double denom = glm::dot(normal_, ray.dir);
  double num = offset_ - glm::dot(normal_, ray.origin);
  Boundary lo{-kInfinity, nullptr, 0, false}, hi{kInfinity, nullptr, 0, false};
  if (denom == 0.0) {
    if (num < 0.0) return;
  } else if (denom > 0.0) {
    hi = boundary(num / denom);
  } else {
    lo = boundary(num / denom);
  }
  if (hi.t < ray.tMin || lo.t > ray.tMax) return;
  out.push_back(lo, hi);
}

bool HalfSpace::objectContains(const dvec3& p) const { return glm::dot(normal_, p) <= offset_; }

dvec3 HalfSpace::objectNormal(const dvec3&, int) const { return normal_; }

Bounds HalfSpace::objectBounds() const {
  // Tight on the axis of an axis-aligned half-space, unbounded otherwise.
  Bounds b = Bounds::everything();
  for (int axis = 0; axis < 3; ++axis) {
    if (std::abs(normal_[axis]) != 1.0) continue;
    if (normal_[axis] > 0.0)
      b.hi[axis] = offset_;
    else
      b.lo[axis] = -offset_;
  }
  return b;
}

}  // namespace csgray::detail
