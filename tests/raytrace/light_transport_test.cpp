// Indirect light, emission, gloss and ambient occlusion: the truths they
// must hold. The white furnace (a closed diffuse room that glows: every
// point sees E/(1 − albedo)), an error that falls as 1/√samples against a
// converged image, an emitting surface seen as its emission, a mirror's
// reflection blurred by gloss and exact without it, and the ambient term
// dimmed next to a wall.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "raytrace/renderer.h"
#include "script/script.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

Scene sceneOf(const std::string& source) { return runScript(source, "light.lua", {}); }

Image renderOf(const Scene& scene, int width, int height, int samples = 1) {
  RenderOptions options(width, height, 2);
  options.samples = samples;
  return Renderer(scene, options).render();
}

double mean(const Image& image) {
  double sum = 0.0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) sum += image.at(x, y).x;
  return sum / (image.width * image.height);
}

// A hollow ball around the camera, white and diffuse with albedo a, giving
// off E: L = E + a·L, so L = E/(1 − a) everywhere (the lamp outside is
// hidden, and there is no ambient term with indirect light).
std::string furnace(double albedo, double emission, int bounces) {
  return "local room = sphere(10) - sphere(9)\n"
         "return scene{objects={room:material{color={1, 1, 1}, diffuse=" +
         std::to_string(albedo) + ", ambient=0.3, specular=0, emission={" +
         std::to_string(emission) + ", " + std::to_string(emission) + ", " +
         std::to_string(emission) +
         "}}}, camera=camera{eye={0, 0, 0}, look_at={1, 0.3, 0.2}}, "
         "lights={point_light{pos={100, 0, 0}}}, indirect={samples=64, bounces=" +
         std::to_string(bounces) + "}}";
}

TEST(LightTransport, TheWhiteFurnaceGivesEmissionOverOneLessAlbedo) {
  for (double albedo : {0.3, 0.6}) {
    const double expected = 0.1 / (1.0 - albedo);
    // Russian roulette after no sure bounce or after two: unbiased either way.
    for (int bounces : {0, 2}) {
      const double measured = mean(renderOf(sceneOf(furnace(albedo, 0.1, bounces)), 16, 16));
      EXPECT_NEAR(measured, expected, 0.03 * expected) << albedo << " " << bounces;
    }
  }
}

// A room of coloured walls lit by a lamp, seen at 8 × 8: the error of
// the mean over N scattered rays, against 2 048 of them, falls as 1/√N.
TEST(LightTransport, TheErrorFallsAsOneOverTheRootOfTheSamples) {
  auto room = [](int samples) {
    return sceneOf(
        "local walls = box{size={10, 10, 10}, center=true} - box{size={9, 9, 9}, center=true}"
        ":translate(0, -1, 0)\n"
        "return scene{objects={walls:material{color={0.8, 0.7, 0.5}, ambient=0}, "
        "sphere(1.5):translate(1, 1, -3):material{color={0.3, 0.5, 0.9}, ambient=0}}, "
        "camera=camera{eye={0, -5, 0}, look_at={0, 0, 0}, fov=70}, "
        "lights={point_light{pos={0, 0, 3.5}}}, indirect={samples=" +
        std::to_string(samples) + "}}");
  };
  const Image reference = renderOf(room(2048), 8, 8);
  auto error = [&](int samples) {
    const Image image = renderOf(room(samples), 8, 8);
    double sum = 0.0;
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) {
        const dvec3 d = image.at(x, y) - reference.at(x, y);
        sum += glm::dot(d, d);
      }
    return std::sqrt(sum / 64);
  };
  const double e4 = error(4), e64 = error(64);
  // 16 times the samples: a quarter of the error (the reference's own
  // noise, a sixth of e64's, and chance move it a little).
  EXPECT_GT(e4 / e64, 2.8);
  EXPECT_LT(e4 / e64, 5.5);
}

TEST(LightTransport, AnEmittingSurfaceShowsItsEmission) {
  // No diffuse, specular or ambient part: what is seen is the emission.
  const Scene scene = sceneOf(
      "return scene{objects={sphere(1):material{diffuse=0, ambient=0, emission={0.2, 0.5, 0.7}}}, "
      "camera=camera{eye={0, -5, 0}, look_at={0, 0, 0}}, background={0, 0, 0}}");
  const Image image = renderOf(scene, 9, 9);
  test::expectVecNear(image.at(4, 4), dvec3(0.2, 0.5, 0.7), 1e-6);  // images hold floats
  test::expectVecNear(image.at(0, 0), dvec3(0.0), 1e-6);
}

