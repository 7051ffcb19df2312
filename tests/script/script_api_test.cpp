// The script API beyond solids (docs/script.md: Materials, Textures, Open
// surfaces, Lights and shadows, Scenes): every parameter lands where the
// renderer reads it, defaults hold when it is absent, and every bad value
// stops the script with one "file:line: message" error.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <glm/geometric.hpp>
#include <optional>
#include <string>
#include <vector>

#include "engine/boolean.h"
#include "engine/instance.h"
#include "engine/primitive.h"
#include "io/image_file.h"
#include "io/scratch_folder.h"
#include "script/script.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

namespace fs = std::filesystem;
using test::expectVecNear;
using test::scriptError;

Scene sceneOf(const std::string& source, const ScriptOptions& options = {}) {
  return runScript(source, "part.lua", options);
}

// The error of source must contain expected (which names the file and line).
void expectError(const std::string& source, const std::string& expected,
                 const ScriptOptions& options = {}) {
  std::string e = scriptError(source, options);
  EXPECT_NE(e.find(expected), std::string::npos) << source << "\n  gave: " << e;
}

// The one solid a script returns, which must be a primitive.
std::shared_ptr<const Primitive> primitiveOf(const std::string& source,
                                             const ScriptOptions& options = {}) {
  Scene scene = sceneOf(source, options);
  EXPECT_EQ(scene.objects.size(), 1u);
  EXPECT_TRUE(scene.surfaces.empty());
  auto p = std::dynamic_pointer_cast<const Primitive>(scene.objects.at(0));
  EXPECT_NE(p, nullptr) << source;
  return p;
}

// The material of sphere(1):material{args}.
MaterialPtr materialOf(const std::string& args, const ScriptOptions& options = {}) {
  auto p = primitiveOf("return sphere(1):material{" + args + "}", options);
  if (!p) return nullptr;
  EXPECT_NE(p->material(), nullptr) << args;
  return p->material();
}

// The texture of sphere(1):material{color=expression}.
TexturePtr textureOf(const std::string& expression, const ScriptOptions& options = {}) {
  MaterialPtr m = materialOf("color=" + expression, options);
  if (!m) return nullptr;
  EXPECT_NE(m->texture, nullptr) << expression;
  return m->texture;
}

// The one surface a script returns.
SurfacePtr surfaceOf(const std::string& source) {
  Scene scene = sceneOf(source);
  EXPECT_TRUE(scene.objects.empty()) << source;
  EXPECT_EQ(scene.surfaces.size(), 1u) << source;
  return scene.surfaces.empty() ? nullptr : scene.surfaces[0];
}

// The lights of scene{objects=sphere(1), lights={list}}.
std::vector<Light> lightsOf(const std::string& list) {
  return sceneOf("return scene{objects=sphere(1), lights={" + list + "}}").lights;
}

// Points spread over a region, none on a lattice plane.
std::vector<dvec3> samplePoints() {
  std::vector<dvec3> points;
  for (int i = 0; i < 40; ++i)
    points.emplace_back(-7.3 + 0.731 * i, 5.17 - 0.413 * i, 0.29 * i - 3.1);
  return points;
}

// ---- Materials --------------------------------------------------------------

TEST(ScriptMaterial, EveryKeyLandsInTheMaterial) {
  MaterialPtr m = materialOf(
      "color={0.1, 0.2, 0.3}, ambient=0.25, diffuse=0.5, specular=0.75, shininess=60, "
      "reflection=0.3, transparency=0.6, filter={0.9, 0.8, 0.7}, ior=1.5, fresnel=true");
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->color, dvec3(0.1, 0.2, 0.3));
  EXPECT_EQ(m->texture, nullptr);
  EXPECT_EQ(m->ambient, 0.25);
  EXPECT_EQ(m->diffuse, 0.5);
  EXPECT_EQ(m->specular, 0.75);
  EXPECT_EQ(m->shininess, 60.0);
  EXPECT_EQ(m->reflection, 0.3);
  EXPECT_EQ(m->transparency, 0.6);
  EXPECT_EQ(m->filter, dvec3(0.9, 0.8, 0.7));
  EXPECT_EQ(m->ior, 1.5);
  EXPECT_TRUE(m->fresnel);
  EXPECT_TRUE(m->refracts());
}

// bumps= takes any texture as its height field.
TEST(ScriptMaterial, Bumps) {
  MaterialPtr m = materialOf("bumps=perlin{scale=0.2}, bump_depth=-0.05");
  ASSERT_NE(m, nullptr);
  ASSERT_NE(m->bumps, nullptr);
  EXPECT_EQ(m->texture, nullptr);
  EXPECT_EQ(m->bumpDepth, -0.05);
  m = materialOf("color=checker{}, bumps=marble{}");
  ASSERT_NE(m, nullptr);
  EXPECT_NE(m->bumps, nullptr);
  EXPECT_NE(m->texture, nullptr);
  EXPECT_EQ(m->bumpDepth, 0.1);
  EXPECT_EQ(materialOf("")->bumps, nullptr);
}

TEST(ScriptMaterial, DefaultsWhenAbsent) {
  MaterialPtr m = materialOf("");
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->color, dvec3(0.8, 0.8, 0.8));
  EXPECT_EQ(m->texture, nullptr);
  EXPECT_EQ(m->ambient, 0.1);
  EXPECT_EQ(m->diffuse, 0.9);
  EXPECT_EQ(m->specular, 0.0);
  EXPECT_EQ(m->shininess, 20.0);
  EXPECT_EQ(m->reflection, 0.0);
  EXPECT_EQ(m->transparency, 0.0);
  EXPECT_EQ(m->filter, dvec3(1.0));
  EXPECT_EQ(m->ior, 1.0);
  EXPECT_FALSE(m->fresnel);
  // One key leaves the others at their defaults.
  m = materialOf("specular=0.4");
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->specular, 0.4);
  EXPECT_EQ(m->color, dvec3(0.8));
  EXPECT_EQ(m->diffuse, 0.9);
  EXPECT_EQ(m->shininess, 20.0);
  // A single number is a grey.
  m = materialOf("color=0.5, filter=0.25");
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->color, dvec3(0.5));
  EXPECT_EQ(m->filter, dvec3(0.25));
  // The bounds of each range are allowed.
  m = materialOf("ambient=0, diffuse=1, reflection=1, transparency=1, ior=10, fresnel=false");
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->ambient, 0.0);
  EXPECT_EQ(m->transparency, 1.0);
  EXPECT_EQ(m->ior, 10.0);
}

TEST(ScriptMaterial, OnABooleanGoesToLeavesWithoutOne) {
  Scene scene = sceneOf(R"(
    local own = box(1):material{color={1, 0, 0}, specular=0.7}
    local bare = sphere(1):translate(3, 0, 0)
    local nested = cylinder{r=1, h=1} - (box(1) + sphere(0.5):material{color={0, 1, 0}})
    return union(own, bare, nested):material{color={0, 0, 1}, shininess=5})");
  ASSERT_EQ(scene.objects.size(), 1u);
  std::vector<const Primitive*> leaves;
  std::function<void(const Solid&)> collect = [&](const Solid& s) {
    if (auto* p = dynamic_cast<const Primitive*>(&s)) leaves.push_back(p);
    for (const SolidPtr& c : s.children()) collect(*c);
  };
  collect(*scene.objects[0]);
  ASSERT_EQ(leaves.size(), 5u);
  std::vector<dvec3> colors;
  for (const Primitive* p : leaves) {
    ASSERT_NE(p->material(), nullptr) << p->kind();
    colors.push_back(p->material()->color);
  }
  // Leaves in order: own box, bare sphere, cylinder, box, green sphere.
  EXPECT_EQ(colors[0], dvec3(1, 0, 0));
  EXPECT_EQ(leaves[0]->material()->specular, 0.7);
  EXPECT_EQ(leaves[0]->material()->shininess, 20.0);  // its own material, untouched
  EXPECT_EQ(colors[1], dvec3(0, 0, 1));
  EXPECT_EQ(leaves[1]->material()->shininess, 5.0);
  EXPECT_EQ(colors[2], dvec3(0, 0, 1));
  EXPECT_EQ(colors[3], dvec3(0, 0, 1));
  EXPECT_EQ(colors[4], dvec3(0, 1, 0));
  // The bare leaves share the one material given.
  EXPECT_EQ(leaves[1]->material(), leaves[2]->material());
}

