#include "primitives/box.h"

#include "primitives/check.h"

namespace csgray::detail {

Box::Box(const dvec3& size) : size_(size) {
  requirePositive("box", "size x", size.x);
  requirePositive("box", "size y", size.y);
  requirePositive("box", "size z", size.z);
}

void Box::objectSpans(const Ray& ray, SpanList& out) const {
  // Slab intersection, remembering which face bounds the span at each end.
  double tIn = -kInfinity, tOut = kInfinity;
  int faceIn = 0, faceOut = 0;
  for (int axis = 0; axis < 3; ++axis) {
    double o = ray.origin[axis], d = ray.dir[axis];
    if (d == 0.0) {
      if (o < 0.0 || o > size_[axis]) return;
      continue;
    }
    double tLow = (0.0 - o) / d, tHigh = (size_[axis] - o) / d;
    int fLow = axis * 2, fHigh = axis * 2 + 1;
    if (tLow > tHigh) {
      std::swap(tLow, tHigh);
      std::swap(fLow, fHigh);
    }
    if (tLow > tIn) tIn = tLow, faceIn = fLow;
    if (tHigh < tOut) tOut = tHigh, faceOut = fHigh;
  }
  if (tIn > tOut || tOut < ray.tMin || tIn > ray.tMax) return;
  out.push_back(boundary(tIn, faceIn), boundary(tOut, faceOut));
}

bool Box::objectContains(const dvec3& p) const {
  return p.x >= 0.0 && p.y >= 0.0 && p.z >= 0.0 && p.x <= size_.x && p.y <= size_.y &&
         p.z <= size_.z;
}

dvec3 Box::objectNormal(const dvec3&, int face) const {
  dvec3 n(0.0);
  n[face / 2] = face % 2 ? 1.0 : -1.0;
  return n;
}

Bounds Box::objectBounds() const { return {dvec3(0.0), size_}; }

}  // namespace csgray::detail
