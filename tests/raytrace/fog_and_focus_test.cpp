// Fog and focal blur against their formulas: a glowing wall seen through
// fog keeps exp(−d / distance) of its light over a way of length d (not
// counting the way inside glass); behind the plane in focus its edge is
// spread over the circle of confusion that similar triangles give, and
// on that plane it stays sharp.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "primitives/box.h"
#include "raytrace/fog.h"
#include "raytrace/ray_estimate.h"
#include "raytrace/renderer.h"
#include "scene/camera.h"
#include "scene/texture.h"

namespace csgray::detail {
namespace {

constexpr double kPi = std::numbers::pi;

// A material that shows exactly its emission, 1: no colour for lights or
// ambient light to reflect.
MaterialPtr glowing() {
  auto m = std::make_shared<Material>();
  m->color = dvec3(0.0);
  m->ambient = m->diffuse = 0.0;
  m->emission = dvec3(1.0);
  return m;
}

// The box from lo to hi.
SolidPtr boxBetween(const dvec3& lo, const dvec3& hi) {
  return Primitive::create<Box>(hi - lo)->transformed(Affine::translation(lo));
}

// A thin wall square to the view (+y) at distance `depth` from the eye at
// the origin, from x = left to x = 1000.
SolidPtr wall(double depth, double left) {
  return solidWithMaterial(
      boxBetween(dvec3(left, depth, -1000.0), dvec3(1000.0, depth + 1e-3, 1000.0)), glowing());
}

Scene wallScene(double depth, double left) {
  Scene scene;
  scene.objects.push_back(wall(depth, left));
  scene.camera = CameraSpec{dvec3(0.0), dvec3(0, 1, 0), dvec3(0, 0, 1), 60.0};
  scene.defaultLight = false;
  scene.background = dvec3(0.0);
  return scene;
}

TEST(Fog, AWallKeepsTheShareOfItsLightThatTheWayGives) {
  Scene scene = wallScene(12.0, -1000.0);
  scene.fog = Fog{dvec3(0.2, 0.4, 0.6), 15.0};
  const int w = 40, h = 30;
  const Image image = Renderer(scene, {w, h, 1}).render();
  const Camera camera(*scene.camera, w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Ray ray = camera.ray(x + 0.5, y + 0.5);
      const double kept = std::exp(-(12.0 / ray.dir.y) / 15.0);
      const dvec3 expected = scene.fog.color + (dvec3(1.0) - scene.fog.color) * kept;
      const dvec3 seen = image.at(x, y);
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(seen[c], expected[c], 1e-6) << x << ", " << y;
    }
}

// A ray that meets nothing has crossed endless fog: it sees the fog's
// colour, not the background.
TEST(Fog, ARayThatMeetsNothingSeesTheFog) {
  Scene scene = wallScene(12.0, 0.0);  // the right half of the view
  scene.background = dvec3(1.0, 0.0, 0.0);
  scene.fog = Fog{dvec3(0.3, 0.5, 0.7), 4.0};
  const Image image = Renderer(scene, {40, 30, 1}).render();
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 20; ++x) {
      const dvec3 seen = image.at(x, y);
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(seen[c], scene.fog.color[c], 1e-6);
    }
  EXPECT_GT(image.at(30, 15).x, 0.3);  // the wall, dimmed
}

// The fog is in the air: a clear pane 5 thick before the wall (glass that
// passes all light, not bending it) leaves 7 of the 12 units in fog.
TEST(Fog, TheWayInsideGlassIsNotFogged) {
  Scene scene = wallScene(12.0, -1000.0);
  auto glass = std::make_shared<Material>();
  glass->transparency = 1.0;
  scene.objects.push_back(
      solidWithMaterial(boxBetween(dvec3(-1000, 4, -1000), dvec3(1000, 9, 1000)), glass));
  scene.fog = Fog{dvec3(0.0), 10.0};
  const Image image = Renderer(scene, {21, 21, 1}).render();
  // The centre pixel's ray goes straight along +y.
  EXPECT_NEAR(image.at(10, 10).x, std::exp(-7.0 / 10.0), 1e-6);
}

// Ground fog: full density up to z = offset, 1 / (1 + (z − offset) /
// altitude)² above. A level ray at height 3 over an offset of 1 with an
// altitude of 2 crosses fog of density 1/4; a ray straight down from
// height 10 to the floor crosses the integral of the density by height,
// (offset − 0) + altitude·(1 − 1/(1 + (10 − offset)/altitude)); a ray
// straight up into the sky from the floor all of the fog above it,
// offset + altitude; one down into endless fog sees its colour.
TEST(Fog, GroundFogThinsAboveItsOffset) {
  const Fog ground{dvec3(0.25, 0.5, 0.75), 6.0, 1.0, 2.0};
  Scene level = wallScene(12.0, -1000.0);
  level.camera = CameraSpec{dvec3(0, 0, 3), dvec3(0, 1, 3), dvec3(0, 0, 1), 60.0};
  level.fog = ground;
  const Image seen = Renderer(level, {21, 21, 1}).render();
  EXPECT_NEAR(seen.at(10, 10).x, 0.25 + 0.75 * std::exp(-12.0 * 0.25 / 6.0),
              1e-6);  // the image keeps floats

  Scene down;
  down.objects.push_back(
      solidWithMaterial(boxBetween(dvec3(-1000, -1000, -1), dvec3(1000, 1000, 0)), glowing()));
  down.camera = CameraSpec{dvec3(0, 0, 10), dvec3(0), dvec3(0, 1, 0), 60.0};
  down.defaultLight = false;
  down.background = dvec3(0.0);
  down.fog = Fog{dvec3(0.0), 6.0, 2.0, 3.0};
  const double depth = (2.0 + 3.0 * (1.0 - 1.0 / (1.0 + 8.0 / 3.0))) / 6.0;
  EXPECT_NEAR(Renderer(down, {21, 21, 1}).render().at(10, 10).x, std::exp(-depth),
              1e-6);  // the image keeps floats

  Scene up = down;
  up.objects.clear();
  up.objects.push_back(solidWithMaterial(  // something to frame, off to the side
      boxBetween(dvec3(500, 500, 0), dvec3(501, 501, 1)), glowing()));
  up.camera = CameraSpec{dvec3(0, 0, 0), dvec3(0, 0, 1), dvec3(0, 1, 0), 60.0};
  up.fog = Fog{dvec3(1.0), 6.0, 2.0, 3.0};
  EXPECT_NEAR(Renderer(up, {21, 21, 1}).render().at(10, 10).x, 1.0 - std::exp(-5.0 / 6.0),
              1e-6);  // the image keeps floats
  up.camera = CameraSpec{dvec3(0, 0, 0), dvec3(0, 0, -1), dvec3(0, 1, 0), 60.0};
  EXPECT_EQ(Renderer(up, {21, 21, 1}).render().at(10, 10), dvec3(1.0));
  // Level, with a height step of −0 or +0, into endless fog: its colour,
  // not the infinities of dividing by a zero step.
  for (const double dz : {-0.0, 0.0}) {
    EXPECT_EQ(throughFog(up.fog, dvec3(0.5), dvec3(0, 0, 7), dvec3(1, 0, dz), kInfinity),
              dvec3(1.0));
    EXPECT_NEAR(throughFog(up.fog, dvec3(0.0), dvec3(0, 0, 0), dvec3(1, 0, dz), 6.0).x,
                1.0 - std::exp(-1.0), 1e-12);  // 6 units in full fog of distance 6
  }
}

// A texture as the background is seen by direction: a camera looking
// straight up into a sky that goes from black at the horizon (z = 0) to
// white at the zenith (z = 1) sees at each pixel the z of its ray's
// unit direction. A sky also shows through fog as any background does.
TEST(Sky, ARayThatMeetsNothingSeesTheSkyAtItsDirection) {
  Scene scene = wallScene(12.0, 500.0);  // off to the side: only sky in view
  scene.camera = CameraSpec{dvec3(0.0), dvec3(0, 0, 1), dvec3(0, 1, 0), 90.0};
  scene.sky = placedGradient(ColorPair(dvec3(0.0), dvec3(1.0)), dvec3(0.0), dvec3(0, 0, 1), {});
  const int w = 31, h = 21;
  const Image image = Renderer(scene, {w, h, 1}).render();
  const Camera camera(*scene.camera, w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      ASSERT_NEAR(image.at(x, y).x, camera.ray(x + 0.5, y + 0.5).dir.z, 1e-6) << x << ", " << y;
  EXPECT_NEAR(image.at(15, 10).x, 1.0, 1e-6);
}

// The share of a disc of radius r that lies past a line at signed
// distance s from its centre (s > 0: the centre is past it): the
// circular segment's area (Weisstein, "Circular Segment", MathWorld).
double discShare(double s, double r) {
  if (s >= r) return 1.0;
  if (s <= -r) return 0.0;
  return 0.5 + (s * std::sqrt(r * r - s * s) + r * r * std::asin(s / r)) / (kPi * r * r);
}

// A lens of radius R in focus at distance f sees a point at distance z
// through rays that cross the plane z within R·|f − z| / f of the pinhole
// ray (similar triangles), a disc of radius R·|f − z| / (f·z·p) pixels for
// pixels p wide at unit distance. Each pixel of a wall's straight edge
// then shows the share of that disc on the wall's side, and a pixel
// farther from the edge than the disc's radius (and half a pixel, the
// pixel's own spread) shows the wall alone or nothing.
TEST(FocalBlur, AnEdgeBehindTheFocusSpreadsOverTheCircleOfConfusion) {
  const double f = 10.0, z = 20.0, lensRadius = 0.5;
  Scene scene = wallScene(z, 0.0);
  scene.camera->aperture = 2.0 * lensRadius;
  scene.camera->focalPoint = dvec3(0, f, 0);
  scene.camera->blurSamples = 64;
  const int w = 200, h = 20;
  const Image image = Renderer(scene, {w, h, 1}).render();
  const double pixel = 2.0 * std::tan(30.0 * kPi / 180.0) / w;
  const double r = lensRadius * (z - f) / (f * z * pixel);
  ASSERT_NEAR(r, 4.33, 0.01);
  for (int x = 0; x < w; ++x) {
    const double s = x + 0.5 - 0.5 * w;  // the pixel centre's distance past the edge
    double mean = 0.0;
    for (int y = 0; y < h; ++y) {
      const double seen = image.at(x, y).x;
      if (s > r + 0.5) {
        ASSERT_EQ(seen, 1.0) << x;
      }
      if (s < -r - 0.5) {
        ASSERT_EQ(seen, 0.0) << x;
      }
      if (std::abs(s) < 0.5 * r) {
        EXPECT_GT(seen, 0.0) << x;
        EXPECT_LT(seen, 1.0) << x;
      }
      mean += seen / h;
    }
    // The disc's share, spread over the pixel's width as its samples are.
    double expected = 0.0;
    for (int i = 0; i < 8; ++i) expected += discShare(s - 0.5 + (i + 0.5) / 8.0, r) / 8.0;
    EXPECT_NEAR(mean, expected, 0.04) << x;
  }
}

// On the plane in focus the lens changes nothing: the wall's edge is as
// sharp as a pinhole's, one pixel of spread from the pixel's own samples.
TEST(FocalBlur, AnEdgeOnThePlaneInFocusStaysSharp) {
  Scene scene = wallScene(10.0, 0.0);
  scene.camera->aperture = 1.0;
  scene.camera->focalPoint = dvec3(3, 10, 2);  // another point of the wall's plane
  const int w = 200, h = 20;
  RenderOptions options(w, h, 1);
  options.samples = 4;  // fewer than the blur's 16: each pixel takes 16
  const RenderResult result = Renderer(scene, options).renderAll();
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double s = x + 0.5 - 0.5 * w, seen = result.color.at(x, y).x;
      if (s > 1.0) {
        ASSERT_NEAR(seen, 1.0, 1e-12) << x;
      }
      if (s < -1.0) {
        ASSERT_NEAR(seen, 0.0, 1e-12) << x;
      }
    }
  EXPECT_EQ(result.rays.primary, std::uint64_t(16) * w * h);
}

// With --adaptive, every pixel first takes the lens's blur samples and a
// pixel at an edge the rest of --samples after them, its first rays kept:
// the camera rays are 16 a pixel and 64 − 16 more at each refined one,
// within the bound the render checks beforehand.
TEST(FocalBlur, AdaptiveSamplesAtEdgesAddToTheLensSamples) {
  Scene scene = wallScene(20.0, 0.0);
  scene.camera->aperture = 1.0;
  scene.camera->focalPoint = dvec3(0, 10, 0);
  RenderOptions options(60, 20, 1);
  options.samples = 64;
  options.adaptive = true;
  const RenderResult result = Renderer(scene, options).renderAll();
  const std::uint64_t first = std::uint64_t(16) * 60 * 20, more = result.rays.primary - first;
  EXPECT_GT(result.rays.primary, first);
  EXPECT_EQ(more % 48, 0u);
  EXPECT_LT(more / 48, 60u * 20u);  // not every pixel: the wall and the empty side are flat
  EXPECT_LE(double(result.rays.primary), estimateRays(scene, options).cameraRays);
  // Far from the edge every pixel is the wall or nothing, whichever pass.
  EXPECT_EQ(result.color.at(59, 10).x, 1.0f);
  EXPECT_EQ(result.color.at(0, 10).x, 0.0f);
}

}  // namespace
}  // namespace csgray::detail
