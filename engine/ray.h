// A ray (or line) in double precision: points origin + t·dir for t in [tMin, tMax].
// dir need not be unit length: a ray mapped into an object's frame keeps its
// parameter t, which is what lets spans from different frames be merged.
#pragma once

#include <glm/vec3.hpp>
#include <limits>

namespace csgray::detail {

using glm::dvec3;

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Ray {
  dvec3 origin{0.0};
  dvec3 dir{0.0, 0.0, 1.0};
  dvec3 invDir{kInfinity, kInfinity, 1.0};  // 1/dir per axis, for slab tests
  double tMin = 0.0;
  double tMax = kInfinity;

  Ray() = default;
  Ray(const dvec3& o, const dvec3& d, double t0 = 0.0, double t1 = kInfinity)
      : origin(o), dir(d), invDir(1.0 / d.x, 1.0 / d.y, 1.0 / d.z), tMin(t0), tMax(t1) {}

  // A ray without 1/dir (NaN), for the object-space rays of primitives,
  // which need no slab test: three divisions saved per primitive per ray.
  // A box test against it counts every box as hit.
  static Ray withoutInverse(const dvec3& o, const dvec3& d, double t0, double t1) {
    Ray r;
    r.origin = o;
    r.dir = d;
    r.invDir = dvec3(std::numeric_limits<double>::quiet_NaN());
    r.tMin = t0;
    r.tMax = t1;
    return r;
  }

  dvec3 at(double t) const { return origin + t * dir; }
};

}  // namespace csgray::detail
