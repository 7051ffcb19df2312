// Colours as text (scene/color_names.h) and in scripts: CSS names and hex
// codes are sRGB and come out linear, {r, g, b} stays linear as it always
// was, srgb() converts, and a bad colour is one error line with the
// script's line.
#include "scene/color_names.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "engine/primitive.h"
#include "script/script.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

void expectColor(const dvec3& got, const dvec3& want) {
  EXPECT_NEAR(got.x, want.x, 1e-12);
  EXPECT_NEAR(got.y, want.y, 1e-12);
  EXPECT_NEAR(got.z, want.z, 1e-12);
}

std::string errorOf(const std::string& text) {
  try {
    parseColor(text, "material: color");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

// IEC 61966-2-1: the ends are fixed, the two pieces meet at 0.04045, and
// mid-grey 0.5 is 0.214 in linear light.
TEST(ColorNames, SrgbDecoding) {
  EXPECT_EQ(srgbToLinear(0.0), 0.0);
  EXPECT_NEAR(srgbToLinear(1.0), 1.0, 1e-15);
  EXPECT_NEAR(srgbToLinear(0.5), 0.21404114, 1e-8);
  EXPECT_NEAR(srgbToLinear(0.04045), 0.04045 / 12.92, 1e-15);
  // (The standard's two pieces meet to within 1e-7 there.)
  EXPECT_NEAR(srgbToLinear(0.04045 + 1e-12), 0.04045 / 12.92, 1e-7);
}

TEST(ColorNames, NamesAndHex) {
  expectColor(parseColor("red", "c"), dvec3(1, 0, 0));
  expectColor(parseColor("white", "c"), dvec3(1));
  expectColor(parseColor("black", "c"), dvec3(0));
  // The web's grey and green, not X11's.
  expectColor(parseColor("gray", "c"), dvec3(srgbToLinear(128 / 255.0)));
  expectColor(parseColor("grey", "c"), parseColor("gray", "c"));
  expectColor(parseColor("green", "c"), dvec3(0, srgbToLinear(128 / 255.0), 0));
  // Case, spaces and underscores do not matter; the first and last names.
  expectColor(parseColor("Steel Blue", "c"), parseColor("steelblue", "c"));
  expectColor(parseColor("STEEL_BLUE", "c"), parseColor("#4682b4", "c"));
  expectColor(parseColor("aliceblue", "c"), parseColor("#f0f8ff", "c"));
  expectColor(parseColor("yellowgreen", "c"), parseColor("#9acd32", "c"));
  expectColor(parseColor("rebeccapurple", "c"), parseColor("#663399", "c"));
  // Hex: #rrggbb and #rgb, each digit of #rgb doubled; either case.
  expectColor(parseColor("#ff8800", "c"), dvec3(1, srgbToLinear(0x88 / 255.0), 0));
  expectColor(parseColor("#f80", "c"), parseColor("#ff8800", "c"));
  expectColor(parseColor("#FF8800", "c"), parseColor("#ff8800", "c"));
  expectColor(parseColor("orange", "c"), parseColor("#ffa500", "c"));
}

TEST(ColorNames, BadColoursSayWhy) {
  EXPECT_EQ(errorOf("redd"), "material: color 'redd' is not a colour name (did you mean red?)");
  EXPECT_EQ(errorOf("steelbleu"),
            "material: color 'steelbleu' is not a colour name (did you mean steelblue?)");
  EXPECT_NE(errorOf("chartreusy-ish").find("CSS names such as \"red\""), std::string::npos);
  EXPECT_EQ(errorOf(""),
            "material: color '' is not a colour name (CSS names such as \"red\", "
            "or \"#rrggbb\")");
  for (const char* bad : {"#ff88", "#gg0000", "#", "#ff88001"})
    EXPECT_EQ(errorOf(bad), std::string("material: color '") + bad +
                                "' is not a hex colour: write #rrggbb or #rgb");
  // A long text is shown cut.
  EXPECT_LT(errorOf(std::string(10000, 'x')).size(), 200u);
}

// ---- In scripts

Scene sceneOf(const std::string& source) { return runScript(source, "part.lua"); }

dvec3 colorOf(const std::string& color) {
  Scene scene = sceneOf("return sphere(1):material{color=" + color + "}");
  auto p = std::dynamic_pointer_cast<const Primitive>(scene.objects.at(0));
  return p->material()->color;
}

void expectError(const std::string& source, const std::string& expected) {
  std::string e = test::scriptError(source);
  EXPECT_EQ(e, expected) << source;
}

TEST(ColorScripts, EveryColourKeyTakesNamesAndHex) {
  expectColor(colorOf("\"tomato\""), parseColor("#ff6347", "c"));
  expectColor(colorOf("\"#f80\""), parseColor("#ff8800", "c"));
  // A triple is linear, as before: {0.5, 0.5, 0.5} is not mid-grey's 0.214.
  expectColor(colorOf("{0.5, 0.5, 0.5}"), dvec3(0.5));
  expectColor(colorOf("0.25"), dvec3(0.25));
  // srgb() turns components as a paint program shows them into linear.
  expectColor(colorOf("srgb(1, 0.5, 0)"), dvec3(1, srgbToLinear(0.5), 0));
  expectColor(colorOf("srgb{1, 0.5, 0}"), dvec3(1, srgbToLinear(0.5), 0));

  Scene scene = sceneOf(
      "return scene{objects={sphere(1):material{filter=\"yellow\", transparency=0.5}},\n"
      "  lights={point_light{pos={0, 0, 5}, color=\"#ffcc00\"}}, background=\"white\"}");
  expectColor(scene.background, dvec3(1));
  expectColor(scene.lights.at(0).color, parseColor("#ffcc00", "c"));
  auto p = std::dynamic_pointer_cast<const Primitive>(scene.objects.at(0));
  expectColor(p->material()->filter, dvec3(1, 1, 0));
  scene = sceneOf("return sphere(1):material{color=checker{colors={\"red\", \"#0000ff\"}}}");
  p = std::dynamic_pointer_cast<const Primitive>(scene.objects.at(0));
  expectColor(p->material()->texture->colorAt(dvec3(0.5), dvec3(0, 0, 1)), dvec3(1, 0, 0));
}

TEST(ColorScripts, BadColoursAreOneLineWithTheScriptLine) {
  expectError("local s = sphere(1)\nreturn s:material{color=\"redd\"}",
              "part.lua:2: material: color 'redd' is not a colour name (did you mean red?)");
  expectError("local s = sphere(1)\n\nreturn s:material{color=\"#12345\"}",
              "part.lua:3: material: color '#12345' is not a hex colour: write #rrggbb or #rgb");
  expectError("return sphere(1):material{color=true}",
              "part.lua:1: material: color must be a colour: {r, g, b}, a name such as \"red\" "
              "or \"#rrggbb\"");
  EXPECT_EQ(test::scriptError("return scene{objects={sphere(1)}, background=\"nope\"}")
                .rfind("part.lua:1: scene: background 'nope' is not a colour name", 0),
            0u);
  expectError("return point_light{pos={0, 0, 1}, color=\"bleu\"}",
              "part.lua:1: point_light: color 'bleu' is not a colour name (did you mean blue?)");
  expectError("return srgb(2, 0, 0)",
              "part.lua:1: srgb: components must be in [0, 1] (for 0 to 255, divide by 255 or "
              "write \"#rrggbb\")");
  expectError("return srgb(1, 0)", "part.lua:1: srgb: takes r, g, b or {r, g, b}");
  expectError("return srgb(1, 0, 0, 0)", "part.lua:1: srgb: takes 3 arguments (got 4)");
}

}  // namespace
}  // namespace csgray::detail
