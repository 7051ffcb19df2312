// The camera's rays: a thin lens's rays meet the pinhole ray on the plane
// in focus and leave from the lens's disc, by a map that keeps square
// rings on circles; and the checks of what a user gives.
#include "scene/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <random>
#include <stdexcept>
#include <string>

#include "test_support.h"

namespace csgray::detail {
namespace {

CameraSpec lensCamera(double aperture, dvec3 focalPoint) {
  CameraSpec spec{dvec3(1, -8, 2), dvec3(0, 0, 1), dvec3(0, 0, 1), 50.0};
  spec.aperture = aperture;
  spec.focalPoint = focalPoint;
  return checkedCamera(spec, std::nullopt);
}

// Every ray through the lens from one pixel's point crosses the plane in
// focus (through the focal point, square to the view) where the pinhole
// ray does: there the picture is sharp.
TEST(Camera, LensRaysMeetThePinholeRayOnThePlaneInFocus) {
  const CameraSpec spec = lensCamera(0.8, dvec3(3, 4, -1));
  const Camera lens(spec, 320, 240);
  CameraSpec pinholeSpec = spec;
  pinholeSpec.aperture = 0.0;
  const Camera pinhole(pinholeSpec, 320, 240);
  const dvec3 forward = glm::normalize(spec.lookAt - spec.eye);
  const double focus = glm::dot(*spec.focalPoint - spec.eye, forward);
  auto onFocalPlane = [&](const Ray& ray) {
    const double t =
        (focus - glm::dot(ray.origin - spec.eye, forward)) / glm::dot(ray.dir, forward);
    return ray.at(t);
  };
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> px(0.0, 320.0), py(0.0, 240.0), l(-1.0, 1.0);
  for (int i = 0; i < 1000; ++i) {
    const double x = px(rng), y = py(rng);
    const Ray through = lens.ray(x, y, l(rng), l(rng));
    EXPECT_NEAR(glm::length(through.dir), 1.0, 1e-12);
    test::expectVecNear(onFocalPlane(through), onFocalPlane(pinhole.ray(x, y)), 1e-9);
  }
}

// Shirley and Chiu's map takes the square ring max(|lx|, |ly|) = s onto
// the circle of radius s: the lens point lies at s times the lens's
// radius from the eye, in the plane square to the view. So the inner
// square of half the side fills the inner disc of half the radius, a
// quarter of the area for a quarter of the square: strata stay strata.
TEST(Camera, LensPointsFillTheApertureDiscEvenly) {
  const CameraSpec spec = lensCamera(2.0, dvec3(0, 0, 1));
  const Camera camera(spec, 64, 48);
  const dvec3 forward = glm::normalize(spec.lookAt - spec.eye);
  const int n = 40;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double lx = -1.0 + (i + 0.5) * 2.0 / n, ly = -1.0 + (j + 0.5) * 2.0 / n;
      const dvec3 offset = camera.ray(17.5, 30.25, lx, ly).origin - spec.eye;
      EXPECT_NEAR(glm::dot(offset, forward), 0.0, 1e-12);
      EXPECT_NEAR(glm::length(offset), std::max(std::abs(lx), std::abs(ly)), 1e-12);
    }
  // The square's corners and edges land on the rim; its centre on the eye.
  EXPECT_NEAR(glm::length(camera.ray(3, 4, 1, 1).origin - spec.eye), 1.0, 1e-12);
  EXPECT_NEAR(glm::length(camera.ray(3, 4, -1, 0.3).origin - spec.eye), 1.0, 1e-12);
  EXPECT_EQ(camera.ray(3, 4, 0, 0).origin, spec.eye);
}

TEST(Camera, APinholeIgnoresTheLensPoint) {
  const CameraSpec spec{dvec3(1, -8, 2), dvec3(0, 0, 1), dvec3(0, 0, 1), 50.0};
  const Camera camera(spec, 64, 48);
  EXPECT_FALSE(camera.blurs());
  const Ray a = camera.ray(10.5, 20.5), b = camera.ray(10.5, 20.5, 0.9, -0.4);
  EXPECT_EQ(a.origin, b.origin);
  EXPECT_EQ(a.dir, b.dir);
}

std::string refusal(CameraSpec spec, std::optional<double> width = std::nullopt) {
  try {
    checkedCamera(spec, width);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(Camera, LensSettingsAreChecked) {
  CameraSpec spec;
  spec.aperture = -1.0;
  EXPECT_EQ(refusal(spec), "camera: aperture must be >= 0");
  spec.aperture = 0.5;
  spec.orthographic = true;
  EXPECT_EQ(refusal(spec, 10.0),
            "camera: aperture (focal blur) is for a perspective camera, not an orthographic one");
  spec.orthographic = false;
  spec.focalPoint = dvec3(0, -20, 0);  // behind the eye at (0, -10, 0)
  EXPECT_EQ(refusal(spec), "camera: focal_point must lie in front of the eye");
  spec.focalPoint = dvec3(0, -10, 5);  // beside it
  EXPECT_EQ(refusal(spec), "camera: focal_point must lie in front of the eye");
  spec.focalPoint = dvec3(0, 1e200, 0);
  EXPECT_EQ(refusal(spec), "camera: focal_point is too far from the eye");
  spec.focalPoint = dvec3(0, 3, 0);
  EXPECT_EQ(refusal(spec), "");
  spec.blurSamples = 0;
  EXPECT_EQ(refusal(spec), "camera: blur_samples must be a whole number from 1 to 1024");
  spec.blurSamples = 1025;
  EXPECT_EQ(refusal(spec), "camera: blur_samples must be a whole number from 1 to 1024");
}

}  // namespace
}  // namespace csgray::detail
