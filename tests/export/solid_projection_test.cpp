// OpenSCAD's projection() (export/solid_projection.h, profile/mesh_projection.h):
// sections and shadows with areas known in closed form, the cases where
// the plane passes through faces and vertices, and projection() in
// scripts with its one-line errors.
#include "export/solid_projection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "primitives/mesh_solid.h"
#include "profile/region_evaluation.h"
#include "scene/rotation.h"
#include "scene/shapes.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

using std::numbers::pi;

double projectedArea(const SolidPtr& solid, bool cut) { return area(solidProjection(solid, cut)); }

// The octahedron |x| + |y| + |z| ≤ 1, its corners exactly on the axes.
SolidPtr octahedron() {
  std::vector<dvec3> points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<std::vector<std::int64_t>> faces;
  for (int sx : {0, 1})
    for (int sy : {2, 3})
      for (int sz : {4, 5}) {
        // Counterclockwise seen from outside: the corners' order flips
        // with each negative axis.
        const bool odd = ((sx == 1) != (sy == 3)) != (sz == 5);
        faces.push_back(odd ? std::vector<std::int64_t>{sx, sz, sy}
                            : std::vector<std::int64_t>{sx, sy, sz});
      }
  return Primitive::create<MeshSolid>(points, faces);
}

TEST(SolidProjection, TheCutOfABallThroughItsCentreIsItsGreatDisc) {
  const SolidPtr ball = sphereShape(5.0, std::nullopt);
  const double tolerance = projectionTolerance(*ball);
  EXPECT_EQ(tolerance, 1e-3);
  // The mesh's corners are on the sphere, so its polygons are inside the
  // circle and at most the tolerance from it all round.
  for (bool cut : {true, false}) {
    const double a = projectedArea(ball, cut);
    EXPECT_LE(a, 25.0 * pi) << cut;
    EXPECT_GE(a, 25.0 * pi - 2.0 * pi * 5.0 * tolerance) << cut;
  }
}

TEST(SolidProjection, TheShadowOfATurnedBoxIsARectangle) {
  // A 1 × 2 × 3 box turned 30° about x: its shadow is 1 by 2 cos 30° +
  // 3 sin 30°; its section through the centre 1 by 2 / cos 30°.
  const SolidPtr box =
      boxShape(dvec3(1.0, 2.0, 3.0), true)->transformed(rotationDegrees(30.0, {1.0, 0.0, 0.0}));
  const double c = std::cos(pi / 6.0), s = std::sin(pi / 6.0);
  EXPECT_NEAR(projectedArea(box, false), 2.0 * c + 3.0 * s, 1e-9);
  EXPECT_NEAR(projectedArea(box, true), 2.0 / c, 1e-9);
}

TEST(SolidProjection, AFaceOnThePlaneIsInTheCut) {
  // The closed solid's section, as OpenSCAD's: a box standing on z = 0 or
  // hanging from it is cut in its face.
  const SolidPtr standing = boxShape(dvec3(1.0, 2.0, 3.0), false);
  EXPECT_NEAR(projectedArea(standing, true), 2.0, 1e-12);
  EXPECT_NEAR(projectedArea(standing->transformed(Affine::translation({0.0, 0.0, -3.0})), true),
              2.0, 1e-12);
  // Two boxes stacked on the plane, one on each side: one square.
  const SolidPtr stacked = booleanShape(
      Boolean::Op::Union, {standing, standing->transformed(Affine::translation({0.5, 0.0, -3.0}))});
  EXPECT_NEAR(projectedArea(stacked, true), 3.0, 1e-12);
  // A cube less its upper half: the cut face on the plane is the section,
  // though the cutter's bottom face is on the plane too.
  const SolidPtr half = booleanShape(
      Boolean::Op::Difference,
      {boxShape(dvec3(2.0), true),
       boxShape(dvec3(4.0, 4.0, 2.0), true)->transformed(Affine::translation({0.0, 0.0, 1.0}))});
  EXPECT_NEAR(projectedArea(half, true), 4.0, 1e-12);
  EXPECT_NEAR(projectedArea(half, false), 4.0, 1e-12);
}

