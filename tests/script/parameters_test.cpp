// The customizer's annotations (script/parameters.h): which lines declare
// parameters, what they hold, and -D checked against them on every run.
#include "script/parameters.h"

#include <gtest/gtest.h>

#include "script/script.h"

namespace csgray::detail {
namespace {

Bounds boundsOf(const std::string& source,
                std::vector<std::pair<std::string, std::string>> defines = {}) {
  ScriptOptions options;
  options.defines = std::move(defines);
  return runScript(source, "part.lua", options).bounds();
}

std::string defineError(const std::string& source, const std::string& name,
                        const std::string& value) {
  ScriptOptions options;
  options.defines = {{name, value}};
  try {
    runScript(source, "part.lua", options);
  } catch (const DefineError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(Parameters, EachKindAndItsAnnotation) {
  const std::vector<Parameter> ps = findParameters(
      "-- a part\n"
      "width = 40 -- [10:100] leg width, mm\n"
      "step = 2.5 -- [0.5:0.5:10]\n"
      "style = \"round\" -- [\"round\", \"square\"] the ends\n"
      "holes = 2 -- [1, 2, 3]\n"
      "hollow = true -- [] a shell\n"
      "size = {90, 60, 30} -- [10:200] outer size\n"
      "local depth = depth or 7 -- [1:20]\n"
      "label = 'top' -- []\n"
      "return box(1)\n",
      "part.lua");
  ASSERT_EQ(ps.size(), 8u);
  EXPECT_EQ(ps[0].name, "width");
  EXPECT_EQ(ps[0].line, 2);
  EXPECT_EQ(ps[0].kind, ParameterKind::Number);
  EXPECT_EQ(ps[0].defaultValue.number, 40.0);
  EXPECT_TRUE(ps[0].hasRange);
  EXPECT_EQ(ps[0].min, 10.0);
  EXPECT_EQ(ps[0].max, 100.0);
  EXPECT_EQ(ps[0].step, 0.0);
  EXPECT_EQ(ps[0].description, "leg width, mm");
  EXPECT_EQ(ps[1].step, 0.5);
  EXPECT_EQ(ps[1].max, 10.0);
  EXPECT_EQ(ps[2].kind, ParameterKind::String);
  ASSERT_EQ(ps[2].choices.size(), 2u);
  EXPECT_EQ(ps[2].choices[1].text, "square");
  EXPECT_EQ(ps[3].choices.size(), 3u);
  EXPECT_EQ(ps[4].kind, ParameterKind::Boolean);
  EXPECT_TRUE(ps[4].defaultValue.boolean);
  EXPECT_EQ(ps[5].kind, ParameterKind::Vector);
  EXPECT_EQ(ps[5].defaultValue.vector, (std::vector<double>{90, 60, 30}));
  EXPECT_EQ(ps[5].defaultValue.defineText(), "{90,60,30}");
  EXPECT_EQ(ps[6].name, "depth");
  EXPECT_TRUE(ps[6].readsGlobal);
  EXPECT_EQ(ps[7].defaultValue.text, "top");
}

TEST(Parameters, OtherLinesAreNot) {
  EXPECT_TRUE(findParameters("length = 60 -- [mm] leg length\n"  // a unit, not a spec
                             "  inner = 3 -- [1:5]\n"            // indented: not top level
                             "local w = 3 -- [1:5]\n"            // a local -D cannot set
                             "x = f(2) -- the x\n"
                             "--[[ y = 2 -- [1:3] ]]\n"
                             "z = 1 --[[ [1:3] ]]\n",
                             "part.lua")
                  .empty());
}

TEST(Parameters, AnnotationsThatDoNotFitNameTheLine) {
  auto error = [](const std::string& source) {
    try {
      findParameters(source, "part.lua");
    } catch (const ScriptError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(error("\nw = 4 -- [10:100:5]\n"),
            "part.lua:2: parameter w: [10:100:5]: min is above max (the order is min:step:max)");
  EXPECT_EQ(error("w = 400 -- [10:100]\n"),
            "part.lua:1: parameter w: the default 400 is outside [10:100]");
  EXPECT_EQ(error("s = \"oval\" -- [\"round\", \"square\"]\n"),
            "part.lua:1: parameter s: the default \"oval\" is not among [\"round\", \"square\"]");
  EXPECT_EQ(error("b = true -- [0:1]\n"),
            "part.lua:1: parameter b: a boolean takes empty brackets [] (a check box), not [0:1]");
  EXPECT_EQ(error("w = f(3) -- [1:5]\n"),
            "part.lua:1: parameter w: its value must be a number, a string in quotes, true, false "
            "or {numbers} to be a parameter");
  EXPECT_EQ(error("w = 1 -- [1:5]\nw = 2 -- [1:5]\n"),
            "part.lua:2: parameter w is declared on line 1 already");
}

TEST(Parameters, DefineReplacesThePlainDefault) {
  const std::string source = "width = 40 -- [10:100]\nreturn box{size={width, 1, 1}}\n";
  EXPECT_EQ(boundsOf(source).hi.x, 40.0);
  EXPECT_EQ(boundsOf(source, {{"width", "25"}}).hi.x, 25.0);
  // The `name or value` form reads the global itself.
  const std::string local =
      "local width = width or 40 -- [10:100]\nreturn box{size={width, 1, 1}}\n";
  EXPECT_EQ(boundsOf(local, {{"width", "12.5"}}).hi.x, 12.5);
}

TEST(Parameters, DefineIsCheckedAgainstTheAnnotation) {
  const std::string source =
      "width = 40 -- [10:100]\n"
      "style = \"round\" -- [\"round\", \"square\"]\n"
      "hollow = false -- []\n"
      "size = {9, 6, 3} -- [1:20]\n"
      "return box(1)\n";
  EXPECT_EQ(defineError(source, "width", "500"),
            "-D width=500: width must be from 10 to 100 (part.lua:1)");
  EXPECT_EQ(defineError(source, "width", "wide"), "-D width=wide: width is a number (part.lua:1)");
  EXPECT_EQ(defineError(source, "style", "oval"),
            "-D style=oval: style must be one of \"round\", \"square\" (part.lua:2)");
  EXPECT_EQ(defineError(source, "hollow", "1"),
            "-D hollow=1: hollow is true or false (part.lua:3)");
  EXPECT_EQ(defineError(source, "size", "{1,2}"),
            "-D size={1,2}: size is a vector of 3 numbers, e.g. {9,6,3} (part.lua:4)");
  EXPECT_EQ(defineError(source, "size", "{1,2,30}"),
            "-D size={1,2,30}: size's components must be from 1 to 20 (part.lua:4)");
  EXPECT_EQ(defineError(source, "style", "square"), "(no error)");
}

TEST(Parameters, DefineTakesVectors) {
  // Without an annotation too: a table of numbers.
  const Bounds b = boundsOf("return box{size=size}", {{"size", "{90,60,30}"}});
  EXPECT_EQ(b.hi, dvec3(90, 60, 30));
  const Bounds spaced = boundsOf("return box{size=size}", {{"size", "{ 1.5, 2 , 3e1 }"}});
  EXPECT_EQ(spaced.hi, dvec3(1.5, 2, 30));
  EXPECT_EQ(defineError("return box(1)", "size", "{1,,2}"),
            "-D size={1,,2}: a vector is finite numbers between braces, e.g. {90,60,30}");
  EXPECT_EQ(defineError("return box(1)", "size", "{1,inf}"),
            "-D size={1,inf}: a vector is finite numbers between braces, e.g. {90,60,30}");
  // A brace left open (or a closing one alone) is a typo, not a string;
  // in quotes it is one.
  EXPECT_EQ(defineError("return box(1)", "size", "{1,2"),
            "-D size={1,2: a vector is finite numbers between braces, e.g. {90,60,30}");
  EXPECT_EQ(defineError("return box(1)", "size", "1,2}"),
            "-D size=1,2}: a vector is finite numbers between braces, e.g. {90,60,30}");
  EXPECT_EQ(defineError("assert(size == '{1,2') return box(1)", "size", "'{1,2'"), "(no error)");
}

// A whole number arrives as a Lua integer, as the same literal in the
// script would: a label made of it reads "20 mm", not "20.0 mm".
TEST(Parameters, WholeNumbersAreIntegers) {
  EXPECT_EQ(defineError("assert(size .. ' mm' == '20 mm') return box(1)", "size", "20"),
            "(no error)");
  EXPECT_EQ(defineError("size = 10 -- [5:50]\nassert(size .. ' mm' == '20 mm') return box(1)",
                        "size", "20"),
            "(no error)");
  EXPECT_EQ(defineError("assert(math.type(x) == 'float' and x == 2.5) return box(1)", "x", "2.5"),
            "(no error)");
  EXPECT_EQ(defineError("assert(math.type(v[1]) == 'integer' and v[2] == 0.5) return box(1)", "v",
                        "{2, 0.5}"),
            "(no error)");
}

// A -D of a name the script never writes is a typo, told but not refused.
TEST(Parameters, ADefineNoLineNamesIsWarnedOf) {
  ScriptOptions options;
  std::vector<std::string> warnings;
  options.warn = [&](const std::string& w) { warnings.push_back(w); };
  options.defines = {{"Width", "50"}, {"width", "60"}, {"height", "1"}};
  runScript("width = 40 -- [10:100]\nreturn box{size={width, 10, 10}}", "part.lua", options);
  EXPECT_EQ(warnings,
            (std::vector<std::string>{"-D Width: part.lua never names Width; did you mean width?",
                                      "-D height: part.lua never names height"}));
}

TEST(Parameters, LinesKeepTheirNumbersWhenADefineReplacesADefault) {
  const std::string source = "width = 40 -- [10:100]\nerror('here')\n";
  ScriptOptions options;
  options.defines = {{"width", "20"}};
  try {
    runScript(source, "part.lua", options);
    FAIL() << "no error";
  } catch (const ScriptError& e) {
    EXPECT_NE(std::string(e.what()).find("part.lua:2:"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace csgray::detail
