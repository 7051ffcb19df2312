#include "engine/moved_box.h"

namespace csgray::detail {

Bounds movedBox(const Bounds& objectBox, const Affine& worldFromObject) {
  Bounds world;
  for (int i = 0; i < 8; ++i) {
    dvec3 corner(i & 1 ? objectBox.hi.x : objectBox.lo.x, i & 2 ? objectBox.hi.y : objectBox.lo.y,
                 i & 4 ? objectBox.hi.z : objectBox.lo.z);
    world.include(worldFromObject.pointToWorld(corner));
  }
  return world;
}

}  // namespace csgray::detail
