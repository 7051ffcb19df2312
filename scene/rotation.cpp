#include "scene/rotation.h"

#include <numbers>

namespace csgray::detail {

namespace {

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

}  // namespace

Affine rotationDegrees(const dvec3& degrees) {
  return Affine::rotation(radians(degrees.x), {1, 0, 0})
      .then(Affine::rotation(radians(degrees.y), {0, 1, 0}))
      .then(Affine::rotation(radians(degrees.z), {0, 0, 1}));
}

Affine rotationDegrees(double angle, const dvec3& axis) {
  return Affine::rotation(radians(angle), axis);
}

}  // namespace csgray::detail
