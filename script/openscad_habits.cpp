#include "script/openscad_habits.h"

#include <map>
#include <regex>
#include <utility>
#include <vector>

namespace csgray::detail {

namespace {

const char* const kModifiers =
    "modifiers are methods here: # is s:highlight(), % s:ghost(), ! only(s), * s:disable()";
const char* const kMaterialColour = "a colour is a material here: s:material{color={r, g, b}}";
const char* const kTransforms =
    "transforms are methods of a solid here: s:translate(x, y, z), s:rotate(x, y, z), "
    "s:scale(...), s:mirror(...), s:transform{...}, s:resize{...}";

}  // namespace

std::string methodNameHint(const std::string& name, bool isFunction) {
  static const std::map<std::string, std::string> kMethods = {
      {"color", kMaterialColour},
      {"colour", kMaterialColour},
      {"texture", "a texture is a material's colour here: s:material{color=checker{...}}"},
      {"pigment", kMaterialColour},
      {"union", "union is a function here, not a method: union(s, t) or s + t"},
      {"difference", "difference is a function here, not a method: difference(s, t) or s - t"},
      {"intersection",
       "intersection is a function here, not a method: intersection(s, t) or s * t"},
  };
  if (auto it = kMethods.find(name); it != kMethods.end()) return "; " + it->second;
  if (isFunction) return "; " + name + " is a function here, not a method: " + name + "(s, ...)";
  return "";
}

std::string otherToolNameHint(const std::string& name) {
  // OpenSCAD's built-in modules and functions that csgray calls otherwise.
  static const std::map<std::string, std::string> kNames = {
      {"cube", "OpenSCAD's cube is box{size={x, y, z}} (or box(s)) here"},
      {"translate", "transforms are methods of a solid here: s:translate(...)"},
      {"rotate", "transforms are methods of a solid here: s:rotate(...)"},
      {"scale", "transforms are methods of a solid here: s:scale(...)"},
      {"mirror", "transforms are methods of a solid here: s:mirror(...)"},
      {"resize", "transforms are methods of a solid here: s:resize(...)"},
      {"multmatrix", "transforms are methods of a solid here: s:transform(...)"},
      {"color", kMaterialColour},
      {"echo", "OpenSCAD's echo is print(...) here (it writes to standard error)"},
      {"import",
       "meshes are read with mesh{file=\"part.stl\"}, DXF drawings with "
       "import_dxf{file=\"part.dxf\"}, SVG drawings with import_svg{file=\"part.svg\"}, "
       "OpenSCAD's .csg files with import_csg{file=\"part.csg\"}"},
      {"surface", "OpenSCAD's surface() is height_map{file=\"terrain.dat\"} here"},
      {"projection", "projection() is not supported yet"},
      {"children", "a module is a Lua function here; pass the parts it works on as arguments"},
      {"len", "the length of a list is #list here"},
      {"str", "strings are joined with .. here (tostring(x) for a number)"},
      {"concat", "lists are joined with table.move or a loop here"},
      {"pow", "a power is x^y here"},
      {"ln", "OpenSCAD's ln is math.log(x) here"},
      {"atan2", "OpenSCAD's atan2(y, x) is math.atan(y, x) here (in radians)"},
      {"round", "OpenSCAD's round(x) is math.floor(x + 0.5) here"},
      {"sign", "there is no sign(): write x > 0 and 1 or x < 0 and -1 or 0"},
      {"norm", "there is no norm(): write math.sqrt(x^2 + y^2 + z^2)"},
      // POV-Ray's.
      {"light_source",
       "POV-Ray's light_source is point_light{pos={x, y, z}} here (or "
       "spot_light{}, area_light{}), given in scene{lights={...}}"},
      {"merge", "POV-Ray's merge is union(a, b) or a + b here (a union has no inner faces)"},
      {"lathe", "POV-Ray's lathe is rotate_extrude{region} here"},
      {"sor", "POV-Ray's sor is rotate_extrude{region} here"},
      {"prism", "POV-Ray's prism is linear_extrude{region, height=h} here"},
      {"blob", "there are no blobs: hull(a, b) or rounded_box{} round shapes"},
      {"bozo", "POV-Ray's bozo is perlin{} here"},
      {"granite", "there is no granite pattern: perlin{}, turbulence{}, marble{} or wood{}"},
      {"rgb",
       "POV-Ray's rgb <r, g, b> is {r, g, b} here, linear as in POV-Ray 3.7 (srgb(r, g, "
       "b) is for sRGB codes such as those of a paint program)"},
      {"rgbf", "POV-Ray's rgbf is color={r, g, b} with transparency= and filter={r, g, b} here"},
      {"fog", "fog is a scene's: scene{..., fog={color={r, g, b}, distance=d}}"},
      {"sky_sphere",
       "POV-Ray's sky_sphere is a scene's background texture here: "
       "scene{background=gradient{colors={horizon, zenith}}}"},
      {"color_map", "a pattern's colour map is its colors={{0, c1}, {0.5, c2}, {1, c3}} here"},
      {"bumps", "bumps are a material's: material{bumps=perlin{scale=s}, bump_depth=d}"},
      {"wrinkles", "there is no wrinkles pattern: material{bumps=turbulence{}} tilts normals"},
      {"ripples", "there is no ripples pattern: material{bumps=<any texture>} tilts normals"},
      {"waves", "there is no waves pattern: material{bumps=<any texture>} tilts normals"},
      {"dents", "there is no dents pattern: material{bumps=<any texture>, bump_depth=-d}"},
      {"focal_blur", "focal blur is a camera's: camera{aperture=a, focal_point=p}"},
  };
  if (auto it = kNames.find(name); it != kNames.end()) return "; " + it->second;
  // OpenSCAD's maths functions are those of Lua's math table, which take
  // radians where OpenSCAD's take degrees.
  static const std::map<std::string, std::string> kMaths = {{"abs", ""},
                                                            {"ceil", ""},
                                                            {"floor", ""},
                                                            {"exp", ""},
                                                            {"log", ""},
                                                            {"max", ""},
                                                            {"min", ""},
                                                            {"sqrt", ""},
                                                            {"sin", " (radians)"},
                                                            {"cos", " (radians)"},
                                                            {"tan", " (radians)"},
                                                            {"asin", " (radians)"},
                                                            {"acos", " (radians)"},
                                                            {"atan", " (radians)"},
                                                            {"rands", ""}};
  if (auto it = kMaths.find(name); it != kMaths.end())
    return name == "rands"
               ? "; OpenSCAD's rands is math.random() here"
               : "; OpenSCAD's " + name + " is math." + name + "(...) here" + it->second;
  return "";
}

std::string openscadLineHint(const std::string& sourceLine, bool syntaxError) {
  // The first form the line holds decides: the more particular ones first,
  // so that `translate([1, 2, 3]) cube(1);` is told about transforms
  // rather than about brackets.
  // Forms Lua cannot parse apply to syntax errors only; those it parses
  // (`difference() { a; b; }` calls difference with nothing, `#s` takes a
  // length) to any error on their line.
  struct Form {
    std::regex pattern;
    std::string hint;
    bool anyError;
  };
  static const std::vector<Form> kForms = [] {
    std::vector<Form> forms;
    auto add = [&](const char* pattern, std::string hint, bool anyError = false) {
      forms.push_back({std::regex(pattern), std::move(hint), anyError});
    };
    add(R"(\$f[nas]\b)",
        "there is no $fn, $fa or $fs here: curves are exact, and an export's facets follow "
        "--tolerance");
    add(R"(^\s*(include|use)\s*<)",
        "there is no include or use: a script is one file (a mesh is read with mesh{file=...}, "
        "an OpenSCAD .csg file with import_csg{file=...})");
    add(R"(^\s*module\s+\w)",
        "a module is a Lua function here: local function name(args) ... return solid end");
    add(R"(^\s*function\s+\w+\s*\([^)]*\)\s*=)",
        "a function is written local function f(x) return ... end here");
    add(R"(\bfor\s*\(\s*\w+\s*=)",
        "a loop is for i = 0, 10 do ... end here ([a:s:b] is for i = a, b, s; a list is "
        "for _, v in ipairs(list) do)");
    add(R"(\b(difference|union|intersection|hull)\s*\(\s*\)\s*\{)",
        "booleans take their operands as arguments here: difference(a, b, c) or a - b - c, "
        "union(a, b) or a + b, intersection(a, b) or a * b",
        true);
    add(R"(^\s*(return\s+)?[#%!*]\s*[A-Za-z_])", kModifiers, true);
    // Not a method call (`s:translate(1, 0) else`): OpenSCAD's transform
    // stands alone before what it moves.
    add(R"((?:^|[^:.\w])(translate|rotate|scale|mirror|multmatrix|resize)\s*\([^)]*\)\s*[\w{])",
        kTransforms, true);
    add(R"(\bcolor\s*\([^)]*\)\s*[\w{])",
        "a colour is a material here: s:material{color=\"red\"} or {r, g, b}", true);
    add(R"(\b(linear_extrude|rotate_extrude)\s*\(\s*\w+\s*=[^=])",
        "sweeps take the region and named parameters in braces here: "
        "linear_extrude{region, height=5}, rotate_extrude{region, angle=360}");
    // Named parameters first (sphere(r=2)) or after a value (text("hi",
    // size=5)).
    add(R"(\b\w+\s*\((?:[^()=]*,)?\s*\w+\s*=[^=])",
        "named parameters go in braces here: f{name=value} (as sphere{r=2}, text{\"hi\", "
        "size=5})");
    add(R"(\[\s*[-+.\d\w])", "vectors are Lua tables in braces here: {1, 2, 3}");
    add(R"(!=)", "not equal is ~= in Lua");
    add(R"(&&|\|\|)", "Lua writes and, or and not for &&, || and !");
    add(R"(\?[^:]*:)", "Lua has no ?: operator: write condition and a or b");
    return forms;
  }();
  // A line of a few hundred characters holds any of these forms early; a
  // longer one is not searched whole (the regular expressions backtrack).
  const std::string line = sourceLine.substr(0, 400);
  for (const Form& form : kForms)
    if ((syntaxError || form.anyError) && std::regex_search(line, form.pattern))
      return "; " + form.hint;
  return "";
}

std::string lineOf(const std::string& source, int line) {
  if (line < 1) return "";
  std::size_t begin = 0;
  for (int i = 1; i < line; ++i) {
    begin = source.find('\n', begin);
    if (begin == std::string::npos) return "";
    ++begin;
  }
  const std::size_t end = source.find('\n', begin);
  return source.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
}

}  // namespace csgray::detail
