// linear_extrude and rotate_extrude in scripts: the solids they make (their
// volumes from spans, their meshes' validity) and the one-line errors of
// bad input, each naming the script's line.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "export/cgal/mesh_validity.h"
#include "primitives/linear_extrusion.h"
#include "primitives/revolution.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

constexpr double kPi = std::numbers::pi;

using test::scriptError;
using test::solidOf;

double volumeOf(const SolidPtr& s) { return test::gridVolume(*s, s->bounds(), 300); }

TEST(SweepApi, LinearExtrudeMakesPrismsOfRegions) {
  SolidPtr s =
      solidOf("return linear_extrude{square(2) - circle{r=0.5}:translate(1, 1), height=3}");
  EXPECT_EQ(s->kind(), "linear_extrude");
  EXPECT_NEAR(volumeOf(s), (4 - kPi * 0.25) * 3, 0.005 * (4 - kPi * 0.25) * 3);
  // The region and a table of options; centred; scaled.
  s = solidOf("return linear_extrude(circle(1), {height=2, center=true, scale=0.5})");
  EXPECT_NEAR(s->bounds().lo.z, -1.0, 1e-12);
  EXPECT_NEAR(volumeOf(s), kPi * 2 * (1 + 0.5 + 0.25) / 3, 0.005 * kPi);
  s = solidOf(
      "return linear_extrude{square{size=2, center=true}, height=1, twist=90, scale={1, 2}}");
  EXPECT_NEAR(volumeOf(s), 4 * 1.5, 0.01 * 6);
  // A solid like any other: booleans and transforms.
  s = solidOf("return (linear_extrude{square(2), height=2} - sphere{r=0.5}):translate(5, 0, 0)");
  EXPECT_NEAR(volumeOf(s), 8 - kPi / 48, 0.01 * 8);  // less the ball's octant
}

TEST(SweepApi, RotateExtrudeTurnsRegionsAboutZ) {
  SolidPtr s = solidOf("return rotate_extrude{circle(1):translate(3, 0)}");
  EXPECT_EQ(s->kind(), "rotate_extrude");
  EXPECT_NEAR(volumeOf(s), 2 * kPi * kPi * 3, 0.005 * 2 * kPi * kPi * 3);
  s = solidOf("return rotate_extrude(circle(1):translate(3, 0), {angle=90})");
  EXPECT_NEAR(volumeOf(s), kPi * kPi * 3 / 2, 0.005 * kPi * kPi * 3 / 2);
}

TEST(SweepApi, SweptSolidsExportValid) {
  for (const char* source :
       {"return linear_extrude{square(2) - circle{r=0.5}:translate(1, 1), height=3, twist=45}",
        "return rotate_extrude{(square(2) - circle(0.5):translate(1, 1)):translate(1, 0), "
        "angle=200}",
        "return linear_extrude{regular_polygon{n=6, r=2} + circle(1):translate(2, 0), height=1}"}) {
    SCOPED_TRACE(source);
    SolidPtr s = solidOf(source);
    auto p = std::dynamic_pointer_cast<const Primitive>(s);
    ASSERT_TRUE(p);
    TriangleMesh mesh = p->tessellate(0.01, Bounds::everything());
    EXPECT_EQ(meshDefect(mesh).text, "");
    EXPECT_NEAR(mesh.volume(), volumeOf(s), 0.01 * mesh.volume());
  }
}

void expectError(const std::string& source, const std::string& expected) {
  const std::string e = scriptError(source);
  EXPECT_NE(e.find("part.lua:1:"), std::string::npos) << e;
  EXPECT_NE(e.find(expected), std::string::npos) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;
}

TEST(SweepApi, BadInputIsAOneLineErrorNamingTheLine) {
  expectError("return linear_extrude{square(1), height=0}",
              "linear_extrude: height must be a positive");
  expectError("return linear_extrude{square(1), height=-2}",
              "linear_extrude: height must be a positive");
  expectError("return linear_extrude{square(1), height=0/0}", "height");
  expectError("return linear_extrude{square(1)}", "linear_extrude: needs height");
  expectError("return linear_extrude{square(1), height=1, twist=1e9}", "twist must be at most");
  expectError("return linear_extrude{square(1), height=1, scale=-1}", "scale must be >= 0");
  expectError("return linear_extrude{square(1), height=1, scale={1, 2, 3}}",
              "scale must be a number or {sx, sy}");
  expectError("return linear_extrude{square(1), height=1, hieght=2}", "unknown parameter 'hieght'");
  expectError("return linear_extrude{sphere{r=1}, height=1}", "linear_extrude");
  expectError("return linear_extrude{height=1}", "linear_extrude: needs a region");
  expectError("return linear_extrude{square(1), 2, height=1}", "unexpected value without a name");
  expectError("return linear_extrude(square(1), {height=1}, 3)", "linear_extrude: takes a region");
  expectError("return rotate_extrude{circle(1)}", "rotate_extrude: the region crosses the axis");
  expectError("return rotate_extrude{circle(1):translate(-3, 0)}",
              "rotate_extrude: the region lies on the side x < 0 of the axis (from x = -4), and "
              "every point must have x >= 0: mirror it first, r:mirror(1, 0)");
  expectError("return rotate_extrude{square(1):translate(1, 0), angle=0}",
              "rotate_extrude: angle must be in [-360, 0) or (0, 360] degrees (got 0)");
  expectError("return rotate_extrude{square(1):translate(1, 0), angle=400}",
              "angle must be in [-360, 0) or (0, 360]");
  expectError("return rotate_extrude{square(1):translate(1, 0), angle=-400}",
              "angle must be in [-360, 0) or (0, 360]");
  expectError("return rotate_extrude{42}", "rotate_extrude");
  expectError("return rotate_extrude()", "rotate_extrude: needs a region");
}

}  // namespace
}  // namespace csgray::detail
