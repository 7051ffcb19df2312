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
  if (spec.blurs()) {
    lensRadius_ = 0.5 * spec.aperture;
    focusDistance_ = glm::dot(spec.focalPoint.value_or(spec.lookAt) - spec.eye, forward_);
  }
}

Ray Camera::ray(double x, double y) const {
  double u = (x - 0.5 * width_) * pixel_;
  double v = (0.5 * height_ - y) * pixel_;
  if (orthographic_) return Ray(eye_ + u * right_ + v * up_, forward_);
  return Ray(eye_, glm::normalize(forward_ + u * right_ + v * up_));
}

// A thin lens (Kolb, Mitchell and Hanrahan, "A Realistic Camera Model for
// Computer Graphics", SIGGRAPH '95, §2; Pharr, Jakob and Humphreys,
// Physically Based Rendering, 4th ed., §5.2.3): every ray through the lens
// from the pixel's point meets the pinhole ray on the plane in focus, at
// focusDistance along the view. The lens point (lx, ly) in [−1, 1]² is
// taken onto the disc by Shirley and Chiu's concentric map ("A Low
// Distortion Map Between Disk and Square", Journal of Graphics Tools 2(3),
// 1997), which keeps strata of the square strata of the disc.
Ray Camera::ray(double x, double y, double lx, double ly) const {
  if (lensRadius_ == 0.0) return ray(x, y);
  const double u = (x - 0.5 * width_) * pixel_;
  const double v = (0.5 * height_ - y) * pixel_;
  const dvec3 focused = eye_ + focusDistance_ * (forward_ + u * right_ + v * up_);
  double r = 0.0, phi = 0.0;
  constexpr double kQuarter = 0.25 * std::numbers::pi;
  if (std::abs(lx) > std::abs(ly)) {
    r = lx, phi = kQuarter * (ly / lx);
  } else if (ly != 0.0) {
    r = ly, phi = 2.0 * kQuarter - kQuarter * (lx / ly);
  }
  const dvec3 origin = eye_ + lensRadius_ * r * (std::cos(phi) * right_ + std::sin(phi) * up_);
  return Ray(origin, glm::normalize(focused - origin));
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
  checkNonNegative("camera", "aperture", c.aperture);
  if (c.aperture > 0.0 && c.orthographic)
    throw std::invalid_argument(
        "camera: aperture (focal blur) is for a perspective camera, not an orthographic one");
  checkWhole("camera", "blur_samples", c.blurSamples, 1, 1024);
  if (c.focalPoint) checkFinite("camera", "focal_point", *c.focalPoint);
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
  if (c.focalPoint) {
    // Its distance in doubles (as the look_at's above), and the plane in
    // focus ahead, where the pixels' rays go.
    const dvec3 toFocus = *c.focalPoint - c.eye;
    if (!std::isfinite(glm::dot(toFocus, toFocus)))
      throw std::invalid_argument("camera: focal_point is too far from the eye");
    if (!(glm::dot(toFocus, view) > 0.0))
      throw std::invalid_argument("camera: focal_point must lie in front of the eye");
  }
  return c;
}

}  // namespace csgray::detail
