// OpenSCAD's modifiers in scripts (docs/script.md, Modifiers): a ghost is
// shown but is not part of the model, a highlight is part of it and is
// drawn over the image, only() keeps one solid, disable() drops one. The
// volumes are those of the exported mesh, the colours those of rendered
// pixels.
#include "scene/modifiers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "export/cgal/mesh_boolean.h"
#include "raytrace/renderer.h"
#include "script/script.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

using std::numbers::pi;

Scene sceneOf(const std::string& source) {
  return runScript(source, "part.lua", test::exampleOptions());
}

// The volume of the export of a script's model.
double exportedVolume(const Scene& scene) {
  EXPECT_EQ(scene.objects.size(), 1u);
  return meshOfSolid(*scene.objects.at(0), 0.001).mesh.volume();
}

TEST(Modifiers, AGhostIsLeftOutOfTheExport) {
  Scene scene = sceneOf("return box(10) + sphere(3):translate(20, 0, 0):ghost()");
  EXPECT_NEAR(exportedVolume(scene), 1000.0, 1e-6);
  ASSERT_EQ(scene.ghosts.size(), 1u);
  EXPECT_NEAR(scene.ghosts[0]->bounds().center().x, 20.0, 1e-9);
  EXPECT_TRUE(scene.highlights.empty());
}

TEST(Modifiers, AGhostCutsNothingAndIntersectsNothing) {
  EXPECT_NEAR(exportedVolume(sceneOf("return box(10) - box(5):ghost()")), 1000.0, 1e-6);
  // OpenSCAD drops the ghost from the intersection: the box is left.
  EXPECT_NEAR(exportedVolume(sceneOf("return box(10) * box(5):ghost()")), 1000.0, 1e-6);
  // The first operand of a difference a ghost: the next one is cut.
  EXPECT_NEAR(exportedVolume(sceneOf("return difference(box(20):ghost(), box(10), "
                                     "box(5))")),
              1000.0 - 125.0, 1e-6);
}

TEST(Modifiers, AHighlightIsPartOfTheModel) {
  Scene scene =
      sceneOf("return box(10) - cylinder{r=2, h=30, center=true}:translate(5, 5, 0):highlight()");
  EXPECT_NEAR(exportedVolume(scene), 1000.0 - pi * 4.0 * 10.0, 0.2);
  ASSERT_EQ(scene.highlights.size(), 1u);
  // The highlight is the cylinder, where it is, not the part it cuts.
  EXPECT_NEAR(scene.highlights[0]->bounds().hi.z, 15.0, 1e-9);
  EXPECT_TRUE(scene.highlights[0]->contains({5.0, 5.0, 12.0}));
  EXPECT_TRUE(scene.ghosts.empty());
}

TEST(Modifiers, OnlyDropsTheRest) {
  Scene scene = sceneOf("return box(10) + only(sphere(2):translate(20, 0, 0)) + sphere(1):ghost()");
  EXPECT_NEAR(exportedVolume(scene), 4.0 / 3.0 * pi * 8.0, 0.05);
  EXPECT_TRUE(scene.ghosts.empty());  // the ghost is outside the only() solid
  EXPECT_FALSE(scene.objects[0]->contains({5.0, 5.0, 5.0}));
}

TEST(Modifiers, DisableDropsIt) {
  Scene scene = sceneOf("return box(10) + sphere(3):translate(20, 0, 0):disable()");
  EXPECT_NEAR(exportedVolume(scene), 1000.0, 1e-6);
  EXPECT_TRUE(scene.ghosts.empty());
  EXPECT_TRUE(scene.highlights.empty());
}

TEST(Modifiers, MarksGoAlongWithTransformsAndScenes) {
  Scene scene = sceneOf(
      "local part = (box(1) + sphere(1):ghost()):translate(5, 0, 0)\n"
      "return scene{objects={part, box(1):translate(0, 9, 0):highlight()}}");
  ASSERT_EQ(scene.ghosts.size(), 1u);
  EXPECT_NEAR(scene.ghosts[0]->bounds().center().x, 5.0, 1e-9);
  EXPECT_EQ(scene.objects.size(), 2u);
  ASSERT_EQ(scene.highlights.size(), 1u);
  EXPECT_NEAR(scene.highlights[0]->bounds().lo.y, 9.0, 1e-9);
}

