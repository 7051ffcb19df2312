#include "modeler/solid.h"

#include "modeler/primitive.h"

namespace csgray {

SolidPtr Solid::transformed(const Affine& worldFromObject) const {
  return mapPrimitives(
      [&](const Primitive& p) { return p.withFrame(p.frame().then(worldFromObject)); });
}

SolidPtr Solid::withDefaultMaterial(const MaterialPtr& material) const {
  return mapPrimitives([&](const Primitive& p) -> SolidPtr {
    if (p.material()) return p.shared_from_this();
    return p.withMaterial(material);
  });
}

TreeStats treeStats(const Solid& solid) {
  TreeStats stats;
  if (solid.children().empty()) {
    stats.primitives = 1;
    return stats;
  }
  stats.booleans = 1;
  for (const SolidPtr& child : solid.children()) {
    TreeStats c = treeStats(*child);
    stats.primitives += c.primitives;
    stats.booleans += c.booleans;
  }
  return stats;
}

}  // namespace csgray
