// The look of a bare solid (raytrace/cad_look.h): only a script that
// returns no scene{} gets it; a light, soft background that through-holes
// show; key, fill and rim lights about the camera that shade the faces of
// a box apart; a ground shadow that only darkens; scenes of the script's
// own keep their background and light.
#include "raytrace/cad_look.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "raytrace/ray_estimate.h"
#include "raytrace/renderer.h"
#include "scene/camera.h"
#include "script/script.h"

namespace csgray::detail {
namespace {

Scene sceneOf(const std::string& source) { return runScript(source, "part.lua"); }

double luminance(const dvec3& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

RenderResult renderWithAovs(const Scene& scene, int w, int h) {
  RenderOptions options(w, h, 2);
  options.depthAov = options.normalAov = true;
  return Renderer(scene, options).renderAll();
}

bool missed(const RenderResult& r, int x, int y) { return std::isinf(r.depth.at(x, y).x); }

TEST(CadLook, OnlyForWhatIsNotAScene) {
  EXPECT_TRUE(sceneOf("return box(1)").cadLook);
  EXPECT_TRUE(sceneOf("return disc{r=1}").cadLook);
  EXPECT_TRUE(sceneOf("return square(1)").cadLook);
  EXPECT_FALSE(sceneOf("return scene{objects={box(1)}}").cadLook);
  EXPECT_FALSE(sceneOf("return scene{objects={box(1)}}").edges);
  EXPECT_TRUE(sceneOf("return scene{objects={box(1)}, edges=true}").edges);
}

// The camera frames the part's own box, and the ground lies under it: a
// ball cut flat by a difference stands on the ground at its cut, not at
// the bottom of the whole ball that bounds() gives. An empty difference
// has nothing to frame.
TEST(CadLook, FramesThePartsOwnBox) {
  const Scene cut = sceneOf("return sphere(10) - box(40):translate(-20, -20, -40)");
  EXPECT_EQ(cut.bounds().lo.z, -10.0);
  const Renderer renderer(cut, RenderOptions(64, 48));
  EXPECT_NEAR(renderer.camera().lookAt.z, 5.0, 1e-6);
  EXPECT_NEAR(CadLook(renderer.camera(), 4.0 / 3.0, cut.framedBounds()).groundZ(), 0.0, 1e-6);
  try {
    Renderer(sceneOf("return box(10) - box(10)"), RenderOptions(64, 48));
    ADD_FAILURE() << "an empty part was framed";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "nothing to frame: the part is empty (no ray through its box meets it)");
  }
  // A region of nothing is not an unbounded surface.
  try {
    Renderer(sceneOf("return square(2):offset{r=-3}"), RenderOptions(64, 48));
    ADD_FAILURE() << "an empty region was framed";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "nothing to frame: the region is empty");
  }
  bool metNothing = false;
  sceneOf("return box(10) - box(10)").partBounds(&metNothing);
  EXPECT_TRUE(metNothing);
  // An empty object beside a real one is no part of the box.
  const Bounds both =
      sceneOf("return scene{objects={box(1), box(10) - box(10)}}").partBounds(&metNothing);
  EXPECT_EQ(both.lo, dvec3(0.0));
  EXPECT_EQ(both.hi, dvec3(1.0));
  EXPECT_FALSE(metNothing);
}

TEST(CadLook, KeyFillAndRimAboutTheCamera) {
  Scene scene = sceneOf("return box(10)");
  Renderer renderer(scene, {320, 240, 1});
  const std::vector<Light>& lights = renderer.lights();
  ASSERT_EQ(lights.size(), 3u);
  EXPECT_TRUE(lights[0].castsShadows);
  EXPECT_FALSE(lights[1].castsShadows);
  EXPECT_FALSE(lights[2].castsShadows);
  const CameraSpec& c = renderer.camera();
  const dvec3 forward = glm::normalize(c.lookAt - c.eye);
  const dvec3 right = glm::normalize(glm::cross(forward, c.up));
  const dvec3 up = glm::cross(right, forward);
  const double d = glm::length(c.lookAt - c.eye);
  // Key: above and left of the eye; fill: right of it; rim: behind the part.
  EXPECT_GT(glm::dot(lights[0].position - c.eye, up), 0.0);
  EXPECT_LT(glm::dot(lights[0].position - c.eye, right), 0.0);
  EXPECT_GT(glm::dot(lights[1].position - c.eye, right), 0.0);
  EXPECT_GT(glm::dot(lights[2].position - c.eye, forward), d);
  EXPECT_EQ(estimateRays(scene, {320, 240, 1}).lights, 3u);

  // A scene without lights keeps the one default light.
  Scene own = sceneOf("return scene{objects={box(10)}}");
  EXPECT_EQ(Renderer(own, {320, 240, 1}).lights().size(), 1u);
}

TEST(CadLook, BackgroundIsLightAndSoft) {
  Scene scene = sceneOf("return box(10)");
  RenderResult r = renderWithAovs(scene, 160, 120);
  ASSERT_TRUE(missed(r, 0, 0) && missed(r, 0, 119));
  const double top = luminance(r.color.at(0, 0)), bottom = luminance(r.color.at(0, 119));
  EXPECT_GT(top, 0.5);
  EXPECT_GT(bottom, top);
  // No band: neighbouring rows of the background differ by little.
  for (int y = 1; y < 120; ++y)
    if (missed(r, 0, y) && missed(r, 0, y - 1)) {
      EXPECT_LT(std::abs(luminance(r.color.at(0, y)) - luminance(r.color.at(0, y - 1))), 0.01);
    }
}

// The faces a box turns to the camera (top, front, right) differ in shade.
TEST(CadLook, FacesOfABoxDifferInShade) {
  Scene scene = sceneOf("return box(10)");
  RenderResult r = renderWithAovs(scene, 160, 120);
  const dvec3 normals[3] = {{0, 0, 1}, {0, -1, 0}, {1, 0, 0}};
  double sum[3] = {0, 0, 0};
  int count[3] = {0, 0, 0};
  for (int y = 0; y < 120; ++y)
    for (int x = 0; x < 160; ++x)
      for (int i = 0; i < 3; ++i)
        if (!missed(r, x, y) && glm::length(r.normal.at(x, y) - normals[i]) < 1e-6)
          sum[i] += luminance(r.color.at(x, y)), ++count[i];
  double shade[3];
  for (int i = 0; i < 3; ++i) {
    ASSERT_GT(count[i], 100) << i;
    shade[i] = sum[i] / count[i];
  }
  EXPECT_GT(std::abs(shade[0] - shade[1]), 0.05);
  EXPECT_GT(std::abs(shade[1] - shade[2]), 0.05);
  EXPECT_GT(std::abs(shade[0] - shade[2]), 0.05);
  // The shades docs/script.md gives ("The default look"), averaged over
  // each face: the lights are points, so a face is not quite even.
  EXPECT_NEAR(shade[0], 0.54, 0.02);
  EXPECT_NEAR(shade[1], 0.40, 0.02);
  EXPECT_NEAR(shade[2], 0.30, 0.02);
}

// Through a hole in a plate lying on the ground the view meets nothing
// and shows the background, not a dark void: the ground is lit there.
TEST(CadLook, ThroughHoleShowsTheBackground) {
  Scene scene = sceneOf(
      "return box{size={40, 40, 2}} - cylinder{r=8, h=10, center=true}"
      ":translate(20, 20, 0)");
  const int w = 320, h = 240;
  Renderer renderer(scene, {w, h, 2});
  RenderOptions options(w, h, 2);
  options.depthAov = true;
  RenderResult r = Renderer(scene, options).renderAll();
  // The pixel whose centre ray passes nearest the middle of the hole.
  Camera camera(renderer.camera(), w, h);
  const dvec3 middle(20, 20, 1);
  int bestX = 0, bestY = 0;
  double best = std::numeric_limits<double>::infinity();
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      Ray ray = camera.ray(x + 0.5, y + 0.5);
      double d = glm::length(glm::cross(middle - ray.origin, ray.dir));
      if (d < best) best = d, bestX = x, bestY = y;
    }
  ASSERT_LT(best, 0.5);
  // It and its neighbours see through.
  CadLook look(renderer.camera(), double(w) / h, scene.bounds());
  for (int y = bestY - 3; y <= bestY + 3; ++y)
    for (int x = bestX - 3; x <= bestX + 3; ++x) {
      ASSERT_TRUE(missed(r, x, y)) << x << "," << y;
      dvec3 background = look.background(camera.ray(x + 0.5, y + 0.5));
      EXPECT_GT(luminance(background), 0.5);
      EXPECT_NEAR(r.color.at(x, y).x, background.x, 1e-6);
      EXPECT_NEAR(r.color.at(x, y).y, background.y, 1e-6);
      EXPECT_NEAR(r.color.at(x, y).z, background.z, 1e-6);
    }
}

