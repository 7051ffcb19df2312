// What OpenSCAD users bring along: each habit that Lua refuses gets a
// one-line error at the script's line naming the csgray way (docs/script.md,
// "Coming from OpenSCAD"), and resize() sizes a part as OpenSCAD's does.
#include <gtest/gtest.h>

#include <string>

#include "engine/tight_bounds.h"
#include "script/script.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

void expectHint(const std::string& source, const std::string& expected) {
  const std::string e = test::scriptError(source);
  EXPECT_NE(e.find(expected), std::string::npos) << source << "\n  gave: " << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;
}

TEST(OpenScadHabits, EachHabitNamesTheCsgrayWay) {
  expectHint("local a = 1\n$fn = 50\nreturn sphere(1)",
             "part.lua:2: unexpected symbol near '$'; there is no $fn, $fa or $fs here");
  expectHint("return sphere(1, $fa=5)", "there is no $fn, $fa or $fs here");
  expectHint("return box([1, 2, 3])",
             "part.lua:1: unexpected symbol near '['; vectors are Lua tables in braces here: "
             "{1, 2, 3}");
  expectHint("difference() { box(1); sphere(1); }",
             "part.lua:1: difference: needs at least one solid; booleans take their operands as "
             "arguments here: difference(a, b, c) or a - b - c");
  expectHint("union() {\n box(1);\n}", "part.lua:1: union: needs at least one solid; booleans");
  expectHint("module peg(h) { cylinder{r=1, h=h} }",
             "part.lua:1: syntax error near 'peg'; a module is a Lua function here: local "
             "function name(args) ... return solid end");
  expectHint("function twice(x) = 2 * x;",
             "part.lua:1: unexpected symbol near '='; a function is written local function f(x) "
             "return ... end here");
  expectHint("for (i = [0:10]) box(i);",
             "part.lua:1: <name> expected near '('; a loop is for i "
             "= 0, 10 do ... end here");
  expectHint("return linear_extrude(height=5)",
             "part.lua:1: ')' expected near '='; sweeps take the region and named parameters in "
             "braces here: linear_extrude{region, height=5}");
  expectHint("echo(\"width\", 3)",
             "part.lua:1: attempt to call a nil value (global 'echo'); OpenSCAD's echo is "
             "print(...) here");
  expectHint("include <MCAD/boxes.scad>\nreturn box(1)",
             "part.lua:1: syntax error near '<'; there is no include or use: a script is one file");
  expectHint("use <lib.scad>", "there is no include or use");
  expectHint("translate([1, 2, 3]) box(1)",
             "part.lua:1: unexpected symbol near '['; transforms are methods of a solid here: "
             "s:translate(x, y, z)");
  expectHint("return cube(10)", "OpenSCAD's cube is box{size={x, y, z}} (or box(s)) here");
  // Lua reads this as sphere{r=1} % box(1), a remainder.
  expectHint("return sphere{r=1}\n%box(1)",
             "part.lua:2: attempt to perform arithmetic on a solid value; modifiers are methods "
             "here: # is s:highlight(), % s:ghost()");
  expectHint("local a = box(1)\n!box(2)", "part.lua:2: unexpected symbol near '!'; modifiers are");
  expectHint("return sphere(r=2)", "named parameters go in braces here: f{name=value}");
  expectHint("return text(\"hi\", size=5)", "as sphere{r=2}, text{\"hi\", size=5}");
  expectHint("return cylinder{r=5, h=2 * PI}",
             "part.lua:1: attempt to perform arithmetic on a nil "
             "value (global 'PI'); OpenSCAD's PI is math.pi here");
  expectHint("local v = {1, 2, 3} + {4, 5, 6}",
             "vectors are Lua tables here, which have no arithmetic");
  expectHint("if 1 != 2 then end", "not equal is ~= in Lua");
  expectHint("return sphere(abs(-1))", "OpenSCAD's abs is math.abs(...) here");
  expectHint("return sphere(sin(30) + 1)", "OpenSCAD's sin is math.sin(...) here (radians)");
}

TEST(OpenScadHabits, LuaOfItsOwnGetsNoOpenScadHint) {
  // Indexing is Lua: a runtime error on a line with t[1] is not about vectors.
  const std::string e = test::scriptError("local t = {1}\nreturn t[1] + nil");
  EXPECT_EQ(e, "part.lua:2: attempt to perform arithmetic on a nil value") << e;
  // A transform written as a method, followed by a word on its line, is
  // no OpenSCAD transform.
  const std::string method =
      test::scriptError("local r = square(1):translate(1, 0) and nil + 1\nreturn box(1)");
  EXPECT_EQ(method.find("transforms are methods"), std::string::npos) << method;
  // A near miss of an API name still gets the nearest name.
  EXPECT_NE(test::scriptError("return sphre(1)").find("did you mean sphere?"), std::string::npos);
  // A method of another kind of value says so, instead of suggesting itself.
  EXPECT_NE(test::scriptError("return circle(1):ghost()")
                .find("ghost is a method of another kind of value (solid, surface), not of this "
                      "one"),
            std::string::npos);
}