TEST(ScriptMaterial, OnAPrimitiveReplacesItsMaterial) {
  auto p = primitiveOf("return sphere(1):material{color={1, 0, 0}}:material{diffuse=0.2}");
  ASSERT_TRUE(p && p->material());
  EXPECT_EQ(p->material()->color, dvec3(0.8));  // replaced, not merged
  EXPECT_EQ(p->material()->diffuse, 0.2);
}

TEST(ScriptMaterial, MaterialLeavesTheOriginalAlone) {
  Scene scene = sceneOf(R"(
    local plain = sphere(1)
    local red = plain:material{color={1, 0, 0}}
    return scene{objects={plain, red}})");
  ASSERT_EQ(scene.objects.size(), 2u);
  auto plain = std::dynamic_pointer_cast<const Primitive>(scene.objects[0]);
  auto red = std::dynamic_pointer_cast<const Primitive>(scene.objects[1]);
  ASSERT_TRUE(plain && red);
  EXPECT_EQ(plain->material(), nullptr);
  ASSERT_NE(red->material(), nullptr);
}

TEST(ScriptMaterial, OutOfRangeValuesAreErrors) {
  struct Case {
    const char* args;
    const char* expected;
  } cases[] = {
      {"ambient=1.5", "material: ambient must be in [0, 1]"},
      {"ambient=-0.1", "material: ambient must be in [0, 1]"},
      {"diffuse=2", "material: diffuse must be in [0, 1]"},
      {"specular=-1", "material: specular must be in [0, 1]"},
      {"reflection=1.01", "material: reflection must be in [0, 1]"},
      {"transparency=3", "material: transparency must be in [0, 1]"},
      {"filter_distance=-1", "material: filter_distance must be a finite number >= 0"},
      {"transmitted_specular=2", "material: transmitted_specular must be in [0, 1]"},
      {"ior=0.5", "material: ior must be from 1 to 10"},
      {"ior=11", "material: ior must be from 1 to 10"},
      {"color={1, -0.5, 0}", "material: color components must be >= 0"},
      {"color=-1", "material: color components must be >= 0"},
      {"color={1, 1}", "material: color must be a colour: {r, g, b}, a name"},
      {"color='redd'", "material: color 'redd' is not a colour name (did you mean red?)"},
      {"filter={1, 1.5, 1}", "material: filter components must be in [0, 1]"},
      {"filter={-1, 1, 1}", "material: filter components must be >= 0"},
      {"shininess=0", "material: shininess must be > 0"},
      {"shininess=-5", "material: shininess must be > 0"},
      {"fresnel='yes'", "material: fresnel must be true or false"},
      {"fresnel=1", "material: fresnel must be true or false"},
      {"colour={1, 0, 0}", "material: unknown parameter 'colour'"},
      {"ambient=0/0", "material: ambient must be finite"},
      {"bumps=0.5", "material: bumps must be a texture, such as perlin{scale=0.2}"},
      {"bumps=perlin{}, bump_depth=1/0", "material: bump_depth must be finite"},
      {"normal=perlin{}", "material: unknown parameter 'normal'; did you mean 'bumps'?"},
  };
  for (const Case& c : cases)
    expectError(std::string("local s = sphere(1)\n\nreturn s:material{") + c.args + "}",
                std::string("part.lua:3: ") + c.expected);
  // Also on a boolean, and on a surface.
  expectError("local s = sphere(1) + box(1)\nreturn s:material{ior=0.5}",
              "part.lua:2: material: ior must be from 1 to 10");
  expectError("local s = disc{r=1}\nreturn s:material{ambient=1.5}",
              "part.lua:2: material: ambient must be in [0, 1]");
  expectError("return sphere(1):material(3)",
              "part.lua:1: material: expected a table of named parameters");
}

// ---- Textures ---------------------------------------------------------------

TEST(ScriptTexture, EveryTextureGivesAMaterialWithATexture) {
  for (const char* expression :
       {"checker{}", "checker{size=2, colors={{1, 0, 0}, {0, 0, 1}}}", "perlin{}",
        "perlin{scale=3}", "turbulence{}", "marble{strength=2}", "wood{octaves=16}",
        "checker{scale=3, rotate={10, 20, 30}, translate={1, 2, 3}}", "mandelbrot{}",
        "julia{c={-0.8, 0.156}, iterations=300}", "gradient{}",
        "gradient{colors={'white', 'steelblue'}, from={0, 0, -1}, to={0, 0, 1}}"}) {
    TexturePtr t = textureOf(expression);
    EXPECT_NE(t, nullptr) << expression;
  }
  // A texture is a value: not a colour list, but accepted where a colour is.
  expectError("return sphere(1):material{filter=checker{}}",
              "part.lua:1: material: filter must be a colour: {r, g, b}");
  expectError("return point_light{pos={0, 0, 1}, color=checker{}}",
              "part.lua:1: point_light: color must be a colour: {r, g, b}");
}

TEST(ScriptTexture, PatternsFollowTheirDefinitions) {
  // checker: colour a where the cell parity is even, cubes of edge size.
  TexturePtr c = textureOf("checker{size=2, colors={{1, 0, 0}, {0, 0, 1}}}");
  ASSERT_NE(c, nullptr);
  const dvec3 n(0, 0, 1);
  EXPECT_EQ(c->colorAt({0.5, 0.5, 0.5}, n), dvec3(1, 0, 0));
  EXPECT_EQ(c->colorAt({1.9, 1.9, 1.9}, n), dvec3(1, 0, 0));
  EXPECT_EQ(c->colorAt({2.5, 0.5, 0.5}, n), dvec3(0, 0, 1));
  EXPECT_EQ(c->colorAt({2.5, 2.5, 0.5}, n), dvec3(1, 0, 0));
  EXPECT_EQ(c->colorAt({-0.5, 0.5, 0.5}, n), dvec3(0, 0, 1));
  // perlin: noise is 0 on the integer lattice, halfway between a and b.
  TexturePtr p = textureOf("perlin{colors={{0, 0, 0}, {1, 1, 1}}}");
  ASSERT_NE(p, nullptr);
  expectVecNear(p->colorAt({3, -2, 5}, n), dvec3(0.5), 1e-12);
  // marble without turbulence: 0.5 + 0.5 sin x.
  TexturePtr m = textureOf("marble{colors={{0, 0, 0}, {1, 1, 1}}, strength=0}");
  ASSERT_NE(m, nullptr);
  for (double x : {0.0, 1.0, 2.5, -4.0})
    expectVecNear(m->colorAt({x, 0.3, 0.7}, n), dvec3(0.5 + 0.5 * std::sin(x)), 1e-12);
  // wood without turbulence: rings, one per unit of radius about z.
  TexturePtr w = textureOf("wood{colors={{0, 0, 0}, {1, 1, 1}}, strength=0}");
  ASSERT_NE(w, nullptr);
  expectVecNear(w->colorAt({0.3, 0.4, 7}, n), dvec3(0.5), 1e-12);
  expectVecNear(w->colorAt({1.5, 2.0, -3}, n), dvec3(0.5), 1e-12);
  expectVecNear(w->colorAt({0.6, 0.8, 0}, n), dvec3(0.0), 1e-9);
  // octaves count: one octave and eight give different turbulence.
  TexturePtr t1 = textureOf("turbulence{colors={{0, 0, 0}, {1, 1, 1}}, octaves=1}");
  TexturePtr t8 = textureOf("turbulence{colors={{0, 0, 0}, {1, 1, 1}}, octaves=8}");
  ASSERT_TRUE(t1 && t8);
  int differ = 0;
  for (const dvec3& q : samplePoints())
    if (std::abs(t1->colorAt(q, n).x - t8->colorAt(q, n).x) > 1e-6) ++differ;
  EXPECT_GT(differ, 20);
}