// The ground shows the part's shadow and nothing else: background pixels
// are never lighter than the background, some near the part are darker,
// and the top rows, far from it, are the background itself.
TEST(CadLook, GroundShadowOnlyDarkens) {
  Scene scene = sceneOf("return box(10)");
  const int w = 320, h = 240;
  RenderOptions options(w, h, 2);
  options.depthAov = true;
  Renderer renderer(scene, options);
  RenderResult r = renderer.renderAll();
  Camera camera(renderer.camera(), w, h);
  CadLook look(renderer.camera(), double(w) / h, scene.bounds());
  int shadowed = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!missed(r, x, y)) continue;
      const dvec3 background = look.background(camera.ray(x + 0.5, y + 0.5));
      const dvec3 c = r.color.at(x, y);
      EXPECT_LE(c.x, background.x + 1e-6);
      if (y < 10) {
        EXPECT_NEAR(c.x, background.x, 1e-6);
      }
      shadowed += c.x < 0.9 * background.x;
      // At most the darkness of full shadow.
      EXPECT_GE(c.x, (1.0 - CadLook::kShadowDarkness) * background.x - 1e-6);
    }
  EXPECT_GT(shadowed, 200);
}

// The sky light's points for a ground point lie on its disc, and drawn
// anew for each point they cover the disc evenly: averaged over many
// ground points, the share of them beyond a chord is the share of the
// disc's area beyond it. Undrawn, they are Vogel's spiral, the same for
// every point.
TEST(CadLook, SkyPointsCoverTheDiscEvenly) {
  // A part 4 wide and 2 high on the ground z = 0: the disc is 2 in
  // radius, centred over the part at 2 + 3 · 4 = 14 (cad_look.cpp).
  Bounds bounds;
  bounds.include(dvec3(-2.0, -1.0, 0.0));
  bounds.include(dvec3(2.0, 1.0, 2.0));
  const CameraSpec camera{dvec3(10, -20, 10), dvec3(0), dvec3(0, 0, 1), 40.0};
  const CadLook look(camera, 4.0 / 3.0, bounds);
  const dvec3 centre(0.0, 0.0, 14.0);
  const double radius = 2.0, d = 0.3;  // the chord x = centre.x + d · radius
  double beyond = 0.0;
  int n = 0;
  for (int i = 0; i < 60; ++i)
    for (int j = 0; j < 60; ++j) {
      const dvec3 ground(0.13 * i - 4.0, 0.11 * j - 3.0, 0.0);
      const auto points = look.skyPointsFor(ground);
      EXPECT_EQ(points, look.skyPointsFor(ground));
      for (const dvec3& q : points) {
        EXPECT_DOUBLE_EQ(q.z, centre.z);
        EXPECT_LE(glm::length(q - centre), radius * (1.0 + 1e-12));
        beyond += q.x > centre.x + d * radius;
        ++n;
      }
    }
  const double segment = (std::acos(d) - d * std::sqrt(1.0 - d * d)) / std::numbers::pi;
  EXPECT_NEAR(beyond / n, segment, 0.005);
  EXPECT_NE(look.skyPointsFor(dvec3(0.0)), look.skyPointsFor(dvec3(0.5, 0.0, 0.0)));
  // Undrawn: the spiral itself, the probes on four sides, half a ring in.
  const auto spiral = look.skyPointsFor(dvec3(0.0), false);
  EXPECT_EQ(spiral, look.skyPointsFor(dvec3(3.0, 1.0, 0.0), false));
  for (int k = 0; k < CadLook::kProbes; ++k)
    EXPECT_NEAR(glm::length(spiral[k] - centre), radius * std::sqrt((k + 0.5) / CadLook::kProbes),
                1e-12);
}

