// The script front end: the API builds the solids it says, parameters are
// checked, errors name the file and line, -D sets globals.
#include "script/script.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine/boolean.h"
#include "engine/primitive.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

using test::scriptError;
using test::solidOf;

TEST(Script, SphereByRadiusOrDiameter) {
  for (const char* source : {"return sphere{r=2}", "return sphere(2)", "return sphere{d=4}"}) {
    SolidPtr s = solidOf(source);
    EXPECT_EQ(s->bounds().hi.x, s->bounds().hi.x);
    EXPECT_NEAR(s->bounds().hi.x, 2.0, 1e-6) << source;
    EXPECT_TRUE(s->contains(dvec3(0, 0, 1.99)));
    EXPECT_FALSE(s->contains(dvec3(0, 0, 2.01)));
  }
}

TEST(Script, BoxFollowsOpenScadCube) {
  SolidPtr corner = solidOf("return box{size={10, 20, 30}}");
  EXPECT_TRUE(corner->contains(dvec3(9, 19, 29)));
  EXPECT_FALSE(corner->contains(dvec3(-1, 1, 1)));
  SolidPtr centred = solidOf("return box{size={10, 20, 30}, center=true}");
  EXPECT_TRUE(centred->contains(dvec3(-4.9, -9.9, -14.9)));
  EXPECT_FALSE(centred->contains(dvec3(5.1, 0, 0)));
  SolidPtr cube = solidOf("return box(4)");
  EXPECT_TRUE(cube->contains(dvec3(3.9)));
}

TEST(Script, CylinderAndCone) {
  SolidPtr c = solidOf("return cylinder{r=2, h=5}");
  EXPECT_TRUE(c->contains(dvec3(1.9, 0, 4.9)));
  EXPECT_FALSE(c->contains(dvec3(0, 0, 5.1)));
  SolidPtr centred = solidOf("return cylinder{d=4, h=6, center=true}");
  EXPECT_TRUE(centred->contains(dvec3(0, 1.9, -2.9)));
  SolidPtr cone = solidOf("return cone{r=2, h=4}");
  EXPECT_TRUE(cone->contains(dvec3(0.9, 0, 2)));  // radius at z=2 is 1
  EXPECT_FALSE(cone->contains(dvec3(1.1, 0, 2)));
  SolidPtr frustum = solidOf("return cylinder{r1=2, r2=1, h=4}");
  EXPECT_TRUE(frustum->contains(dvec3(1.4, 0, 2)));  // radius at z=2 is 1.5
  EXPECT_FALSE(frustum->contains(dvec3(1.6, 0, 2)));
}

TEST(Script, EllipsoidHalfSpaceQuadric) {
  SolidPtr e = solidOf("return ellipsoid{radii={3, 2, 1}}");
  EXPECT_TRUE(e->contains(dvec3(2.9, 0, 0)));
  EXPECT_FALSE(e->contains(dvec3(0, 2.1, 0)));
  SolidPtr h = solidOf("return half_space{normal={0, 0, 1}, offset=2}");
  EXPECT_TRUE(h->contains(dvec3(100, -100, 1.9)));
  EXPECT_FALSE(h->contains(dvec3(0, 0, 2.1)));
  // x² + y² + z² - 4 <= 0 as a quadric matrix.
  SolidPtr q = solidOf("return quadric{matrix={{1,0,0,0},{0,1,0,0},{0,0,1,0},{0,0,0,-4}}}");
  EXPECT_TRUE(q->contains(dvec3(0, 1.9, 0)));
  EXPECT_FALSE(q->contains(dvec3(0, 2.1, 0)));
}

