// 2D regions in the script (docs/script.md, "2D regions"): the shapes,
// their booleans and transforms land where they should, a region shown in
// a scene is flat in the plane z = 0, areas of offsets and hulls are the
// analytic ones, and every mistake is one line naming the script's line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "primitives/mesh_solid.h"
#include "scene/region_surface.h"
#include "script/script.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

using test::scriptError;

Scene sceneOf(const std::string& source) { return runScript(source, "part.lua", {}); }

void expectError(const std::string& source, const std::string& expected) {
  const std::string e = scriptError(source);
  EXPECT_EQ(e, expected) << source;
}

// Runs a script whose assert() calls hold the truths; an assert that fails
// is the script's error, which fails the test.
void expectHolds(const std::string& source) {
  try {
    sceneOf(source + "\nreturn square(1)");
  } catch (const std::exception& e) {
    ADD_FAILURE() << e.what();
  }
}

// The one region a script returns, in the world's (x, y).
RegionPtr regionOf(const std::string& source) {
  Scene scene = sceneOf(source);
  EXPECT_TRUE(scene.objects.empty());
  EXPECT_EQ(scene.surfaces.size(), 1u);
  if (scene.surfaces.size() != 1) return nullptr;
  RegionPtr r = regionInPlane(*scene.surfaces[0]);
  EXPECT_NE(r, nullptr) << source;
  return r;
}

std::optional<double> hitFrom(const Surface& s, double x, double y, double z) {
  return s.hit(Ray(dvec3(x, y, z), dvec3(0, 0, z > 0 ? -1 : 1)));
}

TEST(ScriptRegion, ShapesAreFlatInThePlaneZ0SeenFromBothSides) {
  Scene scene = sceneOf(R"(
    return scene{objects={circle{r=2}, square(3):translate(10, 0), ellipse{rx=3, ry=1},
                          polygon{{0, 0}, {4, 0}, {0, 3}}, regular_polygon{n=6, r=1},
                          rectangle{size={4, 2}, center=true}, box(1)}})");
  EXPECT_EQ(scene.objects.size(), 1u);
  ASSERT_EQ(scene.surfaces.size(), 6u);
  const char* kinds[] = {"circle", "square", "ellipse", "polygon", "regular_polygon", "rectangle"};
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(scene.surfaces[i]->kind(), kinds[i]);
    EXPECT_EQ(scene.surfaces[i]->shape(), Surface::Shape::Region);
  }
  const Surface& circle = *scene.surfaces[0];
  ASSERT_TRUE(hitFrom(circle, 1.9, 0, 10));
  EXPECT_DOUBLE_EQ(*hitFrom(circle, 1.9, 0, 10), 10.0);
  ASSERT_TRUE(hitFrom(circle, 0, -1.9, -5));  // from below too
  EXPECT_DOUBLE_EQ(*hitFrom(circle, 0, -1.9, -5), 5.0);
  EXPECT_FALSE(hitFrom(circle, 1.5, 1.5, 10));  // 1.5² + 1.5² > 4
  EXPECT_EQ(glm::abs(circle.normal()), dvec3(0, 0, 1));
  EXPECT_LE(circle.bounds().lo.x, -2);
  EXPECT_GE(circle.bounds().hi.y, 2);
  EXPECT_LT(circle.bounds().hi.y, 2 + 1e-6);
  const Surface& square = *scene.surfaces[1];
  EXPECT_TRUE(hitFrom(square, 12.9, 2.9, 1));
  EXPECT_FALSE(hitFrom(square, 9.9, 1, 1));
  EXPECT_TRUE(hitFrom(*scene.surfaces[2], 2.9, 0, 1));
  EXPECT_FALSE(hitFrom(*scene.surfaces[2], 0, 1.1, 1));
  EXPECT_TRUE(hitFrom(*scene.surfaces[3], 1, 1, 1));
  EXPECT_FALSE(hitFrom(*scene.surfaces[3], 3, 2, 1));
  EXPECT_TRUE(hitFrom(*scene.surfaces[4], 0.95, 0, 1));
  EXPECT_FALSE(hitFrom(*scene.surfaces[4], 0, 0.95, 1));  // the flat is at √3/2
  EXPECT_TRUE(hitFrom(*scene.surfaces[5], -1.9, -0.9, 1));
  EXPECT_FALSE(hitFrom(*scene.surfaces[5], -2.1, 0, 1));
}

