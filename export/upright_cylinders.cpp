#include "export/upright_cylinders.h"

#include <algorithm>
#include <cmath>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <optional>

namespace csgray::detail {

namespace {

// The coordinate axis a column lies on (its one non-zero entry), or -1.
int axisOf(const glm::dvec4& column) {
  int axis = -1;
  for (int k = 0; k < 3; ++k) {
    if (column[k] == 0.0) continue;
    if (axis >= 0) return -1;
    axis = k;
  }
  return axis;
}

// The scale of a frame's x and y columns that lie in the plane of axes
// `first` and `second`, where they are a turn (or a mirror) of two equal
// scales: perpendicular and as long as each other, to rounding. A turn's
// sines and cosines give a length that rounding may have taken a unit or
// two in the last place off the scale: one written with few digits (1,
// 2.5) is taken back exactly, so a pin turned about its axis and its
// unturned hole have one radius bit for bit.
std::optional<double> roundScale(const glm::dvec4& x, const glm::dvec4& y, int first, int second) {
  const double lx = std::hypot(x[first], x[second]), ly = std::hypot(y[first], y[second]);
  const double slack = 1e-12 * lx;
  if (lx == 0.0 || std::abs(lx - ly) > slack ||
      std::abs(x[first] * y[first] + x[second] * y[second]) > slack * lx)
    return std::nullopt;
  int exponent = 0;
  const double mantissa = std::frexp(lx, &exponent);
  const double short_ = std::ldexp(std::round(std::ldexp(mantissa, 40)), exponent - 40);
  const double ulp = std::nextafter(lx, INFINITY) - lx;
  return std::abs(short_ - lx) <= 8.0 * ulp ? short_ : lx;
}

}  // namespace

std::shared_ptr<const Cylinder> uprightCylinder(const Cylinder& cylinder, const Affine& frame) {
  const glm::dmat4& m = frame.worldFromObject();
  const int zAxis = axisOf(m[2]), xAxis = axisOf(m[0]), yAxis = axisOf(m[1]);
  if (zAxis < 0) return nullptr;
  const bool down = m[2][zAxis] < 0.0;
  glm::dmat4 upright = m;
  upright[2] = down ? -m[2] : m[2];
  // The other two axes, in their order.
  const int first = zAxis == 0 ? 1 : 0, second = zAxis == 2 ? 1 : 2;
  if (xAxis >= 0 && yAxis >= 0) {
    // Its own x and y along the other two axes in their order: a turn of
    // a quarter about its axis, and a mirror that swaps x and y, map it
    // onto itself too. Their scales stay in the frame, where those of
    // the solids scaled with it are (a part scaled as a whole: a sweep's
    // hole takes its pin's rim as the two are placed).
    const double radial = std::abs(m[0][xAxis]);
    if (std::abs(m[1][yAxis]) != radial) return nullptr;  // an elliptic cylinder
    if (!down && m[0][xAxis] > 0.0 && m[1][yAxis] > 0.0 && xAxis < yAxis) return nullptr;
    upright[0] = upright[1] = glm::dvec4(0.0);
    upright[0][first] = radial;
    upright[1][second] = radial;
  } else if (m[0][zAxis] != 0.0 || m[1][zAxis] != 0.0) {
    return nullptr;  // its rims slanted against its axis
  } else if (const std::optional<double> radial = roundScale(m[0], m[1], first, second)) {
    // Turned about its axis by another angle (a pin turned onto a bolt
    // circle, or about its own axis in a hole of its radius), mirrored
    // or not: a round cylinder is the same solid unturned, and so is cut
    // on the points of its hole, turned by another angle or not at all.
    upright[0] = upright[1] = glm::dvec4(0.0);
    upright[0][first] = *radial;
    upright[1][second] = *radial;
  } else {
    // An elliptic cylinder turned about its axis, which stays: a reversed
    // axis is undone by half a turn about its own x (turned over by
    // rotate(180, 0, 0)), or where the frame mirrors, by reversing the
    // axis alone (mirrored across its base); a mirror otherwise by
    // reversing its own x (mirror(1, 0, 0)).
    const bool mirrored = glm::determinant(glm::dmat3(m)) < 0.0;
    if (!down && !mirrored) return nullptr;
    if (down && !mirrored) upright[1] = -m[1];
    if (!down && mirrored) upright[0] = -m[0];
  }
  // (x, y, z) → (−x, y, z) and (x, −y, z) map a frustum onto itself, and
  // (x, y, h − z) onto the one with its radii swapped, which stands where
  // the top rim was.
  const double h = cylinder.height();
  upright[3] = down ? m * glm::dvec4(0.0, 0.0, h, 1.0) : m[3];
  const Affine placed = Affine::fromMatrix(upright);
  // The rims where they were, bit for bit.
  const dvec3 bottom = frame.pointToWorld(dvec3(0.0)), top = frame.pointToWorld(dvec3(0.0, 0.0, h));
  if (placed.pointToWorld(dvec3(0.0)) != (down ? top : bottom) ||
      placed.pointToWorld(dvec3(0.0, 0.0, h)) != (down ? bottom : top))
    return nullptr;
  const SolidPtr shape =
      down ? cylinder.withRadiiSwapped()->withFrame(placed) : cylinder.withFrame(placed);
  return std::static_pointer_cast<const Cylinder>(shape);
}

}  // namespace csgray::detail