TEST(Script, BooleansAndOperators) {
  const char* a = "local a, b = box{size=2}, sphere{r=1}:translate(2, 1, 1) ";
  for (std::string op : {"a + b", "union(a, b)", "union{a, b}"}) {
    SolidPtr s = solidOf(std::string(a) + "return " + op);
    EXPECT_TRUE(s->contains(dvec3(0.5, 0.5, 0.5)));
    EXPECT_TRUE(s->contains(dvec3(2.5, 1, 1)));
  }
  for (std::string op : {"a - b", "difference(a, b)"}) {
    SolidPtr s = solidOf(std::string(a) + "return " + op);
    EXPECT_TRUE(s->contains(dvec3(0.5, 0.5, 0.5)));
    EXPECT_FALSE(s->contains(dvec3(1.5, 1, 1)));
  }
  for (std::string op : {"a * b", "intersection(a, b)"}) {
    SolidPtr s = solidOf(std::string(a) + "return " + op);
    EXPECT_FALSE(s->contains(dvec3(0.5, 0.5, 0.5)));
    EXPECT_TRUE(s->contains(dvec3(1.5, 1, 1)));
  }
  // An operand may be a list of solids: difference(a, holes), as the
  // message about deep boolean trees recommends.
  for (std::string op : {"difference(a, {b})", "difference(a, {b}, {})", "difference(a, b, {})"}) {
    SolidPtr s = solidOf(std::string(a) + "return " + op);
    EXPECT_TRUE(s->contains(dvec3(0.5, 0.5, 0.5))) << op;
    EXPECT_FALSE(s->contains(dvec3(1.5, 1, 1))) << op;
  }
  SolidPtr holes = solidOf(
      "local holes = {}\n"
      "for i = 1, 5 do holes[i] = sphere(0.1):translate(i, 0, 0) end\n"
      "return union(sphere(0.1), holes)");
  EXPECT_EQ(treeStats(*holes).primitives, 6);
  EXPECT_EQ(treeStats(*holes).booleans, 1);
  EXPECT_NE(scriptError("return difference(box(1), {sphere(1), 3})")
                .find("part.lua:1: difference: operand 2[2] must be a solid, got number"),
            std::string::npos);
  EXPECT_NE(scriptError("return union{box(1), {sphere(1)}}")
                .find("part.lua:1: union: operand 2 must be a solid, got table"),
            std::string::npos);
  SolidPtr nary =
      solidOf("return union(sphere(1), sphere(1):translate(3,0,0), sphere(1):translate(6,0,0))");
  EXPECT_EQ(treeStats(*nary).primitives, 3);
  EXPECT_EQ(treeStats(*nary).booleans, 1);
}

// OpenSCAD's convexity, a hint for its preview, is taken and changes
// nothing, on sweeps as on polyhedra.
TEST(Script, ConvexityIsAcceptedAndIgnored) {
  EXPECT_EQ(solidOf("return linear_extrude{circle(5), height=10, convexity=10}")->bounds().hi,
            solidOf("return linear_extrude{circle(5), height=10}")->bounds().hi);
  EXPECT_EQ(solidOf("return rotate_extrude{circle(1):translate(5, 0), convexity=4}")->bounds().hi,
            solidOf("return rotate_extrude{circle(1):translate(5, 0)}")->bounds().hi);
}

TEST(Script, TransformsCompose) {
  // Rotate 90° about z, then translate: (1, 0, 0) goes to (0, 1, 0) + (10, 0, 0).
  SolidPtr s =
      solidOf("return sphere(0.5):translate(1, 0, 0):rotate(0, 0, 90):translate{10, 0, 0}");
  EXPECT_TRUE(s->contains(dvec3(10, 1, 0)));
  EXPECT_FALSE(s->contains(dvec3(11, 0, 0)));
  SolidPtr axis = solidOf("return box(1):rotate{angle=180, axis={0, 0, 1}}");
  EXPECT_TRUE(axis->contains(dvec3(-0.5, -0.5, 0.5)));
  // One angle turns about z, as OpenSCAD's rotate(a) and a region's
  // rotate(a) do (a flat plate stays flat), and so does angle= alone.
  for (const char* turn : {"rotate(90)", "rotate{angle=90}"}) {
    SolidPtr plate = solidOf(std::string("return box{size={20, 10, 2}}:") + turn);
    EXPECT_TRUE(plate->contains(dvec3(-5, 15, 1))) << turn;
    EXPECT_FALSE(plate->contains(dvec3(15, 5, 1))) << turn;
    EXPECT_EQ(plate->bounds().hi.z, 2.0) << turn;
  }
  // OpenSCAD's translate([x, y]): z is 0.
  for (const char* move : {"translate(3, 4)", "translate{3, 4}"}) {
    SolidPtr moved = solidOf(std::string("return box(1):") + move);
    EXPECT_EQ(moved->bounds().lo, dvec3(3, 4, 0)) << move;
  }
  SolidPtr mirrored = solidOf("return box(1):mirror(1, 0, 0)");
  EXPECT_TRUE(mirrored->contains(dvec3(-0.5, 0.5, 0.5)));
  SolidPtr scaled = solidOf("return sphere(1):scale(2, 1, 1)");
  EXPECT_TRUE(scaled->contains(dvec3(1.9, 0, 0)));
  EXPECT_FALSE(scaled->contains(dvec3(0, 1.1, 0)));
  SolidPtr m = solidOf("return sphere(1):transform{{1,0,0,5},{0,1,0,0},{0,0,1,0}}");
  EXPECT_TRUE(m->contains(dvec3(5.9, 0, 0)));
}

TEST(Script, MaterialGoesToPrimitivesWithoutOne) {
  SolidPtr s = solidOf(R"(
    local red = sphere(1):material{color={1, 0, 0}}
    return (red + sphere(1):translate(3, 0, 0)):material{color={0, 0, 1}})");
  auto* node = dynamic_cast<const Boolean*>(s.get());
  ASSERT_NE(node, nullptr);
  auto* first = dynamic_cast<const Primitive*>(node->children()[0].get());
  auto* second = dynamic_cast<const Primitive*>(node->children()[1].get());
  ASSERT_TRUE(first && second && first->material() && second->material());
  EXPECT_EQ(first->material()->color, dvec3(1, 0, 0));
  EXPECT_EQ(second->material()->color, dvec3(0, 0, 1));
}

