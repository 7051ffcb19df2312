#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <stdexcept>

#include "engine/boolean.h"
#include "engine/tight_bounds.h"
#include "scene/modifiers.h"
#include "scene/value_checks.h"

namespace csgray::detail {

Bounds Scene::bounds() const {
  Bounds b;
  for (const SolidPtr& s : objects) b.include(s->bounds());
  for (const SolidPtr& s : ghosts) b.include(s->bounds());
  // An infinite plane is a floor or a wall, not part of what to frame.
  for (const SurfacePtr& s : surfaces)
    if (s->bounds().finite()) b.include(s->bounds());
  return b;
}

Bounds Scene::framedBounds(const std::optional<Bounds>& part) const {
  bool metNothing = false;
  Bounds b = part ? *part : partBounds(&metNothing);
  if (metNothing) b = Bounds();
  for (const SolidPtr& s : ghosts) {
    const Bounds own = tightBounds(*s, &metNothing);
    if (!metNothing) b.include(own);
  }
  for (const SurfacePtr& s : surfaces)
    if (s->bounds().finite()) b.include(s->bounds());
  return b;
}

Bounds Scene::partBounds(bool* metNothing) const {
  // The objects the rays meet; an empty one (a difference of a solid less
  // all of it) has no place in the part's box.
  Bounds met, missed;
  for (const SolidPtr& s : objects) {
    bool none = false;
    const Bounds own = tightBounds(*s, &none);
    (none ? missed : met).include(own);
  }
  if (metNothing) *metNothing = met.empty() && !missed.empty();
  return met.empty() ? missed : met;
}

void Scene::resolveModifiers() {
  ResolvedModifiers resolved = detail::resolveModifiers(objects);
  objects = std::move(resolved.model);
  ghosts.insert(ghosts.end(), resolved.ghosts.begin(), resolved.ghosts.end());
  highlights.insert(highlights.end(), resolved.highlights.begin(), resolved.highlights.end());
}

CameraSpec frameBounds(const Bounds& box, double aspect, double fovDegrees) {
  if (box.empty())
    throw std::invalid_argument(
        "nothing to frame: the part is empty (no ray through its box meets it)");
  if (!box.finite())
    throw std::invalid_argument(
        "cannot frame an unbounded solid: return scene{objects=..., camera=camera{...}}");
  CameraSpec camera;
  camera.lookAt = box.center();
  camera.fovDegrees = fovDegrees;
  // Look from the front, right and above; back off until every corner of
  // the box is inside both view angles: a corner at (x, y) across and z
  // along the view from the centre needs distance D with |x| <= tanH·(D + z)
  // and |y| <= tanV·(D + z).
  dvec3 forward = glm::normalize(dvec3(-0.55, 1.0, -0.75));
  dvec3 right = glm::normalize(glm::cross(forward, camera.up));
  dvec3 up = glm::cross(right, forward);
  double tanH = std::tan(0.5 * fovDegrees * std::numbers::pi / 180.0);
  double tanV = tanH / aspect;
  double distance = 0.5 * glm::length(box.size()) + 1e-9;  // eye outside the box
  for (int i = 0; i < 8; ++i) {
    dvec3 corner(i & 1 ? box.hi.x : box.lo.x, i & 2 ? box.hi.y : box.lo.y,
                 i & 4 ? box.hi.z : box.lo.z);
    dvec3 d = corner - camera.lookAt;
    double x = glm::dot(d, right), y = glm::dot(d, up), z = glm::dot(d, forward);
    distance = std::max({distance, std::abs(x) / tanH - z, std::abs(y) / tanV - z});
  }
  camera.eye = camera.lookAt - 1.08 * distance * forward;
  return camera;
}

Light defaultLight(const CameraSpec& camera) {
  dvec3 view = camera.lookAt - camera.eye;
  dvec3 right = glm::normalize(glm::cross(view, camera.up));
  dvec3 up = glm::normalize(glm::cross(right, view));
  double d = glm::length(view);
  Light light;
  light.position = camera.eye + d * (0.6 * up - 0.4 * right) - 0.2 * view;
  return light;
}

void ObjectTally::add(std::size_t count, const std::string& what) {
  total_ += count;
  if (total_ > Boolean::kMaxPrimitives)
    throw std::invalid_argument(what + ": the scene would have more than " +
                                std::to_string(Boolean::kMaxPrimitives) +
                                " primitives and surfaces (counting each use of a shared part)");
}

void checkBackground(const dvec3& color) { checkColor("scene", "background", color); }

void checkIndirectLight(const IndirectLight& indirect) {
  checkWhole("scene: indirect", "samples", indirect.samples, 0, 4096);
  checkWhole("scene: indirect", "bounces", indirect.bounces, 0, 64);
}

void checkFog(const Fog& fog) {
  checkColor("scene: fog", "color", fog.color);
  checkPositive("scene: fog", "distance", fog.distance);
  checkFinite("scene: fog", "offset", fog.offset);
  checkNonNegative("scene: fog", "altitude", fog.altitude);
}

void checkAmbientOcclusion(const AmbientOcclusion& occlusion) {
  checkWhole("scene: ambient_occlusion", "samples", occlusion.samples, 0, 4096);
  checkNonNegative("scene: ambient_occlusion", "distance", occlusion.distance);
}

int checkedMaxDepth(double depth) { return checkWhole("scene", "max_depth", depth, 0, 64); }

void checkMinWeight(double weight) { checkUnit("scene", "min_weight", weight); }

void checkHasObjects(const Scene& scene) {
  if (scene.objects.empty() && scene.surfaces.empty() && scene.ghosts.empty())
    throw std::invalid_argument("scene: objects is empty");
}

}  // namespace csgray::detail
