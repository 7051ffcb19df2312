#include "engine/moved_box.h"

#include <cmath>

namespace csgray::detail {

Bounds movedBox(const Bounds& objectBox, const glm::dmat4& worldFromObject) {
  Bounds world;
  for (int i = 0; i < 8; ++i) {
    dvec3 corner(i & 1 ? objectBox.hi.x : objectBox.lo.x, i & 2 ? objectBox.hi.y : objectBox.lo.y,
                 i & 4 ? objectBox.hi.z : objectBox.lo.z);
    world.include(dvec3(worldFromObject * glm::dvec4(corner, 1.0)));
  }
  return world;
}

Bounds movedBox(const Bounds& objectBox, const Affine& worldFromObject) {
  return movedBox(objectBox, worldFromObject.worldFromObject());
}

namespace {

// columns: how many columns of the linear part span the shape (3 or 2).
Bounds movedRound(const dvec3& centre, double r, const Affine& worldFromObject, int columns) {
  const glm::dmat4& m = worldFromObject.worldFromObject();  // m[column][row]
  const dvec3 c = worldFromObject.pointToWorld(centre);
  Bounds box;
  for (int i = 0; i < 3; ++i) {
    double row = 0.0;
    for (int j = 0; j < columns; ++j) row += m[j][i] * m[j][i];
    const double reach = r * std::sqrt(row);
    const double pad = 1e-12 * (std::abs(c[i]) + reach);
    box.lo[i] = c[i] - reach - pad;
    box.hi[i] = c[i] + reach + pad;
  }
  return box;
}

}  // namespace

Bounds movedBall(const dvec3& centre, double r, const Affine& worldFromObject) {
  return movedRound(centre, r, worldFromObject, 3);
}

Bounds movedDisc(const dvec3& centre, double r, const Affine& worldFromObject) {
  return movedRound(centre, r, worldFromObject, 2);
}

}  // namespace csgray::detail