TEST(Script, SceneWithCameraAndLights) {
  Scene scene = runScript(R"(
    return scene{
      objects = {sphere(1), box(1)},
      camera = camera{eye={0, -10, 0}, look_at={0, 0, 0}, fov=30},
      lights = {point_light{pos={5, -5, 5}, color={1, 0.5, 0.25}, intensity=2}},
      background = {0.1, 0.2, 0.3},
    })",
                          "scene.lua");
  EXPECT_EQ(scene.objects.size(), 2u);
  ASSERT_TRUE(scene.camera.has_value());
  EXPECT_EQ(scene.camera->fovDegrees, 30.0);
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0].intensity, 2.0);
  EXPECT_EQ(scene.lights[0].color, dvec3(1, 0.5, 0.25));
  EXPECT_EQ(scene.background, dvec3(0.1, 0.2, 0.3));
}

TEST(Script, DefinesSetGlobals) {
  ScriptOptions options;
  options.defines = {{"radius", "3"}, {"hollow", "true"}, {"label", "\"abc\""}};
  SolidPtr s = solidOf(R"(
    assert(label == "abc" and hollow == true)
    return sphere(radius))",
                       options);
  EXPECT_NEAR(s->bounds().hi.x, 3.0, 1e-6);
  options.defines = {{"not a name", "1"}};
  EXPECT_NE(scriptError("return sphere(1)", options).find("not a valid Lua name"),
            std::string::npos);
  // A name given twice says so (it once said the name was built in).
  options.defines = {{"width", "20"}, {"width", "30"}};
  EXPECT_NE(scriptError("return sphere(1)", options).find("'width' is given twice"),
            std::string::npos)
      << scriptError("return sphere(1)", options);
}