TEST(ScriptRegion, BareArgumentsStandForTheMainOne) {
  RegionPtr s = regionOf("return square{2, 3}");
  ASSERT_TRUE(s);
  EXPECT_EQ(s->bounds().hi, dvec2(2, 3));
  RegionPtr c = regionOf("return circle(2)");
  ASSERT_TRUE(c);
  EXPECT_EQ(c->bounds().hi, dvec2(2, 2));
  RegionPtr holed = regionOf(
      "return polygon{points={{0, 0}, {10, 0}, {10, 10}, {0, 10}, {3, 3}, {7, 3}, {7, 7}, {3, "
      "7}}, paths={{0, 1, 2, 3}, {4, 5, 6, 7}}}");
  ASSERT_TRUE(holed);
  EXPECT_TRUE(holed->contains({1, 1}));
  EXPECT_FALSE(holed->contains({5, 5}));
}

TEST(ScriptRegion, BooleansOfRegions) {
  RegionPtr r = regionOf("return square(4) - circle(1):translate(2, 2)");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->op(), Region::Op::Difference);
  EXPECT_TRUE(r->contains({0.5, 0.5}));
  EXPECT_FALSE(r->contains({2.5, 2.5}));
  r = regionOf("return union(square(1), square(1):translate(3, 0), square(1):translate(6, 0))");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->op(), Region::Op::Union);
  EXPECT_EQ(r->operands().size(), 3u);
  EXPECT_TRUE(r->contains({6.5, 0.5}));
  r = regionOf("return difference(square(10), {circle(1), circle(1):translate(5, 5)})");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->operands().size(), 3u);
  EXPECT_FALSE(r->contains({5.5, 5}));
  EXPECT_TRUE(r->contains({3, 3}));
  r = regionOf("return intersection{square(2), circle(2)} * square(1)");
  ASSERT_TRUE(r);
  EXPECT_TRUE(r->contains({0.5, 0.5}));
  EXPECT_FALSE(r->contains({1.5, 0.5}));
  // The solids' booleans are still there.
  Scene scene = sceneOf("return union(box(1), sphere(1)) - difference{box(2), sphere(1)}");
  EXPECT_EQ(scene.objects.size(), 1u);
}

TEST(ScriptRegion, RegionsAndSolidsDoNotMix) {
  const std::string solidWanted =
      " must be a solid, not a 2D region (a square): it has no volume until it is extruded "
      "(linear_extrude, rotate_extrude)";
  const std::string regionWanted =
      " must be a region, not a solid: 2D regions and solids do not mix (extrude the region "
      "first)";
  expectError("local s = square(1)\nreturn box(1) + s", "part.lua:2: operand of '+'" + solidWanted);
  expectError("local s = square(1)\nreturn s - box(1)",
              "part.lua:2: operand of '-'" + regionWanted);
  expectError("local s = square(1)\nreturn union(box(1), s)",
              "part.lua:2: union: operand 2" + solidWanted);
  expectError("local s = square(1)\nreturn intersection{s, box(1)}",
              "part.lua:2: intersection: operand 2" + regionWanted);
  expectError("return hull(square(1), box(1))", "part.lua:1: hull: operand 2" + regionWanted);
  expectError("return square(1) + plane{}",
              "part.lua:1: operand of '+' must be a region, but a plane is a surface");
  expectError("return square(1) + square(1):translate(0, 0, 1)",
              "part.lua:1: operand of '+' must be a region, but this square was placed in space "
              "(by a 3D transform or a material), so it is a flat surface now");
}