Bounds boundsOf(const std::string& source) {
  Scene scene = runScript(source, "part.lua");
  return scene.objects.at(0)->bounds();
}

TEST(Resize, SizesTheBoundsAndKeepsZeroAxes) {
  Bounds b = boundsOf("return box{size={2, 4, 8}}:resize(10, 0, 2)");
  test::expectVecNear(b.lo, {0, 0, 0}, 1e-12);
  test::expectVecNear(b.hi, {10, 4, 2}, 1e-12);
  // Scaled about the origin, as OpenSCAD's resize is.
  b = boundsOf("return sphere(1):translate(1, 0, 0):resize{4, 2, 2}");
  test::expectVecNear(b.lo, {0, -1, -1}, 1e-12);
  test::expectVecNear(b.hi, {4, 1, 1}, 1e-12);
}

TEST(Resize, AutoScalesTheZeroAxesWithTheOthers) {
  Bounds b = boundsOf("return box{size={2, 4, 8}}:resize{10, 0, 0, auto=true}");
  test::expectVecNear(b.hi, {10, 20, 40}, 1e-12);
  b = boundsOf("return box{size={2, 4, 8}}:resize{10, 0, 0, auto={false, true, false}}");
  test::expectVecNear(b.hi, {10, 20, 8}, 1e-12);
  // Two sizes given: the zero axis takes the larger factor.
  b = boundsOf("return box{size={2, 4, 8}}:resize{4, 12, 0, auto=true}");
  test::expectVecNear(b.hi, {4, 12, 24}, 1e-12);
}

TEST(Resize, RegionsToo) {
  Scene scene = runScript(
      "local r = circle(1):resize{6, 0, auto=true}\n"
      "assert(math.abs(r:area() - math.pi * 9) < 1e-6, r:area())\n"
      "return linear_extrude{circle(1):resize(6, 2), height=1}",
      "part.lua");
  const Bounds b = scene.objects.at(0)->bounds();
  test::expectVecNear(b.lo, {-3, -1, 0}, 1e-12);
  test::expectVecNear(b.hi, {3, 1, 1}, 1e-12);
}

// resize measures the part's own box, as OpenSCAD does, not the looser
// box of s:bounds(): a cube less half of it, a turned ball, a region less
// half of it.
TEST(Resize, MeasuresThePartsOwnBox) {
  Scene scene =
      runScript("return (box(20) - box(22):translate(10, -1, -1)):resize(30, 0, 0)", "part.lua");
  Bounds b = tightBounds(*scene.objects.at(0));
  test::expectVecNear(b.lo, {0, 0, 0}, 1e-9);
  test::expectVecNear(b.hi, {30, 20, 20}, 1e-9);
  scene = runScript("return sphere(5):rotate(0, 0, 45):resize(20, 0, 0)", "part.lua");
  b = tightBounds(*scene.objects.at(0));
  test::expectVecNear(b.lo, {-10, -5, -5}, 1e-9);
  test::expectVecNear(b.hi, {10, 5, 5}, 1e-9);
  scene = runScript(
      "local half = (square(20) - square(22):translate(10, -1)):resize(30, 0)\n"
      "assert(math.abs(half:area() - 600) < 1e-9, half:area())\n"
      "return linear_extrude{half, height=1}",
      "part.lua");
  EXPECT_NEAR(tightBounds(*scene.objects.at(0)).hi.x, 30.0, 1e-9);
}

TEST(Resize, BadSizesAreErrors) {
  auto expectError = [](const std::string& source, const std::string& expected) {
    const std::string e = test::scriptError(source);
    EXPECT_NE(e.find(expected), std::string::npos) << source << "\n  gave: " << e;
  };
  expectError("return box(1):resize(-1, 0, 0)",
              "part.lua:1: resize: the size along x must be a finite number >= 0");
  expectError("return box(1):resize(1, 0)",
              "part.lua:1: resize: takes x, y, z or {x, y, z, auto=...}");
  expectError("return box(1):resize{1, 0, 0, aut=true}", "resize: unknown parameter 'aut'");
  expectError("return box(1):resize{1, 0, 0, auto=1}",
              "resize: auto must be true, false or a list");
  expectError("return half_space{normal={0, 0, 1}}:resize(1, 1, 0)",
              "resize: the shape is unbounded along x");
  expectError("return square(1):resize(1, 2, 3)", "resize: takes x, y or {x, y, auto=...}");
}

}  // namespace
}  // namespace csgray::detail