// Every error names the file and the line of the call that failed.
TEST(Script, ErrorsNameFileAndLine) {
  struct Case {
    const char* source;
    const char* expected;
  } cases[] = {
      {"local a = 1\nreturn sphere{r=-1}", "part.lua:2: sphere: r must be > 0 (got -1)"},
      {"\n\nreturn sphere{r=0/0}", "part.lua:3: sphere: r must be finite"},
      {"return box{size={1, 0, 1}}", "part.lua:1: box: size y must be a positive"},
      {"return sphere{radius=1}",
       "part.lua:1: sphere: unknown parameter 'radius'; did you mean 'r'?"},
      // Other tools' names for a parameter, and typos.
      {"return camera{angle=60}",
       "part.lua:1: camera: unknown parameter 'angle'; did you mean 'fov'?"},
      {"return spot_light{pos={0, 0, 1}, tightness=2}",
       "spot_light: unknown parameter 'tightness'; did you mean 'exponent'?"},
      {"return linear_extrude{circle(5), height=10, slices=20}",
       "linear_extrude: unknown parameter 'slices'; OpenSCAD's slices is not needed here"},
      {"return linear_extrude{box(3), height=2}",
       "linear_extrude: the table's first value must be a region, not a solid"},
      // POV-Ray's names.
      {"return sphere(1):material{pigment={1, 0, 0}}",
       "material: unknown parameter 'pigment'; did you mean 'color'?"},
      {"return sphere(1):material{texture=checker{}}",
       "material: unknown parameter 'texture'; did you mean 'color'?"},
      {"return sphere(1):material{phong_size=40}",
       "material: unknown parameter 'phong_size'; did you mean 'shininess'?"},
      {"return scene{objects={box(1)}, lights={point_light{location={1, 2, 3}}}}",
       "point_light: unknown parameter 'location'; did you mean 'pos'?"},
      {"return scene{objects={box(1)}, lights={spot_light{pos={1, 2, 3}, falloff=25}}}",
       "POV-Ray's falloff angle of a spot is angle= here"},
      {"return light_source{}", "POV-Ray's light_source is point_light{pos={x, y, z}} here"},
      {"return sphere{center={1, 2, 3}, r=1}",
       "sphere: unknown parameter 'center'; shapes are made at the origin here and placed with "
       ":translate(x, y, z)"},
      {"return cylinder{base={0, 0, 0}, cap={0, 0, 1}, r=1}", "shapes are made at the origin here"},
      {"return box(1):material{color={1, 0, 0, 0.9}}",
       "a fourth number (OpenSCAD's alpha, POV-Ray's filter or transmit) is transparency= here"},
      {"return scene{objects=box(1), fog={color={1, 1, 1, 0.5}, distance=5}}",
       "scene: fog: color must be {r, g, b}: a fourth number (alpha, filter or transmit) has no "
       "meaning here"},
      {"return scene{objects=box(1), fog={color={1, 1, 1}, distance=5, fog_type=2}}",
       "scene: fog: unknown parameter 'fog_type'; ground fog (POV-Ray's fog_type 2) is given by "
       "offset= and altitude= here"},
      {"return scene{objects=box(1), fog={color={1, 1, 1}, distance=5, fog_alt=2}}",
       "scene: fog: unknown parameter 'fog_alt'; did you mean 'altitude'?"},
      {"return box(1):material{bump_map=perlin{}}",
       "material: unknown parameter 'bump_map'; did you mean 'bumps'?"},
      {"return scene{objects=box(1), sky_sphere=gradient{}}",
       "scene: unknown parameter 'sky_sphere'; did you mean 'background'?"},
      {"return perlin{color_map={'red', 'blue'}}",
       "perlin: unknown parameter 'color_map'; did you mean 'colors'?"},
      {"return scene{objects=box(1), camera=camera{aperture=1, confidence=0.9}}",
       "camera: unknown parameter 'confidence'; did you mean 'blur_samples'?"},
      {"return fog{color={1, 1, 1}}", "fog is a scene's: scene{..., fog={color={r, g, b}"},
      {"return sky_sphere{}", "POV-Ray's sky_sphere is a scene's background texture here"},
      {"return wrinkles{}", "there is no wrinkles pattern: material{bumps=turbulence{}}"},
      {"return sphere(1) - plane{}", "the solid side of a plane is half_space{normal=...}"},
      {"return box(1):rotate{a=45}", "rotate: unknown parameter 'a'; did you mean 'angle'?"},
      {"return sphere(1):material{colour={1, 0, 0}}",
       "material: unknown parameter 'colour'; did you mean 'color'?"},
      {"return cylinder{r=1, h=1, centre=true}",
       "cylinder: unknown parameter 'centre'; did you mean 'center'?"},
      // A value of csgray's is named by its kind, not Lua's "userdata".
      {"return sphere{r=box(1)}", "part.lua:1: sphere: r must be a number, got a solid"},
      {"return scene{objects={sphere(1), point_light{pos={0, 0, 5}}}}",
       "part.lua:1: scene: objects[2] (a solid, a surface or a region) must be a solid, got a "
       "light: lights go in scene{lights={...}}"},
      {"return scene{objects={sphere(1)}, lights={sphere(1)}}",
       "part.lua:1: scene: lights[1] must be a light, got a solid: solids go in "
       "scene{objects={...}}"},
      {"return camera{{0, 0, 0}, fov=30}", "part.lua:1: camera: unexpected value without a name"},
      {"return box{1, 2, 3, center=true}", "part.lua:1: box: unexpected value without a name"},
      {"math.randomseed()", "part.lua:1: math.randomseed needs a seed"},
      {"return cylinder{r=1}", "part.lua:1: cylinder: needs h"},
      {"return cone{h=1, r1=0, r2=0}", "part.lua:1: cone: radii must be >= 0 and not both 0"},
      {"return box(1):scale(1, 0, 1)", "part.lua:1: transform is singular"},
      {"return sphere(1) + 3", "part.lua:1: operand of '+' must be a solid, got number"},
      {"return union()", "part.lua:1: union: needs at least one solid"},
      // A variable never set is nil: named as such.
      {"return sphere(radius_mm)",
       "part.lua:1: sphere: got nil (a variable without a value?) where r or a table of "
       "parameters goes"},
      {"local w = 2\nreturn box{size={w, 2 * w, depth}}",
       "part.lua:2: box: size must be a list of three numbers {x, y, z}, got a list of 2 (is a "
       "value in it nil?)"},
      {"local bosses = {}\nreturn box(10) + union(bosses)",
       "part.lua:2: union: the list is empty; there is no empty solid, so leave the union out "
       "when the list is (if #list > 0 then ... end)"},
      {"return quadric{matrix={{1,2,0,0},{0,1,0,0},{0,0,1,0},{0,0,0,-1}}}",
       "part.lua:1: quadric: matrix must be symmetric"},
      {"return camera{eye={0,0,0}, look_at={0,0,0}}", "part.lua:1: camera: eye and look_at"},
      {"x = = 1", "part.lua:1:"},
      {"error('custom')", "part.lua:1: custom"},
      {"local s = sphere(1)", "part.lua: the script returned nothing"},
      {"return 42",
       "part.lua: the script must return a solid, a surface, a region or scene{...}, not "
       "number"},
      {"return scene{objects={}}", "part.lua:1: scene: objects is empty"},
      {"return scene{objects={sphere(1)}, lights={42}}",
       "part.lua:1: scene: lights[1] must be a light, got number"},
  };
  for (const Case& c : cases)
    EXPECT_NE(scriptError(c.source).find(c.expected), std::string::npos)
        << c.source << "\n  gave: " << scriptError(c.source);
}

