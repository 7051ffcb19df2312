#include "scene/material.h"

#include <cmath>
#include <stdexcept>

#include "engine/instance.h"
#include "engine/primitive.h"
#include "scene/value_checks.h"

namespace csgray::detail {

void checkMaterial(const Material& m) {
  const char* f = "material";
  if (!m.texture) checkColor(f, "color", m.color);
  checkUnit(f, "ambient", m.ambient);
  checkUnit(f, "diffuse", m.diffuse);
  checkUnit(f, "specular", m.specular);
  checkPositive(f, "shininess", m.shininess);
  checkUnit(f, "reflection", m.reflection);
  checkUnit(f, "transparency", m.transparency);
  checkColor(f, "filter", m.filter);
  if (m.filter.x > 1.0 || m.filter.y > 1.0 || m.filter.z > 1.0)
    throw std::invalid_argument("material: filter components must be in [0, 1]");
  if (!(m.filterDistance >= 0.0 && std::isfinite(m.filterDistance)))
    throw std::invalid_argument("material: filter_distance must be a finite number >= 0");
  checkUnit(f, "transmitted_specular", m.transmittedSpecular);
  if (!(m.ior >= 1.0 && m.ior <= 10.0))
    throw std::invalid_argument("material: ior must be from 1 to 10");
  checkUnit(f, "gloss", m.gloss);
  checkColor(f, "emission", m.emission);
  checkFinite(f, "bump_depth", m.bumpDepth);
}

SolidPtr solidWithMaterial(const SolidPtr& solid, const MaterialPtr& material) {
  if (auto* p = dynamic_cast<const Primitive*>(solid.get())) return p->withMaterial(material);
  // A texture (or bumps) lies in the world as it is when given: the uses of
  // a shared part each get their own piece of it, so instances are
  // multiplied out.
  if (material && (material->texture || material->bumps))
    return flattened(solid)->withDefaultMaterial(material);
  return solid->withDefaultMaterial(material);
}

}  // namespace csgray::detail
