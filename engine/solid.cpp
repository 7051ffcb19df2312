#include "engine/solid.h"

#include <unordered_set>

#include "engine/boolean.h"
#include "engine/instance.h"
#include "engine/moved_box.h"
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

Bounds Solid::boundsUnder(const Affine& outer) const {
  const Bounds& b = bounds();
  if (b.empty()) return b;
  // An unbounded solid may reach anywhere once moved.
  return b.finite() ? movedBox(b, outer) : Bounds::everything();
}

bool Solid::meetsWindow(const Ray& ray, SpanList& scratch) const {
  spansToFirstBoundary(ray, scratch);
  return scratch.meetsOpenWindow(ray.tMin, ray.tMax);
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

namespace {

// The primitives under solid that are not under a subtree already seen.
std::size_t storedPrimitives(const Solid& solid, std::unordered_set<const Solid*>& seen) {
  if (!seen.insert(&solid).second) return 0;
  if (dynamic_cast<const Primitive*>(&solid)) return 1;
  std::size_t count = 0;
  for (const SolidPtr& child : solid.children()) count += storedPrimitives(*child, seen);
  return count;
}

}  // namespace

TreeStats treeStats(const Solid& solid) {
  std::unordered_set<const Solid*> seen;
  return TreeStats{solid.primitiveCount(), solid.booleanCount(), storedPrimitives(solid, seen)};
}

}  // namespace csgray::detail