// The escape-time fractals: the Julia set of c = 0 is the unit disc; the
// Mandelbrot set holds the period-2 bulb around -1 and is symmetric about
// the real axis; far points escape at once and take colour a.
TEST(ScriptTexture, FractalsFollowTheirSets) {
  const dvec3 n(0, 0, 1), inside(0.0, 1.0, 0.0), a(1.0, 0.0, 0.0);
  TexturePtr disc = textureOf("julia{c={0, 0}, colors={{1, 0, 0}, {0, 0, 1}}, inside={0, 1, 0}}");
  TexturePtr set = textureOf("mandelbrot{colors={{1, 0, 0}, {0, 0, 1}}, inside={0, 1, 0}}");
  ASSERT_TRUE(disc && set);
  for (double r : {0.0, 0.5, 0.99})
    for (double angle : {0.0, 1.0, 2.5, 4.0})
      EXPECT_EQ(disc->colorAt({r * std::cos(angle), r * std::sin(angle), 0.3}, n), inside)
          << r << " " << angle;
  for (double r : {1.01, 1.5, 3.0})
    EXPECT_NE(disc->colorAt({r * std::cos(1.0), r * std::sin(1.0), 0.0}, n), inside) << r;
  for (dvec3 c : {dvec3(-1.0, 0.0, 0.0), dvec3(-1.1, 0.1, 0.0), dvec3(0.0, 0.0, 0.0),
                  dvec3(-0.1, 0.6, 0.0), dvec3(0.25, 0.0, 0.0) - dvec3(0.01, 0.0, 0.0)})
    EXPECT_EQ(set->colorAt(c, n), inside) << c.x << " " << c.y;
  for (dvec3 c : {dvec3(0.3, 0.0, 0.0), dvec3(-2.1, 0.0, 0.0), dvec3(0.0, 1.1, 0.0)})
    EXPECT_NE(set->colorAt(c, n), inside) << c.x << " " << c.y;
  EXPECT_EQ(set->colorAt({50.0, 40.0, 0.0}, n), a);
  // Escaping later blends further towards b.
  EXPECT_LT(set->colorAt({0.3, 0.0, 0.0}, n).x, set->colorAt({0.6, 0.0, 0.0}, n).x);
  for (const dvec3& q : samplePoints()) {
    const dvec3 p(q.x * 0.5 - 0.5, q.y * 0.5, q.z);
    EXPECT_EQ(set->colorAt(p, n), set->colorAt({p.x, -p.y, p.z}, n));
  }
  expectError("return mandelbrot{iterations=0}",
              "part.lua:1: mandelbrot: iterations must be a whole number from 1 to 10000");
  expectError("return julia{c={1}}", "part.lua:1: julia: c must be {x, y}");
  expectError("return julia{z=1}", "part.lua:1: julia:");
}

// scale, rotate and translate move the pattern, in that order: the placed
// texture at q is the unplaced one at the point q came from.
TEST(ScriptTexture, PlacementMovesThePattern) {
  const dvec3 n(0, 0, 1);
  const char* colors = "colors={{0, 0, 0}, {1, 1, 1}}";
  TexturePtr plain = textureOf(std::string("marble{") + colors + "}");
  TexturePtr scaled = textureOf(std::string("marble{") + colors + ", scale={2, 3, 4}}");
  TexturePtr uniform = textureOf(std::string("marble{") + colors + ", scale=5}");
  TexturePtr moved = textureOf(std::string("marble{") + colors + ", translate={1, 2, 3}}");
  TexturePtr turned = textureOf(std::string("marble{") + colors + ", rotate={90, 0, 90}}");
  TexturePtr all = textureOf(std::string("marble{") + colors +
                             ", scale={2, 3, 4}, rotate={0, 0, 90}, translate={1, 2, 3}}");
  ASSERT_TRUE(plain && scaled && uniform && moved && turned && all);
  int differ = 0;
  for (const dvec3& q : samplePoints()) {
    expectVecNear(scaled->colorAt(q, n), plain->colorAt(q / dvec3(2, 3, 4), n), 1e-9);
    expectVecNear(uniform->colorAt(q, n), plain->colorAt(q / 5.0, n), 1e-9);
    expectVecNear(moved->colorAt(q, n), plain->colorAt(q - dvec3(1, 2, 3), n), 1e-9);
    // Rx(90) then Rz(90) maps (x, y, z) to (z, x, y): q came from (q.y, q.z, q.x).
    expectVecNear(turned->colorAt(q, n), plain->colorAt({q.y, q.z, q.x}, n), 1e-9);
    // Scale first, then rotate about z by 90° ((x, y) to (-y, x)), then translate.
    dvec3 r = q - dvec3(1, 2, 3);
    expectVecNear(all->colorAt(q, n), plain->colorAt({r.y / 2, -r.x / 3, r.z / 4}, n), 1e-9);
    if (std::abs(all->colorAt(q, n).x - plain->colorAt(q, n).x) > 1e-6) ++differ;
  }
  EXPECT_GT(differ, 20);  // the placement did change the pattern
  // checker{size=1, scale=10} has cells of 10 units.
  TexturePtr big = textureOf("checker{size=1, scale=10, colors={{1, 0, 0}, {0, 0, 1}}}");
  ASSERT_NE(big, nullptr);
  EXPECT_EQ(big->colorAt({9.5, 9.5, 9.5}, n), dvec3(1, 0, 0));
  EXPECT_EQ(big->colorAt({10.5, 9.5, 9.5}, n), dvec3(0, 0, 1));
  // Translate is not scaled: the cell edge moves by 5 units, not 50.
  TexturePtr shifted =
      textureOf("checker{size=1, scale=10, translate={5, 0, 0}, colors={{1, 0, 0}, {0, 0, 1}}}");
  ASSERT_NE(shifted, nullptr);
  EXPECT_EQ(shifted->colorAt({5.5, 0.5, 0.5}, n), dvec3(1, 0, 0));
  EXPECT_EQ(shifted->colorAt({4.5, 0.5, 0.5}, n), dvec3(0, 0, 1));
  EXPECT_EQ(shifted->colorAt({14.5, 0.5, 0.5}, n), dvec3(1, 0, 0));
  EXPECT_EQ(shifted->colorAt({15.5, 0.5, 0.5}, n), dvec3(0, 0, 1));
}

TEST(ScriptTexture, BadParametersAreErrors) {
  struct Case {
    const char* expression;
    const char* expected;
  } cases[] = {
      {"checker{size=0}", "checker: size must be > 0"},
      {"checker{size=-1}", "checker: size must be > 0"},
      {"checker{colors={{1, 1, 1}}}", "checker: colors must be a list of two colours"},
      {"checker{colors={{1, 1, 1}, {-1, 0, 0}}}", "checker: colors components must be >= 0"},
      {"checker{sise=1}", "checker: unknown parameter 'sise'"},
      {"perlin{octaves=3}", "perlin: unknown parameter"},
      {"turbulence{octaves=0}", "turbulence: octaves must be a whole number from 1 to 16"},
      {"checker{scale=0}", "checker: transform is singular"},
      {"turbulence{octaves=17}", "turbulence: octaves must be a whole number from 1 to 16"},
      {"marble{octaves=2.5}", "marble: octaves must be a whole number from 1 to 16"},
      {"wood{strength=-1}", "wood: strength must be >= 0"},
      {"marble{scale={1, 2}}", "marble: scale must be a list of three numbers"},
      {"image_texture{file='a.png', mapping='cubic'}",
       "image_texture: mapping must be \"planar\", \"spherical\", \"cylindrical\" or \"box\""},
      {"image_texture{mapping='planar'}", "image_texture: needs file="},
      {"image_texture{file=3}", "image_texture: file must be a string, got number"},
  };
  for (const Case& c : cases)
    expectError(std::string("local a = 1\nlocal t = ") + c.expression +
                    "\nreturn sphere(1):material{color=t}",
                std::string("part.lua:2: ") + c.expected);
  // Without a way to read images (ScriptOptions::loadImage unset) an image
  // texture is an error, not a crash.
  expectError("\nreturn sphere(1):material{color=image_texture{file='x.png'}}",
              "part.lua:2: image_texture: this program cannot read images");
}

// A temporary folder tree for image textures:
//   root/x.png             outside the script's folder
//   root/scripts/in.png    inside
//   root/scripts/sub/deeper.png
//   root/scripts/link.png  -> ../x.png   (a link that leads out)
//   root/scripts/alias.png -> in.png     (a link that stays in)
//   root/scripts/outdir    -> root       (a folder link that leads out)
class ImageTextureFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = csgray::test::scratchPathFor("csgray_script_api_");
    fs::remove_all(root_);
    fs::create_directories(root_ / "scripts" / "sub");
    writePng(root_ / "x.png");
    writePng(root_ / "scripts" / "in.png");
    writePng(root_ / "scripts" / "sub" / "deeper.png");
    fs::create_symlink("../x.png", root_ / "scripts" / "link.png");
    fs::create_symlink("in.png", root_ / "scripts" / "alias.png");
    fs::create_directory_symlink(root_, root_ / "scripts" / "outdir");
    options_.folder = (root_ / "scripts").string();
    options_.loadImage = [this](const std::string& path) {
      loaded_.push_back(path);
      return readTextureImage(path);
    };
  }
  void TearDown() override { fs::remove_all(root_); }

  // A 4 × 2 image: the top row red, the bottom row blue (v = 0 is the bottom).
  static void writePng(const fs::path& path) {
    std::vector<float> rgb;
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 4; ++x) {
        rgb.push_back(y == 0 ? 1.0f : 0.0f);
        rgb.push_back(0.0f);
        rgb.push_back(y == 0 ? 0.0f : 1.0f);
      }
    writeImage(path.string(), 4, 2, rgb.data());
  }

  std::string source(const std::string& file) {
    return "local t = image_texture{file=\"" + file + "\"}\nreturn sphere(1):material{color=t}";
  }

  fs::path root_;
  ScriptOptions options_;
  std::vector<std::string> loaded_;
};

