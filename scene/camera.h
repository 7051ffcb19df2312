// The cameras: a pinhole camera (rays from the eye
// through the centres of square pixels on a screen whose width spans the
// horizontal view angle), and an orthographic camera whose parallel rays
// start on a screen through the eye, orthoWidth wide.
#pragma once

#include <optional>

#include "scene/scene.h"

namespace csgray::detail {

class Camera {
 public:
  Camera(const CameraSpec& spec, int width, int height);

  // Unit-direction ray through image point (x, y), in pixels from the top
  // left corner; pixel (i, j) has its centre at (i + 0.5, j + 0.5).
  Ray ray(double x, double y) const;
  // The ray through image point (x, y) from lens point (lx, ly), each in
  // [−1, 1] across the lens (the square mapped onto its disc): for a
  // camera with an aperture, aimed where the pinhole ray meets the plane in
  // focus; the pinhole ray for one without.
  Ray ray(double x, double y, double lx, double ly) const;
  bool blurs() const { return lensRadius_ > 0.0; }

  const dvec3& eye() const { return eye_; }
  const dvec3& forward() const { return forward_; }

 private:
  dvec3 eye_, forward_, right_, up_;
  double pixel_;  // screen size of one pixel: at unit distance, or in model units if orthographic
  int width_, height_;
  bool orthographic_;
  double lensRadius_ = 0.0, focusDistance_ = 0.0;
};

// The camera as a user gives it (the script's camera{}): its orthoWidth is
// set from width, which only an orthographic camera takes (none: fit the
// scene, orthoWidth 0). Checked as the script checks it ("camera: eye and
// look_at are the same point"); throws std::invalid_argument.
CameraSpec checkedCamera(CameraSpec camera, std::optional<double> width);

}  // namespace csgray::detail
