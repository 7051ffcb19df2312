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

std::string SourceLine::text() const {
  return known() ? *file + ":" + std::to_string(line) : std::string();
}

TreeStats treeStats(const Solid& solid) {
  return TreeStats{solid.primitiveCount(), solid.booleanCount()};
}

}  // namespace csgray
