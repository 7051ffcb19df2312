#include "export/upright_cylinders.h"

#include <glm/mat4x4.hpp>

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

}  // namespace

std::optional<Affine> uprightFrame(const Cylinder& cylinder, const Affine& frame) {
  if (cylinder.r1() != cylinder.r2()) return std::nullopt;
  const glm::dmat4& m = frame.worldFromObject();
  const int zAxis = axisOf(m[2]);
  if (zAxis < 0 || m[2][zAxis] > 0.0) return std::nullopt;
  // Half a turn about the object's x axis maps (x, y, z) to (x, −y, h − z),
  // about its y axis to (−x, y, h − z); both map the cylinder onto itself.
  // The one taken keeps a column that points along a positive axis, so
  // that the upright frame is the bore's when the bore's frame is a
  // coordinate frame.
  int kept = -1;
  for (int c = 0; c < 2 && kept < 0; ++c) {
    const int axis = axisOf(m[c]);
    if (axis >= 0 && m[c][axis] > 0.0) kept = c;
  }
  if (kept < 0) return std::nullopt;
  glm::dmat4 upright = m;
  upright[1 - kept] = -m[1 - kept];
  upright[2] = -m[2];
  const double h = cylinder.height();
  upright[3] = m * glm::dvec4(0.0, 0.0, h, 1.0);
  const Affine turned = Affine::fromMatrix(upright);
  // The rims where they were, bit for bit.
  if (turned.pointToWorld(dvec3(0.0, 0.0, h)) != frame.pointToWorld(dvec3(0.0)) ||
      turned.pointToWorld(dvec3(0.0)) != frame.pointToWorld(dvec3(0.0, 0.0, h)))
    return std::nullopt;
  return turned;
}

}  // namespace csgray::detail