// lights={} names no lights: a ball with no ambient term is black, and
// with ambient 0.3 it is 0.3 of its colour, evenly (no lamp shades it).
// Without the key, the default light beside the camera lights it.
TEST(LightTransport, AnEmptyListOfLightsLeavesOnlyAmbientLight) {
  auto ball = [](const std::string& ambient, const std::string& lights) {
    const Scene scene = sceneOf(
        "return scene{objects={sphere(1):material{color={1, 0.5, 0.25}, ambient=" + ambient +
        "}}, camera=camera{eye={0, -5, 0}, look_at={0, 0, 0}}" + lights + "}");
    return renderOf(scene, 9, 9);
  };
  test::expectVecNear(ball("0", ", lights={}").at(4, 4), dvec3(0.0), 1e-9);
  const Image ambient = ball("0.3", ", lights={}");
  test::expectVecNear(ambient.at(4, 4), dvec3(0.3, 0.15, 0.075), 1e-6);
  test::expectVecNear(ambient.at(3, 5), dvec3(0.3, 0.15, 0.075), 1e-6);
  EXPECT_GT(ball("0", "").at(4, 4).x, 0.1);
}

// A mirror floor under a black and white wall: the reflection of the
// wall's edge is sharp without gloss (the same image as before gloss
// existed), and spreads over more pixels with it.
TEST(LightTransport, GlossBlursTheMirroredImage) {
  auto scene = [](const std::string& gloss) {
    return sceneOf(
        "return scene{objects={box{size={20, 20, 1}}:translate(-10, -10, -1):material{"
        "color={0, 0, 0}, ambient=0, diffuse=0, reflection=1" +
        gloss +
        "}, "
        "box{size={10, 1, 10}}:translate(-10, 5, 0):material{color={1, 1, 1}, ambient=1, "
        "diffuse=0}}, "
        "camera=camera{eye={0, -8, 3}, look_at={0, 5, 0}}, background={0, 0, 0}}");
  };
  const Image sharp = renderOf(scene(""), 64, 48, 16);
  const Image same = renderOf(scene(", gloss=0"), 64, 48, 16);
  const Image blurred = renderOf(scene(", gloss=0.3"), 64, 48, 16);
  int between = 0, betweenBlurred = 0;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x) {
      EXPECT_EQ(sharp.at(x, y), same.at(x, y));
      between += sharp.at(x, y).x > 0.05 && sharp.at(x, y).x < 0.95;
      betweenBlurred += blurred.at(x, y).x > 0.05 && blurred.at(x, y).x < 0.95;
    }
  EXPECT_GT(betweenBlurred, 2 * between);
}

// An ambient-only floor with a wall standing on it: by the wall's foot
// the ambient term is dimmed, far from it not at all.
TEST(LightTransport, AmbientOcclusionDimsWhatIsHidden) {
  const Scene scene = sceneOf(
      "return scene{objects={box{size={20, 20, 1}}:translate(-10, -10, -1):material{ambient=1, "
      "diffuse=0, color={1, 1, 1}}, box{size={20, 1, 5}}:translate(-10, 0, 0):material{ambient=0, "
      "diffuse=0}}, camera=camera{eye={0, -6, 8}, look_at={0, -3, 0}}, background={0, 0, 0}, "
      "ambient_occlusion={samples=64, distance=2}}");
  RenderOptions options(40, 30, 2);
  options.samples = 1;
  Renderer renderer(scene, options);
  // Straight down onto the floor by the wall's foot, and far from it.
  const double near = renderer.trace(Ray(dvec3(0, -0.05, 5), dvec3(0, 0, -1))).x;
  const double far = renderer.trace(Ray(dvec3(0, -8, 5), dvec3(0, 0, -1))).x;
  EXPECT_NEAR(far, 1.0, 1e-12);
  // Half the hemisphere is the wall's side: about half the rays are hidden.
  EXPECT_GT(near, 0.35);
  EXPECT_LT(near, 0.65);
}

TEST(LightTransport, BadValuesAreRefused) {
  EXPECT_EQ(test::scriptError("return sphere(1):material{gloss=2}"),
            "part.lua:1: material: gloss must be in [0, 1]");
  EXPECT_EQ(test::scriptError("return sphere(1):material{emission={-1, 0, 0}}"),
            "part.lua:1: material: emission components must be >= 0");
  EXPECT_NE(test::scriptError("return scene{objects={sphere(1)}, indirect={samples=0}}")
                .find("scene: indirect: samples"),
            std::string::npos);
  EXPECT_NE(
      test::scriptError("return scene{objects={sphere(1)}, indirect={bounce=2}}").find("bounce"),
      std::string::npos);
  EXPECT_NE(test::scriptError("return scene{objects={sphere(1)}, ambient_occlusion={distance=-1}}")
                .find("distance"),
            std::string::npos);
}

}  // namespace
}  // namespace csgray::detail