// Drilling holes one at a time builds a flat node, not a 10 000-deep chain
// that would overflow the stack when traced or destroyed.
TEST(Script, ChainsOfOneOperationStayFlat) {
  SolidPtr s = solidOf(R"(
    local part = box{size={100, 100, 10}}
    for i = 0, 99 do for j = 0, 99 do
      part = part - cylinder{r=0.2, h=20}:translate(0.5 + i, 0.5 + j, -5)
    end end
    return part)");
  EXPECT_EQ(s->depth(), 1);
  EXPECT_EQ(treeStats(*s).primitives, 10001u);
  EXPECT_FALSE(s->contains(dvec3(50.5, 50.5, 5)));
  EXPECT_TRUE(s->contains(dvec3(50, 50, 5)));
}

TEST(Script, DeepAndExplodingTreesAreRefused) {
  // Alternating operations cannot be flattened.
  std::string e;
  EXPECT_NE(scriptError("local a = sphere(1)\n"
                        "for i = 1, 2000 do a = (a + sphere(1)) * box(5) end return a")
                .find("boolean tree deeper than 1000 levels; build long chains"),
            std::string::npos);
  // Marks on marks, and 2D booleans that alternate, nest as deep: they
  // overflowed the stack at 20 000 levels.
  e = scriptError("local s = sphere(1)\nfor i = 1, 20000 do s = s:highlight() end\nreturn s");
  EXPECT_EQ(e, "part.lua:2: highlight: tree deeper than 1000 levels") << e;
  e = scriptError(
      "local r = circle(1)\nfor i = 1, 20000 do\n"
      "  if i % 2 == 0 then r = r + square(1):translate(i, 0) else r = r - square(0.5) end\n"
      "end\nreturn linear_extrude{r, height=1}");
  EXPECT_EQ(e,
            "part.lua:3: 2D boolean tree deeper than 1000 levels; build long chains with "
            "union(list) or difference(a, list)")
      << e;
  // Under a thousand levels, both are made.
  EXPECT_NO_THROW(
      runScript("local s = sphere(1)\nfor i = 1, 900 do s = s:highlight() end\n"
                "return s",
                "part.lua"));
  // A shared part used 2^40 times: the count multiplies out.
  e = scriptError("local a = sphere(1)\nfor i = 1, 40 do a = a + a end return a");
  EXPECT_NE(e.find("part.lua:2: union: the part would have more than 2000000 primitives"),
            std::string::npos)
      << e;
}

TEST(Script, CollectedSolidsGiveBackTheirMemory) {
  ScriptOptions options;
  options.limits.memoryBytes = 64u << 20;
  // 2 million solids in all, never more than one alive: far over the cap
  // if collected solids were still counted.
  EXPECT_NO_THROW(runScript("for i = 1, 2000000 do local s = sphere(1) end return sphere(1)",
                            "churn.lua", options));
  // A material copies the tree: 100 painted copies of a 10 000-sphere part
  // do not fit.
  options.limits.memoryBytes = 256u << 20;
  std::string e;
  try {
    runScript(R"(
      local t = {} for i = 1, 10000 do t[i] = sphere(1):translate(i, 0, 0) end
      local part, copies = union(t), {}
      for i = 1, 100 do copies[i] = part:material{color = {1, 0, i / 100}} end
      return union(copies))",
              "copies.lua", options);
  } catch (const ScriptError& error) {
    e = error.what();
  }
  EXPECT_NE(e.find("script exceeded the memory limit of 256 MiB"), std::string::npos) << e;
  // A transform shares it: 100 moved uses of the part fit, a million
  // spheres by use.
  Scene shared = runScript(R"(
      local t = {} for i = 1, 10000 do t[i] = sphere(1):translate(i, 0, 0) end
      local part, uses = union(t), {}
      for i = 1, 100 do uses[i] = part:translate(0, i, 0) end
      return union(uses))",
                           "uses.lua", options);
  ASSERT_EQ(shared.objects.size(), 1u);
  EXPECT_EQ(shared.objects[0]->primitiveCount(), 1'000'000u);
}

TEST(Script, MissingFileIsAClearError) {
  try {
    runScriptFile("/nonexistent/part.lua");
    FAIL() << "no error";
  } catch (const ScriptError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/part.lua: cannot open script"),
              std::string::npos);
  }
}

TEST(Script, RandomNumbersAreReproducible) {
  const char* source = "return sphere(1 + math.random())";
  double a = solidOf(source)->bounds().hi.x;
  double b = solidOf(source)->bounds().hi.x;
  EXPECT_EQ(a, b);
}