TEST_F(ImageTextureFiles, AFileInTheFolderLoads) {
  for (const char* name : {"in.png", "./in.png", "sub/deeper.png", "sub/../in.png", "alias.png"}) {
    loaded_.clear();
    TexturePtr t = textureOf(std::string("image_texture{file=\"") + name + "\"}", options_);
    ASSERT_NE(t, nullptr) << name;
    EXPECT_EQ(loaded_.size(), 1u) << name;
    // Planar mapping, v = 0 at the bottom: rows of texel centres at
    // v = 0.25 (blue, the bottom row) and v = 0.75 (red, the top row).
    expectVecNear(t->colorAt({0.375, 0.25, 0}, {0, 0, 1}), dvec3(0, 0, 1), 1e-6);
    expectVecNear(t->colorAt({0.375, 0.75, 0}, {0, 0, 1}), dvec3(1, 0, 0), 1e-6);
    // Repeated once per unit.
    expectVecNear(t->colorAt({3.375, -1.75, 0}, {0, 0, 1}), dvec3(0, 0, 1), 1e-6);
  }
  // Placement applies to images too: scale 2 makes the image 2 units tall.
  TexturePtr t = textureOf("image_texture{file=\"in.png\", scale=2}", options_);
  ASSERT_NE(t, nullptr);
  expectVecNear(t->colorAt({0.75, 0.5, 0}, {0, 0, 1}), dvec3(0, 0, 1), 1e-6);
  expectVecNear(t->colorAt({0.75, 1.5, 0}, {0, 0, 1}), dvec3(1, 0, 0), 1e-6);
  // Every mapping is accepted.
  for (const char* mapping : {"planar", "spherical", "cylindrical", "box"})
    EXPECT_NE(textureOf(std::string("image_texture{file=\"in.png\", mapping=\"") + mapping + "\"}",
                        options_),
              nullptr)
        << mapping;
}

TEST_F(ImageTextureFiles, FilesOutsideTheFolderAreRefused) {
  std::vector<std::string> names = {"../x.png",
                                    (root_ / "x.png").string(),
                                    (root_ / "scripts" / "in.png").string(),  // absolute
                                    "link.png",
                                    "outdir/x.png",
                                    "sub/../../x.png",
                                    "outdir/scripts/../x.png"};
  for (const std::string& name : names) {
    loaded_.clear();
    std::string e = scriptError(source(name), options_);
    EXPECT_NE(e.find("part.lua:1: image_texture: file " + name + " is outside the script's folder"),
              std::string::npos)
        << name << "\n  gave: " << e;
    EXPECT_TRUE(loaded_.empty()) << name << " was read: " << loaded_.at(0);
  }
}

// A NUL byte would cut the name short at the file system ("in.png\0/../x"
// opens in.png) and in messages: refused, in one whole line.
TEST_F(ImageTextureFiles, ANulInTheNameIsRefused) {
  for (const char* name : {"in.png\\0/../../x.png", "../x.png\\0", "missing\\0.png"}) {
    loaded_.clear();
    std::string e = scriptError(
        std::string("return box(1):material{color=image_texture{file=\"") + name + "\"}}",
        options_);
    EXPECT_EQ(e, "part.lua:1: image_texture: file name contains a NUL byte") << name;
    EXPECT_TRUE(loaded_.empty()) << name << " was read: " << loaded_.at(0);
  }
}

TEST_F(ImageTextureFiles, AMissingFileIsAnErrorNamingIt) {
  std::string e = scriptError(source("missing.png"), options_);
  EXPECT_NE(e.find("part.lua:1: "), std::string::npos) << e;
  EXPECT_NE(e.find("missing.png"), std::string::npos) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  expectError(source(""), "part.lua:1: image_texture: file is empty", options_);
  // A file that is not an image.
  { std::ofstream(root_ / "scripts" / "notes.png") << "not an image"; }
  e = scriptError(source("notes.png"), options_);
  EXPECT_NE(e.find("part.lua:1: "), std::string::npos) << e;
  EXPECT_NE(e.find("notes.png"), std::string::npos) << e;
}

// Image pixels count against the script's memory cap, also when the
// texture values are gone and only the materials of parts hold the images.
TEST_F(ImageTextureFiles, ImagesCountAgainstTheMemoryCap) {
  std::vector<float> rgb(256 * 256 * 3, 0.5f);
  writeImage((root_ / "scripts" / "big.png").string(), 256, 256, rgb.data());
  options_.limits.memoryBytes = 24u << 20;
  EXPECT_EQ(scriptError("return box(1):material{color=image_texture{file='big.png'}}", options_),
            "(no error)");
  // 100 parts with an image of 768 KiB each: 75 MiB.
  std::string e = scriptError(
      "local parts = {}\n"
      "for i = 1, 100 do\n"
      "  parts[i] = box(1):translate(i, 0, 0):material{color=image_texture{file='big.png'}}\n"
      "end\n"
      "return union(parts)",
      options_);
  EXPECT_NE(e.find("script exceeded the memory limit of 24 MiB"), std::string::npos) << e;
}

// Texture space is the world as it was when the material was given, so a
// part textured and then moved carries its texture along.
TEST(ScriptTexture, TexturesAreFixedToThePart) {
  const char* texture = "checker{size=0.5, colors={{1, 0, 0}, {0, 0, 1}}}";
  auto still = primitiveOf(std::string("return box(2):material{color=") + texture + "}");
  auto moved = primitiveOf(std::string("return box(2):material{color=") + texture +
                           "}:rotate(0, 0, 90):translate(10, 20, 30)");
  ASSERT_TRUE(still && moved && still->material() && moved->material());
  const dvec3 n(0, 0, 1);
  int blue = 0;
  for (double x : {0.2, 0.7, 1.2, 1.7})
    for (double y : {0.3, 0.8, 1.3})
      for (double z : {0.1, 0.6, 1.6}) {
        dvec3 p(x, y, z);
        // Rotating 90° about z takes (x, y, z) to (-y, x, z).
        dvec3 q = dvec3(-y, x, z) + dvec3(10, 20, 30);
        EXPECT_TRUE(moved->contains(q));
        expectVecNear(still->texturePoint(p), p, 1e-12);
        expectVecNear(moved->texturePoint(q), p, 1e-9);
        dvec3 expected = still->material()->colorAt(still->texturePoint(p), n);
        EXPECT_EQ(moved->material()->colorAt(moved->texturePoint(q), n), expected);
        if (expected == dvec3(0, 0, 1)) ++blue;
      }
  EXPECT_GT(blue, 0);
  // Moved first and textured after: texture space is the moved world.
  auto after =
      primitiveOf(std::string("return box(2):translate(10, 0, 0):material{color=") + texture + "}");
  ASSERT_TRUE(after);
  expectVecNear(after->texturePoint({10.3, 0.3, 0.3}), dvec3(10.3, 0.3, 0.3), 1e-12);
  // A textured boolean moved as a whole: each leaf keeps its texture space
  // (the leaves in their places: the moved boolean is an instance).
  Scene scene = sceneOf(std::string("return (box(1) + sphere(1):translate(5, 0, 0)):material{") +
                        "color=" + texture + "}:translate(0, 100, 0)");
  ASSERT_EQ(scene.objects.size(), 1u);
  const SolidPtr placed = flattened(scene.objects[0]);
  for (const SolidPtr& child : placed->children()) {
    auto* leaf = dynamic_cast<const Primitive*>(child.get());
    ASSERT_NE(leaf, nullptr);
    dvec3 centre = 0.5 * (leaf->bounds().lo + leaf->bounds().hi);
    expectVecNear(leaf->texturePoint(centre), centre - dvec3(0, 100, 0), 1e-9);
  }
}

// ---- Open surfaces ----------------------------------------------------------