TEST(Modifiers, ScriptQueriesSeeTheModel) {
  // A ghost is empty to bounds() and contains(), and check() leaves it out.
  Scene scene = sceneOf(
      "local g = sphere(3):ghost()\n"
      "assert(not g:contains(0, 0, 0))\n"
      "local part = box(10) + sphere(3):translate(30, 0, 0):ghost()\n"
      "local lo, hi = part:bounds()\n"
      "assert(hi[1] == 10, 'bounds ' .. hi[1])\n"
      "local report = check(part, {samples=2000})\n"
      "assert(report.ok and math.abs(report.volume.exact - 1000) < 1, report.summary)\n"
      "return part");
  EXPECT_EQ(scene.objects.size(), 1u);
}

TEST(Modifiers, BadUsesAreErrors) {
  auto error = [](const std::string& source) { return test::scriptError(source); };
  {
    std::string e = error("return box(1):ghost(2)");
    EXPECT_NE(e.find("part.lua:1: ghost: takes no arguments"), std::string::npos) << e;
  }
  std::string e = error("return only(3)");
  EXPECT_NE(e.find("part.lua:1: only: argument must be a solid"), std::string::npos) << e;
  e = error("return box(1):disable()");
  EXPECT_NE(e.find("part.lua: nothing is left to show: every solid is disabled"), std::string::npos)
      << e;
  e = error("return plane{}:highlight()");
  EXPECT_NE(e.find("highlight: a plane is a surface, not a solid"), std::string::npos) << e;
}

// Seen from above, orthographic, 0.5 units a pixel: x to the right, y up.
const char* kTopView =
    "camera=camera{eye={0, 0, 50}, look_at={0, 0, 0}, up={0, 1, 0}, "
    "projection='orthographic', width=40}, background={0, 0, 0}";

dvec3 pixelAt(const std::string& objects, int x, int y) {
  Scene scene = sceneOf("return scene{objects={" + objects + "}, " + kTopView + "}");
  return Renderer(scene, RenderOptions(80, 80, 1)).render().at(x, y);
}

TEST(Modifiers, RenderShowsAGhostSeeThroughAndGrey) {
  const std::string floor = "box{size={40, 40, 1}, center=true}:translate(0, 0, -10)";
  // Over the floor, at (10, 0): the floor alone, then under a ghost ball.
  const dvec3 bare = pixelAt(floor, 60, 40);
  const dvec3 ghosted = pixelAt(floor + ", sphere(3):translate(10, 0, 0):ghost()", 60, 40);
  EXPECT_GT(std::abs(ghosted.x - bare.x), 0.02);
  EXPECT_NEAR(ghosted.x, ghosted.y, 1e-9);  // grey over grey
  EXPECT_NEAR(ghosted.y, ghosted.z, 1e-9);
  // The ghost lets the floor show through: darker than an opaque grey ball
  // would be lit from above, brighter than nothing behind it.
  const dvec3 alone = pixelAt("sphere(3):translate(10, 0, 0):ghost()", 60, 40);
  EXPECT_GT(alone.x, 0.0);
  EXPECT_GT(ghosted.x, alone.x);
}

TEST(Modifiers, RenderShowsAHighlightInPinkOnTop) {
  // A hole in a plate, its cutter highlighted: the hole's pixel is pink.
  const std::string part =
      "box{size={30, 30, 2}, center=true} - cylinder{r=3, h=10, center=true}"
      ":translate(-10, 0, 0):highlight()";
  const dvec3 hole = pixelAt(part, 20, 40);
  EXPECT_GT(hole.x, 0.3);
  EXPECT_GT(hole.x, 3.0 * hole.y);
  // Elsewhere the plate is grey.
  const dvec3 plate = pixelAt(part, 40, 40);
  EXPECT_NEAR(plate.x, plate.y, 1e-9);
  // Under something in front of it, the highlight still shows.
  const dvec3 covered =
      pixelAt("box{size={20, 20, 2}, center=true}:translate(-10, 0, 10), " + part, 20, 40);
  EXPECT_GT(covered.x, 2.0 * covered.y);
}

}  // namespace
}  // namespace csgray::detail
