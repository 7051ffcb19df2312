#include "scene/camera.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <stdexcept>

#include "scene/value_checks.h"

namespace csgray::detail {

Camera::Camera(const CameraSpec& spec, int width, int height)
    : eye_(spec.eye), width_(width), height_(height), orthographic_(spec.orthographic) {
  forward_ = glm::normalize(spec.lookAt - spec.eye);
  right_ = glm::normalize(glm::cross(forward_, spec.up));
  up_ = glm::cross(right_, forward_);
  double screenWidth = orthographic_
                           ? spec.orthoWidth
                           : 2.0 * std::tan(0.5 * spec.fovDegrees * std::numbers::pi / 180.0);
  pixel_ = screenWidth / width;
}

Ray Camera::ray(double x, double y) const {
  double u = (x - 0.5 * width_) * pixel_;
  double v = (0.5 * height_ - y) * pixel_;
  if (orthographic_) return Ray(eye_ + u * right_ + v * up_, forward_);
  return Ray(eye_, glm::normalize(forward_ + u * right_ + v * up_));
}

CameraSpec checkedCamera(CameraSpec c, std::optional<double> width) {
  checkFinite("camera", "eye", c.eye);
  checkFinite("camera", "look_at", c.lookAt);
  checkFinite("camera", "up", c.up);
  if (width && !c.orthographic)
    throw std::invalid_argument("camera: width is for projection=\"orthographic\"; use fov");
  if (width && !(*width > 0.0 && std::isfinite(*width)))
    throw std::invalid_argument("camera: width must be > 0");
  c.orthoWidth = width.value_or(0.0);  // 0: fit the scene
  if (!(c.fovDegrees > 0.0 && c.fovDegrees < 180.0))
    throw std::invalid_argument("camera: fov must be between 0 and 180 degrees");
  const dvec3 view = c.lookAt - c.eye;
  if (view == dvec3(0.0)) throw std::invalid_argument("camera: eye and look_at are the same point");
  // The view's length in doubles: its square neither overflows (points
  // 1e154 apart) nor underflows (1e-154 apart).
  const double squared = glm::dot(view, view);
  if (!std::isfinite(squared))
    throw std::invalid_argument("camera: eye and look_at are too far apart");
  if (!(squared > 1e-300))
    throw std::invalid_argument("camera: eye and look_at are too close together");
  if (c.up == dvec3(0.0))
    throw std::invalid_argument("camera: up must not be parallel to the view direction");
  // An up of 1e308s (or 1e-308s) scaled by its largest entry, so that its
  // length does not overflow (or underflow); another keeps its bits.
  if (const double u = glm::dot(c.up, c.up); !(std::isfinite(u) && u > 1e-300))
    c.up /= std::max({std::abs(c.up.x), std::abs(c.up.y), std::abs(c.up.z)});
  if (glm::length(glm::cross(view, c.up)) <= 1e-12 * glm::length(view) * glm::length(c.up))
    throw std::invalid_argument("camera: up must not be parallel to the view direction");
  return c;
}

}  // namespace csgray::detail
