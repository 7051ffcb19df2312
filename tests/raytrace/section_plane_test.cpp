// The section plane (raytrace/section_plane.h): a hollow box cut through
// its middle shows its cavity, and its walls where the plane cuts them in
// the section colour, at the plane's exact depth; the model is unchanged
// and the framing is the whole part's.
#include "raytrace/section_plane.h"

#include <gtest/gtest.h>

#include "engine/instance.h"
#include "engine/primitive.h"
#include "raytrace/renderer.h"
#include "script/script.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

// A box of 10 with a cavity of 8, both centred, seen from the front (−y)
// orthographically: 101 pixels over 20 units, pixel 50 on x = 0, pixel 73
// on x = 4.6, within the wall (4 to 5).
Scene hollowBox() {
  Scene scene =
      runScript("return box{size={10, 10, 10}, center=true} - box{size={8, 8, 8}, center=true}\n",
                "part.lua");
  scene.camera = test::frontOrthographicCamera(20.0);
  return scene;
}

// The near half gone: the side y >= 0 is kept.
const SectionPlane kMiddle{{0.0, -1.0, 0.0}, 0.0};

RenderResult render(const Scene& scene, std::optional<SectionPlane> section) {
  RenderOptions options(101, 101, 2);
  options.depthAov = true;
  options.section = section;
  return Renderer(scene, options).renderAll();
}

TEST(SectionPlane, ShowsTheCavityAndTheCutWallsInTheSectionColour) {
  const Scene scene = hollowBox();
  const RenderResult whole = render(scene, std::nullopt);
  const RenderResult cut = render(scene, kMiddle);
  // Whole: the front face, at y = −5, 45 from the eye, in grey.
  EXPECT_DOUBLE_EQ(whole.depth.at(50, 50).x, 45.0);
  EXPECT_DOUBLE_EQ(whole.depth.at(73, 50).x, 45.0);
  const dvec3 grey = whole.color.at(73, 50);
  EXPECT_NEAR(grey.x, grey.y, 0.02 * grey.x);
  // Cut: the centre sees through the cavity to its back wall at y = 4 ...
  EXPECT_DOUBLE_EQ(cut.depth.at(50, 50).x, 54.0);
  // ... and the wall is cut at y = 0, red where the plane meets material.
  EXPECT_DOUBLE_EQ(cut.depth.at(73, 50).x, 50.0);
  const dvec3 section = cut.color.at(73, 50);
  EXPECT_GT(section.x, 3.0 * section.y);
  EXPECT_GT(section.x, 3.0 * section.z);
  const dvec3 expected = sectionColor();
  EXPECT_GT(expected.x, 3.0 * expected.y);
  // The cavity's back wall keeps the part's grey.
  const dvec3 inside = cut.color.at(50, 50);
  EXPECT_NEAR(inside.x, inside.y, 0.02 * inside.x + 1e-3);
}

TEST(SectionPlane, LeavesTheModelAndTheFramingAlone) {
  Scene scene = runScript("return sphere(5)\n", "part.lua");
  const SolidPtr before = scene.objects[0];
  RenderOptions options(64, 48, 1);
  const CameraSpec framed = Renderer(scene, options).camera();
  options.section = SectionPlane{{0.0, 0.0, 1.0}, -2.0};
  const Renderer renderer(scene, options);
  EXPECT_EQ(scene.objects[0], before);
  EXPECT_EQ(renderer.camera().eye, framed.eye);
  EXPECT_EQ(renderer.camera().lookAt, framed.lookAt);
  // Straight down through the centre: the cut at z = −2, a face of the section material.
  const std::optional<SurfaceHit> hit = renderer.firstHit(Ray({0.0, 0.0, 10.0}, {0.0, 0.0, -1.0}));
  ASSERT_TRUE(hit);
  EXPECT_DOUBLE_EQ(hit->t, 12.0);
  EXPECT_EQ(hit->boundary.primitive->material(), sectionMaterial());
  // A plane past the part keeps all of it; one before it, nothing.
  options.section = SectionPlane{{0.0, 0.0, 1.0}, 6.0};
  EXPECT_DOUBLE_EQ(Renderer(scene, options).firstHit(Ray({0.0, 0.0, 10.0}, {0.0, 0.0, -1.0}))->t,
                   5.0);
  options.section = SectionPlane{{0.0, 0.0, 1.0}, -6.0};
  EXPECT_FALSE(Renderer(scene, options).firstHit(Ray({0.0, 0.0, 10.0}, {0.0, 0.0, -1.0})));
}

// A part of nested uses (rows of uses of a union) is cut as its copy in
// place is, and the cut holds it as rays walk it fastest: one union of
// the copied primitives (Solid::forRays), made once for every frame.
TEST(SectionPlane, CutsNestedUsesAsTheirCopies) {
  Scene nested = runScript(
      "local peg = cylinder{r=1, h=4} + sphere{r=1.5}:translate(0, 0, 4)\n"
      "local row = union(peg, peg:translate(4, 0, 0), peg:translate(8, 0, 0))\n"
      "return union(row, row:translate(0, 4, 0):rotate(0, 0, 10))\n",
      "part.lua");
  ASSERT_TRUE(nested.objects[0]->hasInstances());
  Scene copied = nested;
  copied.objects[0] = flattened(nested.objects[0]);
  ASSERT_FALSE(copied.objects[0]->hasInstances());
  const SectionPlane plane{{0.0, -1.0, 0.2}, 1.0};
  const Scene cut = sectioned(nested, plane);
  const SolidPtr held = cut.objects[0]->children()[0];
  EXPECT_EQ(held, nested.objects[0]->forRays());
  EXPECT_FALSE(held->hasInstances());
  EXPECT_EQ(held->children().size(), 12u);
  const RenderResult a = render(nested, plane), b = render(copied, plane);
  int part = 0;
  for (int y = 0; y < 101; ++y)
    for (int x = 0; x < 101; ++x) {
      ASSERT_EQ(a.depth.at(x, y), b.depth.at(x, y)) << x << " " << y;
      ASSERT_EQ(a.color.at(x, y), b.color.at(x, y)) << x << " " << y;
      part += std::isfinite(a.depth.at(x, y).x);
    }
  EXPECT_GT(part, 500);
}

}  // namespace
}  // namespace csgray::detail