TEST(ScriptRegion, TransformsInThePlane) {
  expectHolds(R"lua(
    local function near(a, b) return math.abs(a - b) < 1e-12 end
    local lo, hi = square(2):translate(1, 2):bounds()
    assert(lo[1] == 1 and lo[2] == 2 and hi[1] == 3 and hi[2] == 4)
    lo, hi = square{2, 1}:rotate(90):bounds()  -- exact at quarter turns
    assert(lo[1] == -1 and lo[2] == 0 and hi[1] == 0 and hi[2] == 2)
    lo, hi = square(1):rotate(45):bounds()
    assert(near(lo[1], -math.sqrt(0.5)) and near(hi[2], math.sqrt(2)))
    lo, hi = square(1):scale(2, 3):bounds()
    assert(hi[1] == 2 and hi[2] == 3)
    lo, hi = square(1):scale{2, 3}:scale(0.5):bounds()
    assert(hi[1] == 1 and hi[2] == 1.5)
    lo, hi = square(1):mirror(1, 0):bounds()
    assert(lo[1] == -1 and hi[1] == 0 and hi[2] == 1)
    lo, hi = square(1):mirror{1, 1}:bounds()  -- across y = -x
    assert(near(lo[1], -1) and near(lo[2], -1) and near(hi[1], 0))
    lo, hi = square(1):transform{{1, 1, 5}, {0, 1, 0}}:bounds()  -- a shear
    assert(lo[1] == 5 and hi[1] == 7 and hi[2] == 1)
    lo, hi = square(1):transform{{2, 0, 0}, {0, 2, 0}, {0, 0, 1}}:bounds()
    assert(hi[1] == 2 and hi[2] == 2)
    assert(circle(1):translate{5, 0}:contains(5.9, 0))
    assert(not circle(1):translate{5, 0}:contains{4, 0.5})
    assert(tostring(square(1):rotate(30)) == "region(square, 1 profile, 4 edges)")
    assert(tostring(square(1) - circle(0.2)) == "region(region, 2 profiles, 5 edges)")
  )lua");
  // A transform leaves the original as it was.
  RegionPtr r = regionOf("local a = square(1)\nlocal b = a:translate(5, 0)\nreturn a");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->bounds().lo, dvec2(0, 0));
}

TEST(ScriptRegion, TransformsThatKeepThePlaneKeepARegion) {
  expectHolds(R"lua(
    assert(tostring(square(1):translate(1, 2, 0)) == "region(square, 1 profile, 4 edges)")
    assert(tostring(square(1):rotate(0, 0, 90)) == "region(square, 1 profile, 4 edges)")
    assert(tostring(square(1):rotate(0, 180, 0)) == "region(square, 1 profile, 4 edges)")
    assert(tostring(square(1):scale(2, 2, 5)) == "region(square, 1 profile, 4 edges)")
    assert(tostring(square(1):mirror(1, 0, 0)) == "region(square, 1 profile, 4 edges)")
    local lo, hi = square(1):rotate(0, 180, 0):bounds()  -- turned over about y
    assert(math.abs(lo[1] + 1) < 1e-12 and hi[2] == 1)
    assert(tostring(square(1):translate(0, 0, 1)):find("^surface"))
    assert(tostring(square(1):rotate(90, 0, 0)):find("^surface"))
    assert(tostring(square(1):material{color={1, 0, 0}}):find("^surface"))
  )lua");
  // A wall, as square{} made before regions: the square stood up in y = 0.
  Scene scene = sceneOf("return square{size=10}:rotate(90, 0, 0)");
  ASSERT_EQ(scene.surfaces.size(), 1u);
  const Surface& wall = *scene.surfaces[0];
  EXPECT_EQ(wall.kind(), "square");
  EXPECT_EQ(regionInPlane(wall), nullptr);
  ASSERT_TRUE(wall.hit(Ray(dvec3(5, -3, 5), dvec3(0, 1, 0))));
  EXPECT_NEAR(*wall.hit(Ray(dvec3(5, -3, 5), dvec3(0, 1, 0))), 3.0, 1e-12);
  EXPECT_FALSE(wall.hit(Ray(dvec3(5, -3, 10.5), dvec3(0, 1, 0))));
  // A material keeps the region in place.
  scene = sceneOf("return circle(1):material{color={1, 0, 0}}");
  ASSERT_EQ(scene.surfaces.size(), 1u);
  EXPECT_NE(scene.surfaces[0]->material(), nullptr);
  EXPECT_NE(regionInPlane(*scene.surfaces[0]), nullptr);
}

