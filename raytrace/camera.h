// The pinhole camera of seed 001, 2.1.1: rays from the eye through the
// centres of square pixels on a screen whose width spans the horizontal
// view angle.
#pragma once

#include "modeler/scene.h"

namespace csgray {

class Camera {
 public:
  Camera(const CameraSpec& spec, int width, int height);

  // Unit-direction ray through image point (x, y), in pixels from the top
  // left corner; pixel (i, j) has its centre at (i + 0.5, j + 0.5).
  Ray ray(double x, double y) const;

  const dvec3& eye() const { return eye_; }

 private:
  dvec3 eye_, forward_, right_, up_;
  double halfWidth_;  // tan(fov / 2): screen half-width at unit distance
  double pixel_;      // screen size of one pixel at unit distance
  int width_, height_;
};

}  // namespace csgray