// Bounds are conservative: at most a hair larger than the shape.
void expectLow(const Bounds& b, const dvec3& lo) {
  for (int i = 0; i < 3; ++i) {
    EXPECT_LE(b.lo[i], lo[i]) << "axis " << i;
    EXPECT_GT(b.lo[i], lo[i] - 1e-6) << "axis " << i;
  }
}
void expectHigh(const Bounds& b, const dvec3& hi) {
  for (int i = 0; i < 3; ++i) {
    EXPECT_GE(b.hi[i], hi[i]) << "axis " << i;
    EXPECT_LT(b.hi[i], hi[i] + 1e-6) << "axis " << i;
  }
}
void expectBounds(const Bounds& b, const dvec3& lo, const dvec3& hi) {
  expectLow(b, lo);
  expectHigh(b, hi);
}

// Does the ray from above (x, y, 10) straight down meet the surface, and where.
std::optional<double> hitFromAbove(const Surface& s, double x, double y) {
  return s.hit(Ray(dvec3(x, y, 10), dvec3(0, 0, -1)));
}

TEST(ScriptSurface, SurfacesGoToSceneSurfaces) {
  Scene scene = sceneOf(R"(
    return scene{objects={
      plane{normal={0, 0, 2}, offset=3}, disc{r=2, center={1, 1, 1}},
      triangle{points={{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}},
      parallelogram{origin={1, 0, 0}, u={2, 0, 0}, v={1, 1, 0}},
      rectangle{size={4, 2}}, square{size=3, center=true}, box(1)}})");
  EXPECT_EQ(scene.objects.size(), 1u);
  ASSERT_EQ(scene.surfaces.size(), 6u);
  const char* kinds[] = {"plane", "disc", "triangle", "parallelogram", "rectangle", "square"};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(scene.surfaces[i]->kind(), kinds[i]);
  const Surface &plane = *scene.surfaces[0], &disc = *scene.surfaces[1], &tri = *scene.surfaces[2],
                &para = *scene.surfaces[3], &rect = *scene.surfaces[4],
                &square = *scene.surfaces[5];
  // normal · p = offset with normal (0, 0, 2): z = 1.5.
  ASSERT_TRUE(hitFromAbove(plane, 100, -50));
  EXPECT_NEAR(*hitFromAbove(plane, 100, -50), 8.5, 1e-12);
  expectVecNear(plane.normal(), dvec3(0, 0, 1), 1e-12);
  EXPECT_EQ(plane.shape(), Surface::Shape::Plane);
  // The disc about (1, 1, 1) of radius 2.
  ASSERT_TRUE(hitFromAbove(disc, 2.9, 1));
  EXPECT_NEAR(*hitFromAbove(disc, 2.9, 1), 9.0, 1e-12);
  EXPECT_FALSE(hitFromAbove(disc, 3.1, 1));
  EXPECT_FALSE(hitFromAbove(disc, 2.5, 2.5));
  expectBounds(disc.bounds(), dvec3(-1, -1, 1), dvec3(3, 3, 1));
  EXPECT_TRUE(hitFromAbove(tri, 0.2, 0.2));
  EXPECT_FALSE(hitFromAbove(tri, 0.6, 0.6));
  EXPECT_FALSE(hitFromAbove(tri, -0.1, 0.5));
  // origin + ϑ·u + φ·v is (1 + 2ϑ + φ, φ, 0).
  EXPECT_TRUE(hitFromAbove(para, 3.5, 0.9));   // ϑ = 0.8, φ = 0.9
  EXPECT_FALSE(hitFromAbove(para, 1.2, 0.5));  // ϑ = -0.15
  EXPECT_FALSE(hitFromAbove(para, 2, 1.1));    // φ = 1.1
  EXPECT_TRUE(hitFromAbove(rect, 3.9, 1.9));
  EXPECT_FALSE(hitFromAbove(rect, 4.1, 1));
  EXPECT_FALSE(hitFromAbove(rect, 1, 2.1));
  EXPECT_FALSE(hitFromAbove(rect, -0.1, 1));
  EXPECT_TRUE(hitFromAbove(square, -1.4, 1.4));
  EXPECT_FALSE(hitFromAbove(square, 1.6, 0));
  // A diameter is twice the radius; a rectangle may be centred.
  SurfacePtr d = surfaceOf("return disc{d=4}");
  ASSERT_NE(d, nullptr);
  EXPECT_TRUE(hitFromAbove(*d, 1.9, 0));
  EXPECT_FALSE(hitFromAbove(*d, 2.1, 0));
  SurfacePtr r = surfaceOf("return rectangle{size={4, 2}, center=true}");
  ASSERT_NE(r, nullptr);
  expectBounds(r->bounds(), dvec3(-2, -1, 0), dvec3(2, 1, 0));
  SurfacePtr s = surfaceOf("return square{size=3}");
  ASSERT_NE(s, nullptr);
  expectHigh(s->bounds(), dvec3(3, 3, 0));
  // A tilted disc faces its normal.
  SurfacePtr tilted = surfaceOf("return disc{r=1, normal={1, 0, 0}}");
  ASSERT_NE(tilted, nullptr);
  expectVecNear(glm::abs(tilted->normal()), dvec3(1, 0, 0), 1e-12);
}

TEST(ScriptSurface, SurfacesTakeMaterialsAndTransforms) {
  SurfacePtr s = surfaceOf(
      "return rectangle{size={4, 2}}:material{color={1, 0, 0}, reflection=0.5}"
      ":rotate(0, 0, 90):translate(10, 0, 5)");
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->kind(), "rectangle");
  ASSERT_NE(s->material(), nullptr);
  EXPECT_EQ(s->material()->color, dvec3(1, 0, 0));
  EXPECT_EQ(s->material()->reflection, 0.5);
  // (x, y) to (-y, x), then moved: x in [8, 10], y in [0, 4], z = 5.
  expectBounds(s->bounds(), dvec3(8, 0, 5), dvec3(10, 4, 5));
  ASSERT_TRUE(hitFromAbove(*s, 9, 3.9));
  EXPECT_NEAR(*hitFromAbove(*s, 9, 3.9), 5.0, 1e-9);
  EXPECT_FALSE(hitFromAbove(*s, 9, 4.1));
  EXPECT_FALSE(hitFromAbove(*s, 10.1, 1));
  // scale, mirror and transform too.
  SurfacePtr scaled = surfaceOf("return square{size=1}:scale(3, 2, 1):mirror(1, 0, 0)");
  ASSERT_NE(scaled, nullptr);
  expectBounds(scaled->bounds(), dvec3(-3, 0, 0), dvec3(0, 2, 0));
  SurfacePtr mapped = surfaceOf("return disc{r=1}:transform{{1,0,0,5},{0,1,0,0},{0,0,1,2}}");
  ASSERT_NE(mapped, nullptr);
  expectLow(mapped->bounds(), dvec3(4, -1, 2));
  // A textured surface moved afterwards carries its texture along.
  SurfacePtr tex =
      surfaceOf("return square{size=2}:material{color=checker{size=0.5}}:translate(10, 0, 0)");
  ASSERT_TRUE(tex && tex->material() && tex->material()->texture);
  expectVecNear(tex->texturePoint({10.3, 0.7, 0}), dvec3(0.3, 0.7, 0), 1e-12);
  // Transforms leave the original surface as it was.
  Scene both = sceneOf("local a = square{size=1}\nreturn scene{objects={a, a:translate(5, 0, 0)}}");
  ASSERT_EQ(both.surfaces.size(), 2u);
  expectLow(both.surfaces[0]->bounds(), dvec3(0));
  expectLow(both.surfaces[1]->bounds(), dvec3(5, 0, 0));
}

TEST(ScriptSurface, SurfacesAreNotSolids) {
  const char* sources[] = {
      "local p = plane{}\nreturn p + box(1)",
      "local b = box(1)\nreturn b - disc{r=1}",
      "local t = triangle{points={{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}\nreturn union(box(1), t)",
      "local d = disc{r=1}\nreturn d * box(1)",
      "local s = square{size=1}:rotate(90, 0, 0)\nreturn intersection{box(1), s}",
      "local s = rectangle{size={1, 2}}:translate(0, 0, 1)\nreturn difference(s, box(1))",
      "local s = plane{}\nreturn box(1) + s",
  };
  const char* kinds[] = {"plane", "disc", "triangle", "disc", "square", "rectangle", "plane"};
  for (int i = 0; i < 7; ++i) {
    std::string e = scriptError(sources[i]);
    EXPECT_NE(e.find("part.lua:2: "), std::string::npos) << sources[i] << "\n  gave: " << e;
    EXPECT_NE(e.find(std::string("a ") + kinds[i] + " is a surface"), std::string::npos)
        << sources[i] << "\n  gave: " << e;
    EXPECT_NE(e.find("it encloses no volume"), std::string::npos)
        << sources[i] << "\n  gave: " << e;
  }
  // With the surface first the surface's own operator answers.
  expectError("return plane{} + box(1)", "a plane is a surface, not a solid");
  expectError("return disc{r=1} * box(1)", "a disc is a surface, not a solid");
}