TEST(ScriptRegion, MistakesAreOneLineAtTheScriptsLine) {
  struct Case {
    const char* source;
    const char* expected;
  } cases[] = {
      {"return square{size=0}", "square: size must be > 0 (got 0, 0)"},
      {"return square{size={1, 0/0}}", "square: size[2] must be finite"},
      {"return rectangle{size=2}", "rectangle: size must be {w, h}"},
      {"return rectangle{}", "rectangle: needs size={w, h}"},
      {"return square(1, 2)", "square: takes 1 argument (got 2)"},
      {"return circle{}", "circle: needs r (radius) or d (diameter)"},
      {"return circle{r=1, d=2}", "circle: give r or d, not both"},
      {"return circle(-1)", "circle: the radius must be > 0 (got -1)"},
      {"return circle{radius=1}", "circle: unknown parameter 'radius'; did you mean 'r'?"},
      {"return ellipse{rx=1}", "ellipse: needs rx and ry (the half-axes)"},
      {"return polygon{}", "polygon: needs points={{x, y}, ...}"},
      {"return polygon{{0, 0}, {1, 0}}", "polygon: needs at least 3 distinct points (got 2)"},
      {"return polygon{{0, 0}, {1, 1}, {2, 2}}",
       "polygon: the points are collinear, so they enclose no area"},
      {"return polygon{{0, 0}, {1, 0/0}, {0, 1}}", "polygon: points[2][2] must be finite"},
      {"return polygon{{0, 0}, {1, 0, 0}, {0, 1}}",
       "polygon: points[2] must be {x, y}, got a list of 3"},
      {"return polygon{points={{0, 0}, {1, 0}, {0, 1}}, paths={{0, 1, 3}}}",
       "polygon: paths[1]: index 3 is not a point (there are 3, from 0)"},
      {"return polygon{points={{0, 0}, {1, 0}, {0, 1}}, paths={{0, 1.5, 2}}}",
       "polygon: paths[1][2] must be a point index (an integer from 0)"},
      {"return regular_polygon{n=2, r=1}",
       "regular_polygon: n must be a whole number from 3 to 1000000 (got 2)"},
      {"return regular_polygon{r=1}", "regular_polygon: needs n (the number of corners)"},
      {"return square(1):translate(1)",
       "translate: takes x, y or {x, y} (or x, y, z to place it in space) (got 1 argument)"},
      {"return square(1):rotate(1, 2)",
       "rotate: takes an angle in degrees (or x, y, z to place it in space) (got 2 arguments)"},
      {"return square(1):scale(0)", "scale: a factor of 0 squashes the region flat"},
      {"return square(1):scale(1, 0/0)", "scale: y must be finite"},
      {"return square(1):mirror(0, 0)", "mirror: the normal must not be zero"},
      {"return square(1):transform{{1, 2, 0}, {2, 4, 0}}",
       "transform: the map squashes the plane (it is singular)"},
      {"return square(1):transform{{1, 0, 0}, {0, 1, 0}, {0, 1, 1}}",
       "transform: the third row must be {0, 0, 1}"},
      {"return square(1):transform{{1, 0}, {0, 1}}",
       "transform: a region takes 2 or 3 rows of 3 numbers (or rows of 4 to place it in space)"},
      {"return square(1):translate(1e149, 0):scale(100)",
       "scale: the region's coordinates would pass 1e150"},
      {"return square(1):translate(1e300, 0)",
       "translate: the region's coordinates would pass 1e150"},
      {"return square(10):offset{r=1e200}", "offset: r is too large (at most 1e150 either way)"},
      {"return text{\"A\", size=1e300}", "text: size is too large (at most 1e148; got 1e+300)"},
      {"return square(1):translate(0, 0, 0/0)", "translate: z must be finite"},
      {"return square(1):offset{}",
       "offset: needs r= (rounded) or delta= (with chamfer=true or not)"},
      {"return square(1):offset{r=1, delta=1}", "offset: give r or delta, not both"},
      {"return square(1):offset{r=1, chamfer=true}",
       "offset: chamfer goes with delta=, not with r= (which rounds)"},
      {"return square(1):offset({r=1}, 2)", "offset: takes 1 argument (got 2)"},
      {"local a = square(1):area(2)", "area: takes no arguments (got 1)"},
      {"local a = square(1):contains(1)", "contains: takes x, y or {x, y} (got 1 argument)"},
      {"local a = square(1) - square(1)\nlocal lo = (a * square(1):translate(5, 5)):bounds()",
       "bounds: the region is empty"},
      {"return hull()", "hull: needs at least one solid or region"},
      {"local r = square(1)\nlocal a = r.area(box(1))",
       "area: the receiver (call it as r:area(...)) must be a region, not a solid: 2D regions and "
       "solids do not mix (extrude the region first)"},
  };
  for (const Case& c : cases) {
    const std::string source(c.source);
    const int line = static_cast<int>(std::count(source.begin(), source.end(), '\n')) + 1;
    expectError(source, "part.lua:" + std::to_string(line) + ": " + c.expected);
  }
}