// A call of a name csgray lacks says what it is called here: OpenSCAD's
// names, or the nearest global function's, method's or library function's
// for a typo. Reading an unset
// global (a -D parameter's default) is no error, and a name far from any
// function gets Lua's message alone.
TEST(Script, AnUnknownFunctionSaysWhatItIsCalledHere) {
  EXPECT_EQ(scriptError("return cube(1)"),
            "part.lua:1: attempt to call a nil value (global 'cube'); OpenSCAD's cube is "
            "box{size={x, y, z}} (or box(s)) here");
  EXPECT_NE(scriptError("return translate(1, 0, 0)")
                .find("; transforms are methods of a solid "
                      "here: s:translate(...)"),
            std::string::npos);
  EXPECT_NE(scriptError("return color(1)").find("s:material{color={r, g, b}}"), std::string::npos);
  EXPECT_EQ(scriptError("return sphre(1)"),
            "part.lua:1: attempt to call a nil value (global 'sphre'); did you mean sphere?");
  EXPECT_NE(scriptError("return dodecahedrn{r=1}").find("did you mean dodecahedron?"),
            std::string::npos);
  EXPECT_EQ(scriptError("return frobnicate(1)"),
            "part.lua:1: attempt to call a nil value (global 'frobnicate')");
  EXPECT_EQ(scriptError("return sphere(1):translat(1, 0, 0)"),
            "part.lua:1: attempt to call a nil value (method 'translat'); did you mean "
            "translate?");
  EXPECT_NE(scriptError("return sphere(1):materal{color={1, 0, 0}}").find("did you mean material?"),
            std::string::npos);
  EXPECT_EQ(scriptError("return sphere(math.sine(1))"),
            "part.lua:1: attempt to call a nil value (field 'sine'); did you mean math.sin?");
  EXPECT_NE(scriptError("local t = {}\ntable.insrt(t, 1)\nreturn sphere(1)")
                .find("did you mean table.insert?"),
            std::string::npos);
  EXPECT_EQ(scriptError("return sphere(math.frobnicate(1))"),
            "part.lua:1: attempt to call a nil value (field 'frobnicate')");
  EXPECT_EQ(scriptError("return sphere(1):frobnicate()"),
            "part.lua:1: attempt to call a nil value (method 'frobnicate')");
  EXPECT_EQ(scriptError("return sphere{r=1, frobnicate=2}"),
            "part.lua:1: sphere: unknown parameter 'frobnicate'");
  // A function called as a method says how it is called; so do other
  // tools' habits on a part.
  EXPECT_EQ(scriptError("return sphere(1):union(box(1))"),
            "part.lua:1: attempt to call a nil value (method 'union'); union is a function "
            "here, not a method: union(s, t) or s + t");
  EXPECT_NE(scriptError("return sphere(1):hull(box(1))")
                .find("; hull is a function here, not a method: hull(s, ...)"),
            std::string::npos);
  EXPECT_NE(scriptError("return sphere(1):color{1, 0, 0}").find("; a colour is a material here"),
            std::string::npos);
  EXPECT_NE(scriptError("return sphere(1):texture{}").find("s:material{color=checker{...}}"),
            std::string::npos);
  // Two edits from a short name make another word ("wood" of "load"); the
  // libraries the sandbox leaves out are said to be left out.
  EXPECT_EQ(scriptError("return loop(1)"),
            "part.lua:1: attempt to call a nil value (global 'loop')");
  EXPECT_NE(scriptError("return sqar(1)").find("did you mean square?"), std::string::npos);
  EXPECT_EQ(scriptError("return load(\"x\")"),
            "part.lua:1: attempt to call a nil value (global 'load'); load is not available: "
            "scripts run in a sandbox, without files, processes or loaded code (docs/script.md, "
            "\"The sandbox\")");
  for (const char* use : {"io.open(\"part.stl\")", "os.execute(\"ls\")", "require(\"x\")",
                          "dofile(\"x.lua\")", "debug.getinfo(1)"})
    EXPECT_NE(scriptError(std::string("local x = ") + use + "\nreturn sphere(1)")
                  .find("is not available: scripts run in a sandbox"),
              std::string::npos)
        << use;
  EXPECT_NO_THROW(solidOf("local r = radius or 2\nreturn sphere(r)"));
}

