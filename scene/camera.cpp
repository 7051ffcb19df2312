#include "scene/camera.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

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

}  // namespace csgray::detail
