#include "primitives/sphere.h"

#include <cmath>
#include <glm/geometric.hpp>

#include "engine/moved_box.h"
#include "primitives/check.h"

namespace csgray::detail {

Sphere::Sphere(double radius) : radius_(radius) { requirePositive("sphere", "radius", radius); }

void Sphere::objectSpans(const Ray& ray, SpanList& out) const {
  // |o + t d|² = r². The discriminant is taken from the distance of the
  // line to the centre (Haines et al., "Precision Improvements for
  // Ray/Sphere Intersection", Ray Tracing Gems 2019, ch. 7), which keeps
  // far-away spheres exact where b² - ac cancels.
  const dvec3& o = ray.origin;
  const dvec3& d = ray.dir;
  double a = glm::dot(d, d);
  double b = glm::dot(o, d);  // half the linear coefficient
  double c = glm::dot(o, o) - radius_ * radius_;
  dvec3 closest = o - (b / a) * d;
  double disc = a * (radius_ * radius_ - glm::dot(closest, closest));
  if (disc < 0.0) return;
  double q = -(b + std::copysign(std::sqrt(disc), b));
  double t0 = c / q, t1 = q / a;
  if (q == 0.0) t0 = t1 = 0.0;
  if (t0 > t1) std::swap(t0, t1);
  if (t1 < ray.tMin || t0 > ray.tMax) return;
  out.push_back(boundary(t0), boundary(t1));
}

bool Sphere::objectContains(const dvec3& p) const { return glm::dot(p, p) <= radius_ * radius_; }

dvec3 Sphere::objectNormal(const dvec3& p, int) const { return p; }

Bounds Sphere::objectBounds() const { return {dvec3(-radius_), dvec3(radius_)}; }

Bounds Sphere::objectBoundsUnder(const Affine& worldFromObject) const {
  return movedBall(dvec3(0.0), radius_, worldFromObject)
      .intersected(movedBox(objectBounds(), worldFromObject));
}

}  // namespace csgray::detail