// An argument too many is an error at every function and method of the
// API, never ignored: sphere(1, 2) is not a sphere of radius 1.
TEST(Script, ExtraArgumentsAreErrors) {
  for (const char* function : {"sphere",
                               "ellipsoid",
                               "box",
                               "cylinder",
                               "cone",
                               "half_space",
                               "quadric",
                               "torus",
                               "hyperboloid1",
                               "hyperboloid2",
                               "elliptic_cone",
                               "elliptic_paraboloid",
                               "hyperbolic_paraboloid",
                               "elliptic_cylinder",
                               "hyperbolic_cylinder",
                               "parabolic_cylinder",
                               "tetrahedron",
                               "hexahedron",
                               "octahedron",
                               "dodecahedron",
                               "icosahedron",
                               "convex",
                               "polyhedron",
                               "mesh",
                               "checker",
                               "image_texture",
                               "perlin",
                               "turbulence",
                               "marble",
                               "wood",
                               "plane",
                               "disc",
                               "triangle",
                               "parallelogram",
                               "rectangle",
                               "square",
                               "point_light",
                               "spot_light",
                               "area_light",
                               "sphere_light",
                               "camera",
                               "scene"}) {
    EXPECT_EQ(scriptError(std::string("local x = 1\nreturn ") + function + "({}, 2)"),
              std::string("part.lua:2: ") + function + ": takes 1 argument (got 2)");
  }
  struct Case {
    const char* source;
    const char* expected;
  } cases[] = {
      {"return sphere(1, 2)", "part.lua:1: sphere: takes 1 argument (got 2)"},
      {"return box({1, 2, 3}, true)", "part.lua:1: box: takes 1 argument (got 2)"},
      {"return tetrahedron(1, 2)", "part.lua:1: tetrahedron: takes 1 argument (got 2)"},
      {"return check(sphere(1), {}, 3)", "part.lua:1: check: takes 2 arguments (got 3)"},
      {"return sphere(1):material({}, 1)", "part.lua:1: material: takes 1 argument (got 2)"},
      {"return plane{}:material({}, 1)", "part.lua:1: material: takes 1 argument (got 2)"},
      {"local lo, hi = sphere(1):bounds(0)", "part.lua:1: bounds: takes no arguments (got 1)"},
      {"return sphere(1):transform({{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}, 1)",
       "part.lua:1: transform: takes 1 argument (got 2)"},
      {"return sphere(1):translate(1, 2, 3, 4)",
       "part.lua:1: translate: takes x, y, z or {x, y, z} (got 4 arguments)"},
      {"return plane{}:rotate(1, 2)",
       "part.lua:1: rotate: takes x, y, z or {x, y, z} (got 2 arguments)"},
      {"return sphere(1):scale({1, 1, 1}, 2)",
       "part.lua:1: scale: takes x, y, z or {x, y, z} (got 2 arguments)"},
      {"local inside = sphere(1):contains(0, 0, 0, 0)",
       "part.lua:1: contains: takes x, y, z or {x, y, z} (got 4 arguments)"},
  };
  for (const Case& c : cases) EXPECT_EQ(scriptError(c.source), c.expected) << c.source;
}

// A mistake is told in one line that names the script's line and says
// what the script did in the API's words, not what Lua saw.
TEST(Script, MistakesAreSaidInTheApisWords) {
  struct Case {
    const char* source;
    const char* expected;
  } cases[] = {
      {"setmetatable(1, {})",
       "part.lua:1: setmetatable: the first argument must be a table, got number"},
      {"local s = sphere(1)\nsetmetatable(s, {})",
       "part.lua:2: setmetatable: a solid cannot take a metatable; only a table can"},
      {"setmetatable({}, 1)",
       "part.lua:1: setmetatable: the metatable must be a table or nil, got number"},
      {"setmetatable(setmetatable({}, {__metatable = 'locked'}), {})",
       "part.lua:1: setmetatable: the table's metatable is protected (it has __metatable)"},
      {"setmetatable({})",
       "part.lua:1: setmetatable takes 2 arguments, a table and a metatable or nil (got 1)"},
      // Through pcall, which is a C function too, the line is the script's.
      {"local ok, e = pcall(setmetatable, 1, {})\nerror(e, 0)",
       "part.lua:1: setmetatable: the first argument must be a table, got number"},
      {"math.randomseed('x')",
       "part.lua:1: math.randomseed: the seed must be a whole number, got string"},
      {"math.randomseed(1.5)",
       "part.lua:1: math.randomseed: the seed must be a whole number, got 1.5"},
      {"return plane{}:bounds()",
       "part.lua:1: bounds: a plane is a surface, not a solid, and bounds is a method of solids "
       "only"},
      {"local inside = disc{r=1}:contains(0, 0, 0)",
       "part.lua:1: contains: a disc is a surface, not a solid, and contains is a method of "
       "solids only"},
      {"local s = sphere(1)\nlocal inside = s.contains(square{size=1}, 0, 0, 0)",
       "part.lua:2: contains: the receiver (call it as s:contains(...)) must be a solid, not a 2D "
       "region (a square): it has no volume until it is extruded (linear_extrude, "
       "rotate_extrude)"},
      {"local s = sphere(1)\nlocal inside = s.contains(square{size=1}:translate(0, 0, 1), 0, 0, 0)",
       "part.lua:2: contains: a square is a surface, not a solid, and contains is a method of "
       "solids only"},
      {"local inside = sphere(1):contains(0/0)", "part.lua:1: contains: point must be finite"},
      {"local inside = sphere(1):contains(0, 0/0, 0)", "part.lua:1: contains: y must be finite"},
      {"local inside = sphere(1):contains{0, 0, 1/0}",
       "part.lua:1: contains: point[3] must be finite"},
      {"return check(plane{})",
       "part.lua:1: check: the first argument must be a solid, but a plane is a surface: it "
       "encloses no volume, so it cannot be checked as a part"},
  };
  for (const Case& c : cases) EXPECT_EQ(scriptError(c.source), c.expected) << c.source;
}

