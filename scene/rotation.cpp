#include "scene/rotation.h"

#include <cmath>
#include <numbers>

namespace csgray::detail {

namespace {

// An angle is first taken to (−180°, 180°] (exactly: IEEE's remainder),
// so that one turn written two ways (370° and 10°, −350° and 10°) is one
// matrix bit for bit, and a hole and its pin turned so meet on the same
// points; ±a keep their exact mirror images (cos is even, sin odd).
double radians(double degrees) { return std::remainder(degrees, 360.0) * std::numbers::pi / 180.0; }

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
