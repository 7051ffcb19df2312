// Axis-aligned bounding box. An empty box has lo > hi; an unbounded solid
// has infinite bounds on the axes where it extends forever.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>

#include "engine/ray.h"

namespace csgray::detail {

struct Bounds {
  dvec3 lo{kInfinity};
  dvec3 hi{-kInfinity};

  static Bounds everything() { return {dvec3(-kInfinity), dvec3(kInfinity)}; }

  bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
  bool finite() const {
    return !empty() && std::isfinite(lo.x) && std::isfinite(lo.y) && std::isfinite(lo.z) &&
           std::isfinite(hi.x) && std::isfinite(hi.y) && std::isfinite(hi.z);
  }
  // Halves first, so that a box near the largest double has a finite
  // centre (lo + hi overflowed); the same bits as 0.5 · (lo + hi) elsewhere.
  dvec3 center() const { return 0.5 * lo + 0.5 * hi; }
  dvec3 size() const { return hi - lo; }

  void include(const dvec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void include(const Bounds& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  Bounds intersected(const Bounds& b) const { return {glm::max(lo, b.lo), glm::min(hi, b.hi)}; }
  // Closed boxes: boxes that touch overlap.
  bool overlaps(const Bounds& b) const {
    return lo.x <= b.hi.x && b.lo.x <= hi.x && lo.y <= b.hi.y && b.lo.y <= hi.y && lo.z <= b.hi.z &&
           b.lo.z <= hi.z;
  }
  bool contains(const dvec3& p) const {
    return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
  }

  // Slab test (Kay and Kajiya 1986): where the ray enters the box within
  // [t0, t1] (t0 itself if it starts inside), or +inf if it misses. A ray
  // parallel to a slab has 1/dir = ±inf: outside the slab both distances are
  // infinities of one sign and the test fails; on one of its planes 0·inf
  // gives NaN, which the comparisons below ignore, so the ray counts as
  // within that slab. Infinite extents work the same way.
  double entry(const Ray& ray, double t0, double t1) const {
    for (int a = 0; a < 3; ++a) {
      double near = (lo[a] - ray.origin[a]) * ray.invDir[a];
      double far = (hi[a] - ray.origin[a]) * ray.invDir[a];
      if (near > far) std::swap(near, far);
      t0 = near > t0 ? near : t0;
      t1 = far < t1 ? far : t1;
    }
    return t0 <= t1 ? t0 : kInfinity;
  }
  // Does the ray meet the box within [ray.tMin, ray.tMax]?
  bool hitBy(const Ray& ray) const { return entry(ray, ray.tMin, ray.tMax) != kInfinity; }
};

}  // namespace csgray::detail