// The shadow of a ball held over the ground shades off smoothly: along
// each row of the ground, the shade's second difference stays small (a
// slope, however steep, has none; a step of s shows as s). With the same
// sky points for every ground point, the penumbra showed as nested rings
// a few levels apart, and it stopped short with a step where the probes
// first saw the ball: second differences of 0.17 (now 0.007).
TEST(CadLook, AWidePenumbraShadesOffSmoothly) {
  Scene scene = sceneOf(
      "return box{size = {1, 1, 0.01}}:translate(8, 8, 0) + "
      "sphere{r = 1}:translate(0, 0, 3)");
  const int w = 640, h = 480;
  RenderOptions options(w, h, 2);
  options.depthAov = true;
  const Renderer renderer(scene, options);
  const RenderResult r = renderer.renderAll();
  Camera camera(renderer.camera(), w, h);
  CadLook look(renderer.camera(), double(w) / h, scene.bounds());
  auto shade = [&](int x, int y) {
    return r.color.at(x, y).x / look.background(camera.ray(x + 0.5, y + 0.5)).x;
  };
  double sharpest = 0.0;
  int shaded = 0;
  // The left half of the picture, where the ball and its shadow are (the
  // plate that stands on the ground, on the right, has a sharp one).
  for (int y = 0; y < h; ++y)
    for (int x = 1; x + 1 < w / 2; ++x) {
      if (!missed(r, x - 1, y) || !missed(r, x, y) || !missed(r, x + 1, y)) continue;
      shaded += shade(x, y) < 0.99;
      sharpest =
          std::max(sharpest, std::abs(shade(x - 1, y) - 2.0 * shade(x, y) + shade(x + 1, y)));
    }
  EXPECT_GT(shaded, 2000);
  EXPECT_LT(sharpest, 0.03);
  // Each corner of the shadow's grid has one share, whichever pixel asks
  // first: the image is the same on one thread, whose tiles come in
  // another order.
  RenderOptions one = options;
  one.threads = 1;
  const RenderResult single = Renderer(scene, one).renderAll();
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) ASSERT_EQ(single.color.at(x, y), r.color.at(x, y)) << x << " " << y;
}

TEST(CadLook, ScenesOfTheirOwnKeepTheirBackground) {
  Scene scene = sceneOf("return scene{objects={box(10)}}");
  RenderResult r = renderWithAovs(scene, 80, 60);
  ASSERT_TRUE(missed(r, 0, 0));
  for (int y : {0, 59})
    for (int i = 0; i < 3; ++i) EXPECT_EQ(float(r.color.at(0, y)[i]), float(scene.background[i]));
}

}  // namespace
}  // namespace csgray::detail
