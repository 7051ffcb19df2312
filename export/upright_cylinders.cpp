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

std::shared_ptr<const Cylinder> uprightCylinder(const Cylinder& cylinder, const Affine& frame) {
  const glm::dmat4& m = frame.worldFromObject();
  glm::dmat4 upright = m;
  bool reversed[3] = {false, false, false};
  for (int c = 0; c < 3; ++c) {
    const int axis = axisOf(m[c]);
    if (axis < 0) return nullptr;
    reversed[c] = m[c][axis] < 0.0;
    if (reversed[c]) upright[c] = -m[c];
  }
  if (!reversed[0] && !reversed[1] && !reversed[2]) return nullptr;
  // (x, y, z) → (−x, y, z) and (x, −y, z) map a frustum onto itself, and
  // (x, y, h − z) onto the one with its radii swapped; that moves the
  // origin to the top rim.
  const double h = cylinder.height();
  if (reversed[2]) upright[3] = m * glm::dvec4(0.0, 0.0, h, 1.0);
  const Affine turned = Affine::fromMatrix(upright);
  // The rims where they were, bit for bit.
  const dvec3 bottom = frame.pointToWorld(dvec3(0.0)), top = frame.pointToWorld(dvec3(0.0, 0.0, h));
  if (turned.pointToWorld(dvec3(0.0)) != (reversed[2] ? top : bottom) ||
      turned.pointToWorld(dvec3(0.0, 0.0, h)) != (reversed[2] ? bottom : top))
    return nullptr;
  const SolidPtr placed =
      reversed[2] ? cylinder.withRadiiSwapped()->withFrame(turned) : cylinder.withFrame(turned);
  return std::static_pointer_cast<const Cylinder>(placed);
}

}  // namespace csgray::detail
