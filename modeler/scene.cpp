#include "modeler/scene.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <stdexcept>

namespace csgray {

Bounds Scene::bounds() const {
  Bounds b;
  for (const SolidPtr& s : objects) b.include(s->bounds());
  return b;
}

CameraSpec frameBounds(const Bounds& box, double aspect, double fovDegrees) {
  if (box.empty()) throw std::invalid_argument("nothing to frame: the solid is empty");
  if (!box.finite())
    throw std::invalid_argument(
        "cannot frame an unbounded solid: return scene{objects=..., camera=camera{...}}");
  // The bounding sphere must fit in the narrower of the two view angles.
  double radius = std::max(0.5 * glm::length(box.size()), 1e-9);
  double halfH = 0.5 * fovDegrees * std::numbers::pi / 180.0;
  double halfV = std::atan(std::tan(halfH) / aspect);
  double distance = 1.05 * radius / std::sin(std::min(halfH, halfV));
  CameraSpec camera;
  camera.lookAt = box.center();
  camera.eye = camera.lookAt + distance * glm::normalize(dvec3(0.55, -1.0, 0.75));
  camera.fovDegrees = fovDegrees;
  return camera;
}

PointLight defaultLight(const CameraSpec& camera) {
  dvec3 view = camera.lookAt - camera.eye;
  dvec3 right = glm::normalize(glm::cross(view, camera.up));
  dvec3 up = glm::normalize(glm::cross(right, view));
  double d = glm::length(view);
  PointLight light;
  light.position = camera.eye + d * (0.6 * up - 0.4 * right) - 0.2 * view;
  return light;
}

}  // namespace csgray