// ---- Areas, offsets and hulls (the evaluation of profile/region_evaluation.h)

// The script's area() of expression, within a relative 1e-9 of expected.
void expectArea(const std::string& expression, double expected) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", expected);
  const std::string source = "local a = (" + expression + "):area()\nlocal e = " + text +
                             "\nif math.abs(a - e) > 1e-9 * math.abs(e) then error(string.format("
                             "'area %.17g, expected %.17g', a, e)) end\nreturn square(1)";
  try {
    sceneOf(source);
  } catch (const std::exception& e) {
    ADD_FAILURE() << expression << ": " << e.what();
  }
}

TEST(ScriptRegion, AreasAreAnalytic) {
  const double pi = std::numbers::pi;
  expectArea("square(4)", 16);
  expectArea("circle(2)", 4 * pi);
  expectArea("square(4) - circle(1):translate(2, 2)", 16 - pi);
  expectArea("square(2) + square(2):translate(1, 1)", 7);
  expectArea("square(2) * square(2):translate(1, 1)", 1);
  expectArea("regular_polygon{n=6, r=1}", 3 * std::sqrt(3.0) / 2);
  // Even-odd: the bow tie's two triangles.
  expectArea("polygon{{0, 0}, {2, 2}, {2, 0}, {0, 2}}", 2);
  expectArea(
      "polygon{points={{0, 0}, {10, 0}, {10, 10}, {0, 10}, {3, 3}, {7, 3}, {7, 7}, {3, "
      "7}}, paths={{0, 1, 2, 3}, {4, 5, 6, 7}}}",
      84);
}

TEST(ScriptRegion, OffsetsAndHullsAreAnalytic) {
  const double pi = std::numbers::pi;
  // A rounded offset of a square of side a by r: a² + 4ar + πr².
  expectArea("square(2):offset{r=1}", 4 + 8 + pi);
  // Inwards: the square shrinks to side a − 2r, its corners stay sharp.
  expectArea("square(4):offset{r=-1}", 4);
  // delta mitres the corners: (a + 2d)². chamfer cuts each, as OpenSCAD
  // (Clipper's square join) does, by the line at distance d from the
  // corner across its bisector: a triangle of height (√2 − 1)d and base
  // twice that, (√2 − 1)²d².
  expectArea("square(2):offset{delta=1}", 16);
  expectArea("square(2):offset{delta=1, chamfer=true}",
             16 - 4 * (std::sqrt(2.0) - 1) * (std::sqrt(2.0) - 1));
  // The hull of two circles of radius r at distance d: πr² + 2rd.
  expectArea("hull(circle(1), circle(1):translate(5, 0))", pi + 10);
  expectArea("hull{square(1), square(1):translate(3, 3)}", 7);
}

TEST(ScriptRegion, ALetterPlusACircleIsItsRoundedOffset) {
  // minkowski of a region and a circle is its offset{r=}, at the region's
  // own tolerance: the same region, whose area is the offset's. (At the
  // small circle's finer tolerance the letter's curves took minutes.)
  EXPECT_NO_THROW(
      sceneOf("local o = text{\"o\", size=10}\n"
              "local a, b = minkowski(o, circle(1.5)):area(), o:offset{r=1.5}:area()\n"
              "assert(a == b and a > o:area(), a .. ' against ' .. b)\n"
              "return square(1)"));
}