TEST(ScriptSurface, DegenerateShapesAreErrors) {
  struct Case {
    const char* expression;
    const char* expected;
  } cases[] = {
      {"triangle{points={{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}}", "triangle: the points are collinear"},
      {"triangle{points={{0, 0, 0}, {0, 0, 0}, {1, 0, 0}}}", "triangle: two of the points"},
      {"triangle{points={{0, 0, 0}, {1, 0, 0}}}", "triangle: points must be a list of three"},
      {"triangle{}", "triangle: needs points="},
      {"disc{r=0}", "disc: the radius must be > 0"},
      {"disc{r=-1}", "disc: the radius must be > 0"},
      {"disc{d=0}", "disc: the radius must be > 0"},
      {"disc{}", "disc: needs r"},
      {"disc{r=1, d=2}", "disc: give r or d, not both"},
      {"disc{r=1, normal={0, 0, 0}}", "disc: normal must not be the zero vector"},
      {"plane{normal={0, 0, 0}}", "plane: normal must not be the zero vector"},
      {"parallelogram{u={1, 0, 0}, v={2, 0, 0}}", "parallelogram: the edges are parallel"},
      {"parallelogram{u={1, 0, 0}, v={0, 0, 0}}", "parallelogram: an edge has zero length"},
      {"parallelogram{u={1, 0, 0}}", "parallelogram: needs the edges u="},
      {"rectangle{size={0, 1}}", "rectangle: size must be > 0"},
      {"rectangle{size={1, -1}}", "rectangle: size must be > 0"},
      {"rectangle{size=1}", "rectangle: size must be {w, h}"},
      {"square{size=0}", "square: size must be > 0"},
      {"square{}", "square: needs size=s"},
      {"disc{r=1, radius=2}", "disc: unknown parameter 'radius'"},
  };
  for (const Case& c : cases)
    expectError(std::string("local a = 1\nlocal s = ") + c.expression + "\nreturn s",
                std::string("part.lua:2: ") + c.expected);
  expectError("local s = square{size=1}\nreturn s:scale(1, 0, 1)",
              "part.lua:2: transform is singular");
}

TEST(ScriptSurface, AScriptMayReturnASurface) {
  Scene scene = sceneOf("return disc{r=1}");
  EXPECT_TRUE(scene.objects.empty());
  ASSERT_EQ(scene.surfaces.size(), 1u);
  EXPECT_EQ(scene.surfaces[0]->kind(), "disc");
  // A scene of only surfaces is not empty.
  scene = sceneOf("return scene{objects=square{size=1}}");
  EXPECT_EQ(scene.surfaces.size(), 1u);
  scene = sceneOf("return scene{objects={plane{}}, camera=camera{eye={0, -5, 5}}}");
  EXPECT_EQ(scene.surfaces.size(), 1u);
  expectError("return scene{objects={1}}",
              "part.lua:1: scene: objects[1] (a solid, a surface or a region) must be a solid, got "
              "number");
}

// ---- Lights -----------------------------------------------------------------

TEST(ScriptLight, FieldsLandInSceneLights) {
  std::vector<Light> lights = lightsOf(R"(
    point_light{pos={1, 2, 3}, color={1, 0.5, 0.25}, intensity=2, falloff=true},
    spot_light{pos={0, 0, 10}, look_at={0, 5, 0}, angle=20, exponent=3},
    spot_light{pos={1, 1, 1}, direction={2, 0, 0}},
    area_light{pos={0, 0, 5}, u={2, 0, 0}, v={0, 3, 0}, samples=9, intensity=0.5},
    sphere_light{pos={4, 5, 6}, r=0.5, samples=4, color={0, 1, 0}},
    point_light{pos={0, 0, 0}})");
  ASSERT_EQ(lights.size(), 6u);
  const Light &point = lights[0], &spot = lights[1], &spot2 = lights[2], &area = lights[3],
              &ball = lights[4], &plain = lights[5];
  EXPECT_EQ(point.kind, Light::Kind::Point);
  EXPECT_EQ(point.position, dvec3(1, 2, 3));
  EXPECT_EQ(point.color, dvec3(1, 0.5, 0.25));
  EXPECT_EQ(point.intensity, 2.0);
  EXPECT_TRUE(point.inverseSquare);
  EXPECT_EQ(spot.kind, Light::Kind::Spot);
  EXPECT_EQ(spot.position, dvec3(0, 0, 10));
  expectVecNear(glm::normalize(spot.direction), glm::normalize(dvec3(0, 5, -10)), 1e-12);
  EXPECT_EQ(spot.coneDegrees, 20.0);
  EXPECT_EQ(spot.exponent, 3.0);
  EXPECT_FALSE(spot.inverseSquare);
  EXPECT_EQ(spot2.kind, Light::Kind::Spot);
  expectVecNear(glm::normalize(spot2.direction), dvec3(1, 0, 0), 1e-12);
  EXPECT_EQ(spot2.coneDegrees, 30.0);  // default
  EXPECT_EQ(spot2.exponent, 1.0);
  EXPECT_EQ(area.kind, Light::Kind::Rectangle);
  EXPECT_EQ(area.position, dvec3(0, 0, 5));
  EXPECT_EQ(area.edgeU, dvec3(2, 0, 0));
  EXPECT_EQ(area.edgeV, dvec3(0, 3, 0));
  EXPECT_EQ(area.samples, 9);
  EXPECT_EQ(area.intensity, 0.5);
  EXPECT_TRUE(area.isArea());
  EXPECT_EQ(ball.kind, Light::Kind::Sphere);
  EXPECT_EQ(ball.position, dvec3(4, 5, 6));
  EXPECT_EQ(ball.radius, 0.5);
  EXPECT_EQ(ball.samples, 4);
  EXPECT_EQ(ball.color, dvec3(0, 1, 0));
  // Defaults.
  EXPECT_EQ(plain.kind, Light::Kind::Point);
  EXPECT_EQ(plain.color, dvec3(1));
  EXPECT_EQ(plain.intensity, 1.0);
  EXPECT_FALSE(plain.inverseSquare);
  std::vector<Light> areas = lightsOf("area_light{pos={0, 0, 1}}, sphere_light{pos={0, 0, 1}}");
  ASSERT_EQ(areas.size(), 2u);
  EXPECT_EQ(areas[0].samples, 16);
  EXPECT_EQ(areas[1].samples, 16);
  // The spot cone: light within angle of the axis, none beyond.
  EXPECT_GT(spot2.radianceAt({10, 5.5, 1}, spot2.position).x, 0.0);     // 26.6° off
  EXPECT_EQ(spot2.radianceAt({10, 6.5, 1}, spot2.position), dvec3(0));  // 31.4° off
  // A single light need not be in a list.
  Scene one = sceneOf("return scene{objects=sphere(1), lights=point_light{pos={1, 1, 1}}}");
  ASSERT_EQ(one.lights.size(), 1u);
  EXPECT_EQ(one.lights[0].position, dvec3(1));
  // No lights given: none in the scene (the renderer adds its default).
  EXPECT_TRUE(sceneOf("return scene{objects=sphere(1)}").lights.empty());
  EXPECT_TRUE(sceneOf("return scene{objects=sphere(1)}").defaultLight);
  // An empty list names no lights: no default light either.
  Scene dark = sceneOf("return scene{objects=sphere(1), lights={}}");
  EXPECT_TRUE(dark.lights.empty());
  EXPECT_FALSE(dark.defaultLight);
}

