#include "scene/rotation.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "engine/degrees.h"

namespace csgray::detail {

namespace {

// The cosine and sine of the angle from the unit circle's points at exact
// angles in degrees (engine/degrees.h): one turn written two ways (370°
// and 10°, −350° and 10°) is one matrix bit for bit, and a turn and its
// mirror image (45° and 135°, a and −a) have the same sine and cosine up
// to sign, so that a pin turned to one and mirrored meets a hole turned to
// the other on the same points; 30°, 60° and the quarters are exact.
Affine turn(double degrees, const dvec3& axis) {
  if (!std::isfinite(degrees))
    throw std::invalid_argument("rotation needs a finite angle and a non-zero axis");
  const dvec2 point = unitCircleDegrees(degrees);
  return Affine::rotation(point.x, point.y, axis);
}

}  // namespace

Affine rotationDegrees(const dvec3& degrees) {
  return turn(degrees.x, {1, 0, 0})
      .then(turn(degrees.y, {0, 1, 0}))
      .then(turn(degrees.z, {0, 0, 1}));
}

Affine rotationDegrees(double angle, const dvec3& axis) { return turn(angle, axis); }

}  // namespace csgray::detail