TEST(SolidProjection, ACutThroughCornersAndASolidThatOnlyTouches) {
  const SolidPtr gem = octahedron();
  // Through four corners: the square |x| + |y| ≤ 1.
  EXPECT_NEAR(projectedArea(gem, true), 2.0, 1e-12);
  EXPECT_NEAR(projectedArea(gem, false), 2.0, 1e-12);
  // Touching the plane at a corner, or above it: no area.
  EXPECT_TRUE(
      solidProjection(gem->transformed(Affine::translation({0.0, 0.0, 1.0})), true).loops.empty());
  EXPECT_TRUE(
      solidProjection(gem->transformed(Affine::translation({0.0, 0.0, 5.0})), true).loops.empty());
  // Its shadow does not depend on the height.
  EXPECT_NEAR(projectedArea(gem->transformed(Affine::translation({0.0, 0.0, 5.0})), false), 2.0,
              1e-12);
}

TEST(SolidProjection, ShadowsOfPartsOverOneAnotherAndOfARing) {
  // Two boxes at different heights that overlap seen from above: the union
  // of their squares, 4 + 4 - 1; cut at the lower one's middle: its square.
  const SolidPtr low = boxShape(dvec3(2.0, 2.0, 1.0), false);
  const SolidPtr high = low->transformed(Affine::translation({1.0, 1.0, 2.0}));
  const SolidPtr both = booleanShape(Boolean::Op::Union, {low, high});
  EXPECT_NEAR(projectedArea(both, false), 7.0, 1e-12);
  EXPECT_NEAR(projectedArea(both->transformed(Affine::translation({0.0, 0.0, -0.5})), true), 4.0,
              1e-12);
  // A torus of radii 3 and 1: an annulus from 2 to 4 either way, with a
  // hole (its loops: an outer one and a hole).
  const SolidPtr ring = torusShape(3.0, 1.0);
  const double tolerance = projectionTolerance(*ring);
  for (bool cut : {true, false}) {
    const Profile flat = solidProjection(ring, cut);
    EXPECT_EQ(flat.loops.size(), 2u) << cut;
    EXPECT_NEAR(area(flat), 12.0 * pi, 2.0 * pi * 6.0 * tolerance) << cut;
  }
}

TEST(SolidProjection, InScripts) {
  const ScriptOptions options = test::exampleOptions();
  const Scene scene = runScript(
      "local ball = sphere(5)\n"
      "local disc = projection(ball, {cut = true})\n"
      "assert(math.abs(disc:area() - 25 * math.pi) < 0.04)\n"
      "assert(math.abs(projection(box(2):rotate(0, 0, 45)):area() - 4) < 1e-9)\n"
      "assert(projection(ball:translate(0, 0, 6), {cut = true}):area() == 0)\n"
      "return linear_extrude{disc - circle{r = 4}, height = 1}\n",
      "part.lua", options);
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_TRUE(scene.objects[0]->contains({4.5, 0.0, 0.5}));
  EXPECT_FALSE(scene.objects[0]->contains({3.5, 0.0, 0.5}));
}

TEST(SolidProjection, BadInputInScriptsIsOneLine) {
  const ScriptOptions options = test::exampleOptions();
  EXPECT_EQ(test::scriptError("return projection(circle{r = 1})", options),
            "part.lua:1: projection: the first argument must be a solid, not a 2D region (a "
            "circle): it has no volume until it is extruded (linear_extrude, rotate_extrude)");
  EXPECT_EQ(test::scriptError("return projection(sphere(1), {cut = 1})", options),
            "part.lua:1: projection: cut must be true or false");
  EXPECT_EQ(test::scriptError("return projection(sphere(1), {kut = true})", options),
            "part.lua:1: projection: unknown parameter 'kut'; did you mean 'cut'?");
  EXPECT_EQ(test::scriptError("return projection(sphere(1), {}, 2)", options),
            "part.lua:1: projection: takes 2 arguments (got 3)");
  const std::string unbounded =
      test::scriptError("return projection(half_space{normal = {0, 0, 1}})", options);
  EXPECT_EQ(unbounded.rfind("part.lua:1: projection: the solid is unbounded", 0), 0u) << unbounded;
  EXPECT_EQ(unbounded.find('\n'), std::string::npos);
  EXPECT_EQ(test::scriptError("return projection(sphere(1))"),
            "part.lua:1: projection: this program cannot project solids");
}

}  // namespace
}  // namespace csgray::detail
