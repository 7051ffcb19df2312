#include "engine/degrees.h"

#include <cmath>
#include <numbers>

namespace csgray::detail {

namespace {

// (cos, sin) of an angle in [0°, 90°), computed in its lower half and
// mirrored about 45° for the upper one.
dvec2 firstQuadrant(double degrees) {
  if (degrees == 0.0) return {1.0, 0.0};
  if (degrees == 30.0) return {std::sqrt(3.0) / 2.0, 0.5};
  if (degrees == 60.0) return {0.5, std::sqrt(3.0) / 2.0};
  if (degrees == 45.0) return {std::numbers::sqrt2 / 2.0, std::numbers::sqrt2 / 2.0};
  const bool upper = degrees > 45.0;
  const double a = (upper ? 90.0 - degrees : degrees) * std::numbers::pi / 180.0;
  const dvec2 v(std::cos(a), std::sin(a));
  return upper ? dvec2(v.y, v.x) : v;
}

}  // namespace

dvec2 unitCircleDegrees(double degrees) {
  double d = std::fmod(degrees, 360.0);
  if (d < 0.0) d += 360.0;
  if (d >= 360.0) d = 0.0;  // fmod of a tiny negative angle, plus 360
  const int quadrant = static_cast<int>(d / 90.0);
  const dvec2 v = firstQuadrant(d - 90.0 * quadrant);
  switch (quadrant) {
    case 1:
      return {-v.y, v.x};
    case 2:
      return {-v.x, -v.y};
    case 3:
      return {v.y, -v.x};
  }
  return v;
}

}  // namespace csgray::detail
