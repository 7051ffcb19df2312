#include "engine/solid.h"

#include "engine/boolean.h"
#include "engine/instance.h"
#include "engine/primitive.h"

namespace csgray::detail {

SolidPtr Solid::transformed(const Affine& worldFromObject) const {
  if (auto* instance = dynamic_cast<const Instance*>(this)) {
    auto moved =
        std::make_shared<Instance>(instance->child(), instance->frame().then(worldFromObject));
    moved->setOrigin(origin());
    return moved;
  }
  if (dynamic_cast<const Boolean*>(this)) {
    auto moved = std::make_shared<Instance>(shared_from_this(), worldFromObject);
    moved->setOrigin(origin());
    return moved;
  }
  return mapPrimitives(
      [&](const Primitive& p) { return p.withFrame(p.frame().then(worldFromObject)); });
}

bool Solid::meetsWindow(const Ray& ray, SpanList& scratch) const {
  spansToFirstBoundary(ray, scratch);
  for (const Span& s : scratch)
    if (s.out.t > ray.tMin && s.in.t < ray.tMax) return true;
  return false;
}

SolidPtr Solid::withDefaultMaterial(const MaterialPtr& material) const {
  SharedMap done;
  return mapSharedPrimitives(
      [&](const Primitive& p) -> SolidPtr {
        if (p.material()) return p.shared_from_this();
        return p.withMaterial(material);
      },
      done);
}

std::string SourceLine::text() const {
  if (!known()) return std::string();
  std::string text = *file + ":" + std::to_string(line);
  return via > 0 && via != line ? text + " via line " + std::to_string(via) : text;
}

TreeStats treeStats(const Solid& solid) {
  return TreeStats{solid.primitiveCount(), solid.booleanCount()};
}

}  // namespace csgray::detail
