// The renderer checked against geometry, not golden images: silhouette
// sizes from the pinhole model, shadow edges from similar triangles, and
// Lambert's cosine law.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <vector>

#include "primitives/box.h"
#include "primitives/half_space.h"
#include "primitives/sphere.h"
#include "raytrace/renderer.h"

namespace csgray::detail {
namespace {

constexpr double kPi = std::numbers::pi;

Scene sphereScene() {
  Scene scene;
  scene.objects.push_back(Primitive::create<Sphere>(1.0));
  scene.camera = CameraSpec{dvec3(0, -5, 0), dvec3(0), dvec3(0, 0, 1), 30.0};
  scene.background = dvec3(0.0);
  return scene;
}

// A unit sphere 5 away under a 30° horizontal view angle at 400×300: the
// screen is at focal length f = 200 / tan 15° px, the silhouette's cone has
// half-angle asin(1/5), so its radius is f·tan(asin(0.2)) = 152.4 px.
TEST(Render, SphereSilhouetteRadius) {
  Scene scene = sphereScene();
  Image image = Renderer(scene, {400, 300, 0}).render();
  double expected = 200.0 / std::tan(15.0 * kPi / 180.0) * std::tan(std::asin(0.2));
  ASSERT_NEAR(expected, 152.4, 0.05);
  // From the area of the disc...
  int covered = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) covered += image.at(x, y) != dvec3(0.0);
  EXPECT_NEAR(std::sqrt(covered / kPi), expected, 1.0);
  // ... and from its widest row: half the count of covered pixel centres.
  int widest = 0;
  for (int y = 0; y < image.height; ++y) {
    int row = 0;
    for (int x = 0; x < image.width; ++x) row += image.at(x, y) != dvec3(0.0);
    widest = std::max(widest, row);
  }
  EXPECT_NEAR(widest / 2.0, expected, 1.0);
}

TEST(Render, ImageHasRequestedSizeAndThreadCountDoesNotMatter) {
  Scene scene = sphereScene();
  Image one = Renderer(scene, {64, 48, 1}).render();
  Image two = Renderer(scene, {64, 48, 2}).render();
  EXPECT_EQ(one.width, 64);
  EXPECT_EQ(one.height, 48);
  EXPECT_EQ(one.rgb, two.rgb);
}

// Each band of rows is handed over once, when its pixels are final: the
// rows seen then are those of the finished image, whatever the thread
// count, band height (one that is not a multiple of the tiles' 16 rows
// splits tiles between bands) or second, adaptive pass.
TEST(Render, BandsAreHandedOverOnceWithTheirFinalRows) {
  Scene scene = sphereScene();
  for (int threads : {1, 2, 3})
    for (int bandRows : {16, 23, 64})
      for (bool adaptive : {false, true}) {
        RenderOptions options(70, 53, threads);
        options.samples = adaptive ? 4 : 1;
        options.adaptive = adaptive;
        options.bandRows = bandRows;
        std::vector<std::vector<float>> seen((53 + bandRows - 1) / bandRows);
        std::vector<int> calls(seen.size(), 0);
        options.rowsDone = [&](const Image& color, int first, int last) {
          int band = first / bandRows;
          ASSERT_EQ(first, band * bandRows);
          ASSERT_EQ(last, std::min(53, first + bandRows));
          ++calls[band];
          seen[band].assign(color.rgb.begin() + std::size_t(first) * 70 * 3,
                            color.rgb.begin() + std::size_t(last) * 70 * 3);
        };
        Image image = Renderer(scene, options).render();
        std::vector<float> joined;
        for (std::size_t b = 0; b < seen.size(); ++b) {
          EXPECT_EQ(calls[b], 1) << "band " << b;
          joined.insert(joined.end(), seen[b].begin(), seen[b].end());
        }
        EXPECT_TRUE(std::equal(joined.begin(), joined.end(), image.rgb.begin(), image.rgb.end()))
            << threads << " threads, bands of " << bandRows;
      }
}

// A sphere of radius 1 centred 8 below a point light, over a floor 10
// below it: the shadow is the disc of radius 10·tan(asin(1/8)) = 10/√63.
TEST(Render, ShadowEdgeWhereSimilarTrianglesPutIt) {
  Scene scene;
  scene.objects.push_back(
      Primitive::create<Sphere>(1.0)->transformed(Affine::translation({0, 0, 2})));
  scene.objects.push_back(
      Primitive::create<Box>(dvec3(20, 20, 1))->transformed(Affine::translation({-10, -10, -1})));
  scene.lights.push_back(Light{Light::Kind::Point, dvec3(0, 0, 10)});
  scene.camera = CameraSpec{dvec3(0, -12, 8), dvec3(0), dvec3(0, 0, 1), 40.0};
  Renderer renderer(scene, {100, 100, 1});
  double radius = 10.0 / std::sqrt(63.0);
  for (double angle = 0.0; angle < 2 * kPi; angle += 0.3) {
    dvec3 dir(std::cos(angle), std::sin(angle), 0.0);
    EXPECT_EQ(renderer.transmittance((radius - 1e-3) * dir, scene.lights[0].position), dvec3(0.0))
        << angle;
    EXPECT_EQ(renderer.transmittance((radius + 1e-3) * dir, scene.lights[0].position), dvec3(1.0))
        << angle;
  }
  // Seen by the camera: a floor point in the shadow shows only the ambient
  // term, one just outside it the full Lambert term (light straight above).
  Material floor;
  auto colourAt = [&](const dvec3& p) {
    return renderer.trace(Ray(scene.camera->eye, glm::normalize(p - scene.camera->eye)));
  };
  dvec3 shadowed = colourAt((radius - 0.05) * dvec3(0, -1, 0));
  dvec3 lit = colourAt((radius + 0.05) * dvec3(0, -1, 0));
  EXPECT_NEAR(shadowed.x, floor.ambient * floor.color.x, 1e-9);
  double cosine = 10.0 / glm::length(dvec3(0, radius + 0.05, 10.0));
  EXPECT_NEAR(lit.x, (floor.ambient + floor.diffuse * cosine) * floor.color.x, 1e-9);
}

// Lambert's law (docs/theory.md, "Shading"): the brightness of a sphere point lit from a
// far light along +z follows the cosine of the angle between normal and light.
TEST(Render, LambertFollowsCosine) {
  Scene scene;
  scene.objects.push_back(Primitive::create<Sphere>(1.0));
  scene.lights.push_back(Light{Light::Kind::Point, dvec3(0, 0, 1e7)});
  scene.camera = CameraSpec{dvec3(0, -10, 0), dvec3(0), dvec3(0, 0, 1), 30.0};
  Renderer renderer(scene, {10, 10, 1});
  Material m;
  for (double elevation = 0.1; elevation < 1.5; elevation += 0.2) {
    dvec3 p(0.0, -std::cos(elevation), std::sin(elevation));  // on the sphere, facing the camera
    dvec3 c = renderer.trace(Ray(p + dvec3(0, -3, 0), dvec3(0, 1, 0)));
    EXPECT_NEAR(c.y, (m.ambient + m.diffuse * std::sin(elevation)) * m.color.y, 1e-6) << elevation;
  }
}

TEST(Render, DefaultCameraFramesTheSolid) {
  Scene scene;
  scene.objects.push_back(Primitive::create<Box>(dvec3(10, 20, 5)));
  scene.background = dvec3(0.0);
  Renderer renderer(scene, {80, 60, 1});
  Image image = renderer.render();
  // The whole part is in view: the border rows and columns are background,
  // and the centre shows the part.
  for (int x = 0; x < image.width; ++x) {
    EXPECT_EQ(image.at(x, 0), dvec3(0.0));
    EXPECT_EQ(image.at(x, image.height - 1), dvec3(0.0));
  }
  EXPECT_NE(image.at(40, 30), dvec3(0.0));
}

TEST(Render, UnboundedSolidNeedsACamera) {
  Scene scene;
  scene.objects.push_back(Primitive::create<HalfSpace>(dvec3(0, 0, 1), 0.0));
  try {
    Renderer(scene, {10, 10, 1});
    FAIL() << "an unbounded scene without camera was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("unbounded"), std::string::npos) << e.what();
  }
  scene.camera = CameraSpec{dvec3(0, -10, 5), dvec3(0), dvec3(0, 0, 1), 45.0};
  EXPECT_NO_THROW(Renderer(scene, {10, 10, 1}).render());
}

}  // namespace
}  // namespace csgray::detail