// A name or a value of the script's shows as at most 60 characters in a
// message, however long the script made it, and a message the script
// makes endless is cut.
TEST(Script, LongNamesAreCutInMessages) {
  const std::string name(100000, 'y');
  const std::string shown = std::string(57, 'y') + "...";
  ScriptOptions options;
  options.loadMesh = [](const std::string&, bool, std::string&) -> TriangleMesh { return {}; };
  const std::pair<std::string, std::string> cases[] = {
      {"return sphere{" + name + "=1}", "part.lua:1: sphere: unknown parameter '" + shown + "'"},
      {"return " + name + "(1)",
       "part.lua:1: attempt to call a nil value (global '" + shown + "')"},
      {"return sphere(1):" + name + "()",
       "part.lua:1: attempt to call a nil value (method '" + shown + "')"},
      {"return math." + name + "(1)",
       "part.lua:1: attempt to call a nil value (field '" + shown + "')"},
      {"return 1 + " + name,
       "part.lua:1: attempt to perform arithmetic on a nil value (global '" + shown + "')"},
      {"local t = {}\nt[string.rep('y', 1e5)] = 1\nreturn sphere(t)",
       "part.lua:3: sphere: unknown parameter '" + shown + "'"},
      {"return image_texture{file='a.png', mapping='" + name + "'}",
       "part.lua:1: image_texture: mapping must be \"planar\", \"spherical\", \"cylindrical\" or "
       "\"box\", got \"" +
           shown + "\""},
      {"return mesh{file='" + name + "'}",
       "part.lua:1: mesh: cannot use the file name \"" + shown + "\": File name too long"},
  };
  for (const auto& [source, expected] : cases)
    EXPECT_EQ(scriptError(source, options), expected) << expected;
  std::string e = scriptError("error(string.rep('x', 1e5))");
  EXPECT_TRUE(e.starts_with("part.lua:1: xxx")) << e.substr(0, 100);
  EXPECT_LE(e.size(), 2000u);
}

// error() with a value that is not a string names the line that raised it,
// as Lua names the line of error("text"); the scripts' own pcall is not
// touched.
TEST(Script, ErrorsWithoutAMessageNameTheirLine) {
  EXPECT_EQ(scriptError("local x = 1\nerror()"), "part.lua:2: error(nil) without a message");
  EXPECT_EQ(scriptError("local t = {}\n\nerror(t)"), "part.lua:3: error(table) without a message");
  EXPECT_EQ(scriptError("local function f() error(sphere(1)) end\nf()"),
            "part.lua:1: error(userdata) without a message");
  EXPECT_EQ(scriptError("local ok, e = pcall(error, {})\nerror(type(e))"), "part.lua:2: table");
  // Nor do a number, and a text raised without its position (level 0).
  EXPECT_EQ(scriptError("local x = 1\nerror(42)"), "part.lua:2: 42");
  EXPECT_EQ(scriptError("local x = 1\n\nerror('bad width', 0)"), "part.lua:3: bad width");
  EXPECT_EQ(scriptError("local function f() error('deep', 0) end\nf()"), "part.lua:1: deep");
  // A text with its position keeps it, once.
  EXPECT_EQ(scriptError("local x = 1\nerror('part.lua:9: said so', 0)"), "part.lua:9: said so");
}

// Brackets nested past the parser's limit (200 levels), which Lua reports
// without a position, name the line the parser was reading.
TEST(Script, BracketsNestedTooDeeplyNameTheirLine) {
  const std::string deep = std::string(300, '(') + "1" + std::string(300, ')');
  const std::string message = " C stack overflow (brackets, calls or tables nested too deeply)";
  EXPECT_EQ(scriptError("local x = 1\nlocal y = " + deep + "\nreturn box(1)"),
            "part.lua:2:" + message);
  // One bracket a line: the limit is reached on line 200 (the first line
  // is the assignment with none).
  std::string lines = "local y =\n";
  for (int i = 0; i < 300; ++i) lines += "(\n";
  EXPECT_EQ(scriptError(lines + "1" + std::string(300, ')')), "part.lua:200:" + message);
  // Nesting within the limit runs.
  EXPECT_EQ(
      scriptError("local y = " + std::string(150, '{') + std::string(150, '}') + "\nreturn box(1)"),
      "(no error)");
}

}  // namespace
}  // namespace csgray::detail