TEST(ScriptLight, BadParametersAreErrors) {
  struct Case {
    const char* expression;
    const char* expected;
  } cases[] = {
      {"spot_light{pos={0, 0, 1}, angle=90}", "spot_light: angle must be between 0 and 90"},
      {"spot_light{pos={0, 0, 1}, angle=0}", "spot_light: angle must be between 0 and 90"},
      {"spot_light{pos={0, 0, 1}, look_at={0, 0, 1}}", "spot_light: the direction is the zero"},
      {"spot_light{pos={0, 0, 1}, direction={0, 0, 0}}", "spot_light: the direction is the zero"},
      {"spot_light{pos={0, 0, 1}, look_at={0, 0, 0}, direction={0, 0, -1}}",
       "spot_light: give look_at or direction, not both"},
      {"spot_light{pos={0, 0, 1}, exponent=-1}", "spot_light: exponent must be >= 0"},
      {"area_light{pos={0, 0, 1}, samples=0}", "area_light: samples must be a whole number"},
      {"area_light{pos={0, 0, 1}, samples=2000}", "area_light: samples must be a whole number"},
      {"area_light{pos={0, 0, 1}, samples=1.5}", "area_light: samples must be a whole number"},
      {"sphere_light{pos={0, 0, 1}, samples=0}", "sphere_light: samples must be a whole number"},
      {"sphere_light{pos={0, 0, 1}, samples=1025}",
       "sphere_light: samples must be a whole number from 1 to 1024"},
      {"sphere_light{pos={0, 0, 1}, r=0}", "sphere_light: r must be > 0"},
      {"area_light{pos={0, 0, 1}, u={0, 0, 0}}", "area_light: u must not be the zero vector"},
      {"area_light{pos={0, 0, 1}, u={2, 0, 0}, v={-3, 0, 0}}",
       "area_light: u and v must not be parallel"},
      {"area_light{pos={0, 0, 1}, u={1, 1, 0}, v={1, 1, 1e-12}}",
       "area_light: u and v must not be parallel"},
      {"point_light{pos={0, 0, 1}, intensity=-1}", "point_light: intensity must be >= 0"},
      {"spot_light{pos={0, 0, 1}, intensity=-0.5}", "spot_light: intensity must be >= 0"},
      {"area_light{pos={0, 0, 1}, intensity=-2}", "area_light: intensity must be >= 0"},
      {"point_light{pos={0, 0, 1}, color={-1, 0, 0}}", "point_light: color components must be"},
      {"point_light{pos={0, 0, 1}, falloff=1}", "point_light: falloff must be true or false"},
      {"point_light{}", "point_light: needs pos={x, y, z}"},
      {"point_light{pos={0, 0, 1}, position={1, 1, 1}}",
       "point_light: unknown parameter 'position'"},
  };
  for (const Case& c : cases)
    expectError(std::string("local a = 1\nlocal l = ") + c.expression +
                    "\nreturn scene{objects=sphere(1), lights={l}}",
                std::string("part.lua:2: ") + c.expected);
  // Bounds of the ranges are allowed.
  std::vector<Light> ok = lightsOf(
      "area_light{pos={0, 0, 1}, samples=1}, area_light{pos={0, 0, 1}, samples=1024}, "
      "point_light{pos={0, 0, 1}, intensity=0}, spot_light{pos={0, 0, 1}, angle=89.9}");
  ASSERT_EQ(ok.size(), 4u);
  EXPECT_EQ(ok[0].samples, 1);
  EXPECT_EQ(ok[1].samples, 1024);
  EXPECT_EQ(ok[2].intensity, 0.0);
}

// ---- Camera and scene -------------------------------------------------------

TEST(ScriptScene, CameraProjection) {
  Scene s = sceneOf(
      "return scene{objects=sphere(1), camera=camera{eye={0, -10, 0}, "
      "projection=\"orthographic\", width=20}}");
  ASSERT_TRUE(s.camera);
  EXPECT_TRUE(s.camera->orthographic);
  EXPECT_EQ(s.camera->orthoWidth, 20.0);
  EXPECT_EQ(s.camera->eye, dvec3(0, -10, 0));
  s = sceneOf("return scene{objects=sphere(1), camera=camera{projection=\"perspective\", fov=60}}");
  ASSERT_TRUE(s.camera);
  EXPECT_FALSE(s.camera->orthographic);
  EXPECT_EQ(s.camera->fovDegrees, 60.0);
  s = sceneOf("return scene{objects=sphere(1), camera=camera{}}");
  ASSERT_TRUE(s.camera);
  EXPECT_FALSE(s.camera->orthographic);
  EXPECT_EQ(s.camera->fovDegrees, 45.0);
  EXPECT_EQ(s.camera->eye, dvec3(0, -10, 0));
  EXPECT_EQ(s.camera->lookAt, dvec3(0));
  EXPECT_EQ(s.camera->up, dvec3(0, 0, 1));
  // Orthographic without a width fits the scene (0 says so).
  s = sceneOf("return scene{objects=sphere(1), camera=camera{projection='orthographic'}}");
  ASSERT_TRUE(s.camera);
  EXPECT_TRUE(s.camera->orthographic);
  EXPECT_EQ(s.camera->orthoWidth, 0.0);
  // No camera: none in the scene (framed from the bounds).
  EXPECT_FALSE(sceneOf("return scene{objects=sphere(1)}").camera);

  struct Case {
    const char* expression;
    const char* expected;
  } cases[] = {
      {"camera{width=10}", "camera: width is for projection=\"orthographic\""},
      {"camera{projection='perspective', width=10}",
       "camera: width is for projection=\"orthographic\""},
      {"camera{projection='fisheye'}",
       "camera: projection must be \"perspective\" or \"orthographic\""},
      {"camera{projection='Orthographic'}", "camera: projection must be"},
      {"camera{projection=1}", "camera: projection must be a string"},
      {"camera{projection='orthographic', width=0}", "camera: width must be > 0"},
      {"camera{projection='orthographic', width=-3}", "camera: width must be > 0"},
      {"camera{fov=180}", "camera: fov must be between 0 and 180"},
      {"camera{fov=0}", "camera: fov must be between 0 and 180"},
      {"camera{up={0, 1, 0}, eye={0, -5, 0}}", "camera: up must not be parallel"},
      {"camera{aperture=-1}", "camera: aperture must be >= 0"},
      {"camera{projection='orthographic', aperture=1}",
       "camera: aperture (focal blur) is for a perspective camera"},
      {"camera{aperture=1, focal_point={0, -12, 0}}",
       "camera: focal_point must lie in front of the eye"},
      {"camera{aperture=1, blur_samples=0}",
       "camera: blur_samples must be a whole number from 1 to 1024"},
      {"camera{aperture=1, blur_samples=8.5}", "camera: blur_samples must be a whole number"},
      {"camera{aperture=1, focal_point='near'}", "camera: focal_point must be"},
  };
  for (const Case& c : cases)
    expectError(std::string("local a = 1\nlocal c = ") + c.expression +
                    "\nreturn scene{objects=sphere(1), camera=c}",
                std::string("part.lua:2: ") + c.expected);
}

// A lens: focal blur as POV-Ray's camera gives it (aperture, focal_point,
// blur_samples).
TEST(ScriptScene, CameraLens) {
  Scene s = sceneOf(
      "return scene{objects=sphere(1), camera=camera{aperture=0.5, focal_point={1, 2, 3}, "
      "blur_samples=36}}");
  ASSERT_TRUE(s.camera);
  EXPECT_EQ(s.camera->aperture, 0.5);
  EXPECT_EQ(s.camera->focalPoint, dvec3(1, 2, 3));
  EXPECT_EQ(s.camera->blurSamples, 36);
  EXPECT_TRUE(s.camera->blurs());
  s = sceneOf("return scene{objects=sphere(1), camera=camera{}}");
  EXPECT_FALSE(s.camera->blurs());
  EXPECT_FALSE(s.camera->focalPoint);
  EXPECT_EQ(s.camera->blurSamples, 16);
}