// import_dxf{}, import_svg{} and height_map{} read files beside the
// script, by its rules, and name the file and its line when it is wrong.
TEST(ScriptRegion, DrawingsAndHeightMapsFromFiles) {
  const std::string folder = testing::TempDir() + "/drawings_and_heights";
  std::filesystem::create_directories(folder);
  // A closed 10 × 10 polyline on layer "plate".
  std::ofstream(folder + "/square.dxf")
      << "0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\nplate\n70\n1\n10\n0\n20\n0\n10\n10\n20\n0\n"
         "10\n10\n20\n10\n10\n0\n20\n10\n0\nENDSEC\n0\nEOF\n";
  std::ofstream(folder + "/bad.dxf") << "0\nSECTION\n2\nENTITIES\n0\nLINE\n10\nx\n";
  std::ofstream(folder + "/hill.dat") << "# heights\n1 2\n3 4\n";
  // A 20 × 20 mm page of 40 × 40 user units: a 10 × 10 square and a disc of
  // radius 5 (2.5 mm) with the id "dot".
  std::ofstream(folder + "/shapes.svg")
      << "<svg width='20mm' height='20mm' viewBox='0 0 40 40'>\n<rect width='10' height='10'/>\n"
         "<circle id='dot' cx='30' cy='30' r='5'/>\n</svg>\n";
  std::ofstream(folder + "/bad.svg") << "<svg>\n<path d='M0 0 L1'/>\n</svg>\n";
  auto run = [&](const std::string& source) {
    std::ofstream(folder + "/part.lua") << source;
    return runScriptFile(folder + "/part.lua", test::exampleOptions());
  };
  auto error = [&](const std::string& source) -> std::string {
    try {
      run(source);
    } catch (const ScriptError& e) {
      const std::string message = e.what();
      return message.substr(message.find("part.lua"));
    }
    return "(no error)";
  };
  run("local r = import_dxf{file='square.dxf', layer='plate', origin={5, 5}, scale=2}\n"
      "assert(math.abs(r:area() - 400) < 1e-9)\n"
      "local lo, hi = r:bounds()\n"
      "assert(lo[1] == -10 and hi[2] == 10)\n"
      "return r");
  run("local r = import_svg{file='shapes.svg'}\n"
      "assert(math.abs(r:area() - (25 + math.pi * 6.25)) < 1e-9)\n"
      "local dot = import_svg{file='shapes.svg', id='dot', center=true}\n"
      "assert(math.abs(dot:area() - math.pi * 6.25) < 1e-9)\n"
      "local lo, hi = dot:bounds()\n"
      "assert(math.abs(lo[1] + 2.5) < 1e-12 and math.abs(hi[2] - 2.5) < 1e-12)\n"
      "return linear_extrude{r, height=1}");
  // One cell of mean height 2.5 on a base at z = 0.
  const Scene hill = run("return height_map{file='hill.dat', center=true}");
  ASSERT_EQ(hill.objects.size(), 1u);
  auto mesh = std::dynamic_pointer_cast<const MeshSolid>(hill.objects[0]);
  ASSERT_TRUE(mesh);
  EXPECT_NEAR(mesh->volume(), 2.5, 1e-12);
  EXPECT_EQ(error("return import_dxf{file='bad.dxf'}"),
            "part.lua:1: import_dxf: bad.dxf:8: expected a number for group code 10, found 'x'");
  EXPECT_EQ(error("return import_dxf{file='square.dxf', layer='holes'}"),
            "part.lua:1: import_dxf: square.dxf: layer \"holes\" draws no closed outline (its "
            "layers: plate)");
  EXPECT_EQ(error("return import_svg{file='bad.svg'}"),
            "part.lua:1: import_svg: bad.svg:2: <path> d: after 'L1': expected a number, found "
            "the end of the data");
  EXPECT_EQ(error("return import_svg{file='shapes.svg', dpi=0}"),
            "part.lua:1: import_svg: dpi must be a number >= 0.001");
  EXPECT_EQ(error("return import_svg{file='none.svg'}").substr(0, 34),
            "part.lua:1: import_svg: none.svg: ");
  EXPECT_EQ(error("return height_map{file='square.dxf'}"),
            "part.lua:1: height_map: square.dxf:2: 'SECTION' is not a number");
  const std::string outside = error("return height_map{file='../hill.dat'}");
  EXPECT_TRUE(outside.starts_with("part.lua:1: height_map: ")) << outside;
  EXPECT_EQ(outside.find('\n'), std::string::npos) << outside;
}

}  // namespace
}  // namespace csgray::detail