TEST(ScriptScene, Fog) {
  Scene s = sceneOf("return scene{objects=sphere(1), fog={color={0.7, 0.8, 0.9}, distance=40}}");
  EXPECT_EQ(s.fog.color, dvec3(0.7, 0.8, 0.9));
  EXPECT_EQ(s.fog.distance, 40.0);
  EXPECT_EQ(sceneOf("return scene{objects=sphere(1)}").fog.distance, 0.0);  // off
  s = sceneOf("return scene{objects=sphere(1), fog={color='white', distance=1}}");
  EXPECT_EQ(s.fog.color, dvec3(1.0));
  const char* source = "local a = 1\nreturn scene{objects=sphere(1), fog=";
  expectError(std::string(source) + "{distance=10}}", "part.lua:2: scene: fog needs color (");
  expectError(std::string(source) + "{color={1, 1, 1}}}",
              "part.lua:2: scene: fog needs distance (");
  expectError(std::string(source) + "{}}", "part.lua:2: scene: fog needs color and distance");
  expectError(std::string(source) + "{color={1, 1, 1}, distance=0}}",
              "part.lua:2: scene: fog: distance must be > 0");
  expectError(std::string(source) + "{color={-1, 1, 1}, distance=3}}",
              "part.lua:2: scene: fog: color components must be >= 0");
  expectError(std::string(source) + "{color={1, 1, 1}, distance=3, density=2}}",
              "part.lua:2: scene: fog: unknown parameter 'density'");
  expectError(std::string(source) + "true}", "part.lua:2: scene: fog: expected a table");
  // Colour maps: colours spaced evenly, or stops at places.
  TexturePtr three = textureOf("gradient{colors={'red', {0, 1, 0}, 'blue'}}");
  ASSERT_NE(three, nullptr);
  EXPECT_EQ(three->colorAt(dvec3(0, 0, 0.5), dvec3(0, 0, 1)), dvec3(0, 1, 0));
  TexturePtr stops = textureOf("gradient{colors={{0, 'red'}, {0.5, 'red'}, {1, {0, 0, 1}}}}");
  ASSERT_NE(stops, nullptr);
  EXPECT_EQ(stops->colorAt(dvec3(0, 0, 0.4), dvec3(0, 0, 1)), dvec3(1, 0, 0));
  EXPECT_EQ(stops->colorAt(dvec3(0, 0, 0.75), dvec3(0, 0, 1)), dvec3(0.5, 0, 0.5));
  EXPECT_NE(textureOf("marble{colors={'white', 'grey', 'black', 'white'}}"), nullptr);
  expectError("return sphere(1):material{color=gradient{colors={{0, 'red'}, 'blue'}}}",
              "part.lua:1: gradient: colors: give every entry as a colour, or every one as a "
              "{place, colour} stop");
  expectError("return sphere(1):material{color=wood{colors={'red'}}}",
              "part.lua:1: wood: colors must be a list of two or more colours");
  expectError("return sphere(1):material{color=perlin{colors={{0, 'red'}, {2, 'blue'}}}}",
              "part.lua:1: perlin: colors[2]: a stop's place must be in [0, 1]");
  expectError("return sphere(1):material{color=checker{colors={'red', 'green', 'blue'}}}",
              "part.lua:1: checker: colors must be a list of two colours");
  expectError("return sphere(1):material{color=gradient{from={1, 1, 1}, to={1, 1, 1}}}",
              "part.lua:1: gradient: from and to are the same point");
  expectError("return sphere(1):material{color=gradient{to=3, from=3}}",
              "part.lua:1: gradient: from and to are the same point");
  s = sceneOf(
      "return scene{objects=sphere(1), fog={color={1, 1, 1}, distance=9, offset=-2, altitude=4}}");
  EXPECT_EQ(s.fog.offset, -2.0);
  EXPECT_EQ(s.fog.altitude, 4.0);
  EXPECT_TRUE(s.fog.ground());
  expectError(std::string(source) + "{color={1, 1, 1}, distance=3, offset=1}}",
              "part.lua:2: scene: fog: offset needs altitude (ground fog");
  expectError(std::string(source) + "{color={1, 1, 1}, distance=3, altitude=1}}",
              "part.lua:2: scene: fog: altitude needs offset");
  expectError(std::string(source) + "{color={1, 1, 1}, distance=3, offset=1, altitude=0}}",
              "part.lua:2: scene: fog: altitude must be > 0");
}

TEST(ScriptScene, LimitsLandInTheScene) {
  Scene s = sceneOf("return scene{objects=sphere(1), max_depth=3, min_weight=0.01}");
  EXPECT_EQ(s.limits.maxDepth, 3);
  EXPECT_EQ(s.limits.minWeight, 0.01);
  s = sceneOf("return scene{objects=sphere(1)}");
  EXPECT_EQ(s.limits.maxDepth, 8);
  EXPECT_EQ(s.limits.minWeight, 1.0 / 512.0);
  EXPECT_EQ(s.background, dvec3(0.05, 0.05, 0.08));
  EXPECT_EQ(sceneOf("return scene{objects=sphere(1), max_depth=0}").limits.maxDepth, 0);
  EXPECT_EQ(sceneOf("return scene{objects=sphere(1), max_depth=64}").limits.maxDepth, 64);
  // A solid returned alone gets the default limits.
  EXPECT_EQ(sceneOf("return sphere(1)").limits.maxDepth, 8);
  for (const char* value : {"-1", "65", "1.5", "0/0", "'deep'"}) {
    std::string e = scriptError(
        std::string("local a = 1\nreturn scene{objects=sphere(1), max_depth=") + value + "}");
    EXPECT_NE(e.find("part.lua:2: scene: max_depth"), std::string::npos) << value << ": " << e;
  }
  expectError("return scene{objects=sphere(1), max_depth=65}",
              "part.lua:1: scene: max_depth must be a whole number from 0 to 64");
  expectError("return scene{objects=sphere(1), min_weight=2}",
              "part.lua:1: scene: min_weight must be in [0, 1]");
  expectError("return scene{objects=sphere(1), min_weight=-0.1}",
              "part.lua:1: scene: min_weight must be in [0, 1]");
  expectError("return scene{objects=sphere(1), background={-1, 0, 0}}",
              "part.lua:1: scene: background components must be >= 0");
  expectError("return scene{objects=sphere(1), camera=42}",
              "part.lua:1: scene: camera must be a camera, got number");
  expectError("return scene{objects=sphere(1), maxdepth=3}",
              "part.lua:1: scene: unknown parameter 'maxdepth'");
  expectError("return scene{}", "part.lua:1: scene: objects is empty");
}

// The lists of a scene are copied into it: a list of millions of references
// to one light or part is charged against the memory cap and the limit on
// primitives, and stops there with the line of the call, not after
// gigabytes were allocated outside the cap.
TEST(ScriptScene, HugeListsAreCharged) {
  ScriptOptions options;
  options.limits.memoryBytes = 64u << 20;
  // 1 000 000 lights of about 180 bytes each: 170 MiB.
  std::string e = scriptError(
      "local l, t = point_light{pos={0, 0, 10}}, {}\n"
      "for i = 1, 1000000 do t[i] = l end\n"
      "return scene{objects=sphere(1), lights=t}",
      options);
  EXPECT_EQ(e, "part.lua:3: script exceeded the memory limit of 64 MiB");
  EXPECT_EQ(scriptError("local l, t = point_light{pos={0, 0, 10}}, {}\n"
                        "for i = 1, 1000 do t[i] = l end\n"
                        "return scene{objects=sphere(1), lights=t}",
                        options),
            "(no error)");
  // 1 200 000 uses of a part of two primitives: more than 2 000 000.
  expectError(
      "local s, t = sphere(1) + box(1), {}\n"
      "for i = 1, 1200000 do t[i] = s end\n"
      "return scene{objects=t}",
      "part.lua:3: scene: objects[1000001]: the scene would have more than 2000000 primitives");
  // A scene that fails (a bad entry, caught by pcall) gives its charge back.
  options.limits.memoryBytes = 16u << 20;
  EXPECT_EQ(
      scriptError("local l, t = point_light{pos={0, 0, 10}}, {}\n"
                  "for i = 1, 20000 do t[i] = l end\n"
                  "t[#t + 1] = 5\n"
                  "for i = 1, 100 do assert(not pcall(scene, {objects=sphere(1), lights=t})) end\n"
                  "return sphere(1)",
                  options),
      "(no error)");
}

// A NUL byte in a string parameter would end it early where fontconfig,
// HarfBuzz or the file system read it: refused. In a value a message
// quotes (or an error's own text), it shows as '?' rather than ending
// the message there.
TEST(ScriptStrings, ANulByteIsRefusedOrShown) {
  EXPECT_EQ(scriptError("return linear_extrude{text{'Hi', font='DejaVu Sans\\0Bold'}, height=1}"),
            "part.lua:1: text: font contains a NUL byte");
  EXPECT_EQ(scriptError("return linear_extrude{text{'H\\0i'}, height=1}"),
            "part.lua:1: text: text contains a NUL byte");
  EXPECT_EQ(scriptError("return import_svg{file='a.svg\\0.png'}"),
            "part.lua:1: import_svg: file name contains a NUL byte");
  expectError("return box(1):material{color='red\\0x'}", "color 'red?x' is not a colour name");
  EXPECT_EQ(scriptError("error('before\\0after')"), "part.lua:1: before?after");
}

}  // namespace
}  // namespace csgray::detail
