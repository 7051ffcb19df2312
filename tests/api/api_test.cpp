// The public API (include/csgray/), linked as a user links it, against the
// shared library: analytic volumes of shapes and booleans, containment,
// errors with the script's messages, export, check, render and scripts.
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

#include "../io/scratch_folder.h"
#include "csgray/csgray.h"
#include "error_of.h"

namespace {

using csgray::Error;
using csgray::ErrorCode;
using csgray::Solid;
using csgray::Vec3;
using csgray::test::errorOf;

constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void expectVolume(const Solid& solid, double exact, double relative = 1e-3) {
  EXPECT_NEAR(solid.volume(), exact, relative * exact) << solid.kind();
}

// The message of a one-line script that fails, without its "part.lua:1: ".
std::string scriptMessage(const std::string& source) {
  auto [code, message] = errorOf([&] { csgray::runScriptText(source, "part.lua"); });
  EXPECT_EQ(code, ErrorCode::ScriptError) << source;
  EXPECT_EQ(message.rfind("part.lua:1: ", 0), 0u) << message;
  return message.substr(std::min<std::size_t>(message.size(), 12));
}

TEST(ApiSolid, VolumesOfShapesAreAnalytic) {
  expectVolume(Solid::sphere(2), 4.0 / 3.0 * kPi * 8.0);
  expectVolume(Solid::box({2, 3, 4}), 24.0, 1e-12);
  expectVolume(Solid::box(3, true), 27.0, 1e-12);
  expectVolume(Solid::cylinder(2, 1), 2 * kPi);
  expectVolume(Solid::cone(3, 2, 1), kPi * 3 * (4 + 2 + 1) / 3);
  expectVolume(Solid::ellipsoid({1, 2, 3}), 4.0 / 3.0 * kPi * 6);
  expectVolume(Solid::torus(3, 1), 2 * kPi * kPi * 3);
  expectVolume(Solid::superellipsoid({1, 2, 3}, 1, 1), 4.0 / 3.0 * kPi * 6);
  expectVolume(Solid::superellipsoid({1, 1, 1}, 2, 2), 4.0 / 3.0);  // |x| + |y| + |z| <= 1
  // A lone ball of a blob: the ball of radius r·√(1 − √(t/s)).
  expectVolume(Solid::blob({{{1, 2, 3}, 2.0, 1.0}}, 0.5),
               4.0 / 3.0 * kPi * std::pow(2.0 * std::sqrt(1.0 - std::sqrt(0.5)), 3));
  expectVolume(Solid::octahedron(2), 4.0 / 3.0 * 8);
  expectVolume(Solid::hexahedron(std::sqrt(3.0)), 8.0, 1e-9);
  // A unit cube from half-spaces, and from a polyhedron's faces.
  std::vector<csgray::Plane> planes;
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 n;
    (axis == 0 ? n.x : axis == 1 ? n.y : n.z) = 1;
    planes.push_back({n, 1});
    planes.push_back({-1 * n, 0});
  }
  expectVolume(Solid::convex(planes), 1.0, 1e-9);
  // An unbounded quadric bounded by clip: a circular cylinder of radius 1.
  expectVolume(Solid::ellipticCylinder(1, 1).clip(csgray::Bounds{{-2, -2, 0}, {2, 2, 5}}), 5 * kPi);
}

// Steiner's formula for a box plus a ball; Pappus's for the rounded
// cylinder (docs/script.md, "Hull and Minkowski").
TEST(ApiSolid, HullAndMinkowskiAreAnalytic) {
  const double r = 0.5, a = 3, b = 2, c = 1;
  const double rounded = a * b * c + 2 * r * (a * b + b * c + c * a) + kPi * r * r * (a + b + c) +
                         4.0 / 3.0 * kPi * r * r * r;
  expectVolume(Solid::minkowski({Solid::box({a, b, c}), Solid::sphere(r)}), rounded);
  expectVolume(Solid::roundedBox({a + 2 * r, b + 2 * r, c + 2 * r}, r), rounded);
  expectVolume(Solid::hull({Solid::box(1), Solid::box(1).translate({2, 0, 0})}), 3.0, 1e-9);
  const double R = 2, f = 0.5, h = 4, inner = R - f;
  // Height first, as Solid::cylinder: a rod 4 high, not a disc 2 high.
  expectVolume(Solid::roundedCylinder(h, R, f),
               kPi * inner * inner * h + kPi * (R * R - inner * inner) * (h - 2 * f) +
                   kPi * kPi * f * f * (inner + 4 * f / (3 * kPi)));
}

TEST(ApiSolid, VolumesOfBooleansAreAnalytic) {
  const Solid a = Solid::sphere(1), b = Solid::sphere(1).translate({1, 0, 0});
  // Two unit balls one radius apart share a lens of π(4r + d)(2r − d)²/12.
  const double lens = kPi * 5.0 / 12.0;
  expectVolume(a * b, lens);
  expectVolume(a + b, 2 * 4.0 / 3.0 * kPi - lens);
  expectVolume(a - b, 4.0 / 3.0 * kPi - lens);
  // A cube with a hole through it, and the n-ary forms.
  const Solid cube = Solid::box(10, true);
  const Solid hole = Solid::cylinder(12, 2, true);
  expectVolume(cube - hole, 1000 - kPi * 4 * 10);
  expectVolume(Solid::differenceOf({cube, hole, hole.rotate({90, 0, 0})}),
               1000 - 2 * kPi * 4 * 10 + 16.0 / 3.0 * 8);  // two holes meet in a Steinmetz solid
  // (Cells that straddle a box's face are sampled: within 1e-3 again.)
  expectVolume(Solid::unionOf({Solid::box(1), Solid::box(1).translate({2, 0, 0})}), 2.0);
  expectVolume(Solid::intersectionOf({Solid::box(2), Solid::box(2).translate({1, 1, 1})}), 1.0,
               1e-12);
  // Transforms: a scale multiplies the volume by its determinant.
  expectVolume(Solid::sphere(1).scale({2, 3, 4}), 4.0 / 3.0 * kPi * 24);
  expectVolume(Solid::box(1).mirror({1, 1, 0}).rotate(30, {1, 2, 3}), 1.0, 1e-3);
  EXPECT_EQ(Solid::sphere(1).primitiveCount(), 1u);
  EXPECT_EQ((cube - hole).kind(), "difference");
  // An unbounded solid has no volume.
  EXPECT_EQ(errorOf([] {
              Solid::halfSpace({0, 0, 1}).volume();
            }).first,
            ErrorCode::InvalidArgument);
  // Nor one past the largest double: an error, not infinity or NaN.
  for (double r : {1e150, 1e300})
    EXPECT_EQ(errorOf([r] { Solid::sphere(r).volume(); }),
              std::make_pair(ErrorCode::InvalidArgument,
                             std::string("volume: the solid is too large for its volume to be a "
                                         "number")))
        << r;
}

// A part turned at each step of a loop, as a gear is turned to take its
// next tooth: its bounds() stay the part's, so volume()'s grids cover it,
// and a 2 mm cube turned 144 times is exported, not refused as reaching
// past where 32-bit floats hold the tolerance.
TEST(ApiSolid, APartTurnedAtEachStepKeepsItsSize) {
  Solid gear = Solid::cylinder(2, 10);
  const Solid tooth = Solid::box({2.5, 1, 2}).translate({9.5, -0.5, 0});
  for (int i = 0; i < 36; ++i) gear = (gear + tooth).rotate({0, 0, 10});
  // The teeth's outer corners are √(12² + 0.5²) from the axis.
  const csgray::Bounds box = gear.bounds();
  EXPECT_LE(box.hi.x, std::sqrt(144.25) + 1e-9);
  EXPECT_GE(box.lo.y, -std::sqrt(144.25) - 1e-9);
  // The disc, and 36 teeth less each one's part inside the rim (the
  // circle's segment beyond x = 9.5 over |y| <= 0.5, 2 high).
  const double inside = 2.0 * (0.5 * std::sqrt(99.75) + 100.0 * std::asin(0.05) - 9.5);
  expectVolume(gear, 200.0 * kPi + 36.0 * (5.0 - inside), 1e-3);

  Solid cube = Solid::box(2, true);
  for (int i = 0; i < 144; ++i) cube = (cube + Solid::sphere(0.2)).rotate({0, 0, 10});
  EXPECT_LE(cube.bounds().hi.x, std::sqrt(2.0) + 1e-9);
  const csgray::Mesh mesh = csgray::exportMesh(cube);
  EXPECT_EQ(csgray::meshDefect(mesh).kind, csgray::MeshDefect::Kind::None);
  EXPECT_NEAR(mesh.volume(), 8.0, 1e-9);
}

// A cube of 10 less its top half: bounds() is the cube's (a difference's
// box is its first operand's), ownBounds() the half's; resize measures that.
TEST(ApiSolid, ResizeMeasuresTheSolidsOwnBox) {
  const Solid half = Solid::box(10) - Solid::box({10, 10, 5}).translate({0, 0, 5});
  EXPECT_NEAR(half.bounds().hi.z, 10.0, 1e-9);
  EXPECT_NEAR(half.ownBounds().hi.z, 5.0, 1e-6);
  EXPECT_NEAR(half.ownBounds().lo.x, 0.0, 1e-6);
  // x to 20, the rest kept; then with every axis auto, all by 2 as x.
  expectVolume(half.resize({20, 0, 0}), 1000.0);
  expectVolume(half.resize({20, 0, 0}, {true, true, true}), 4000.0);
  // z to 10 measures the half's 5: factor 2, as OpenSCAD's resize.
  EXPECT_NEAR(half.resize({0, 0, 10}).ownBounds().hi.z, 10.0, 1e-6);
  EXPECT_EQ(errorOf([&] { half.resize({-1, 0, 0}); }).first, ErrorCode::InvalidArgument);
}

TEST(ApiSolid, ContainsKnownPoints) {
  const Solid ball = Solid::sphere(1);
  EXPECT_TRUE(ball.contains({0, 0, 0}));
  EXPECT_TRUE(ball.contains({0.99, 0, 0}));
  EXPECT_FALSE(ball.contains({1.01, 0, 0}));
  const Solid part = Solid::box(10, true) - Solid::cylinder(12, 2, true);
  EXPECT_FALSE(part.contains({0, 0, 0}));  // in the hole
  EXPECT_TRUE(part.contains({3, 0, 0}));
  EXPECT_FALSE(part.contains({6, 0, 0}));  // outside the cube
  const Solid moved = part.translate({100, 0, 0});
  EXPECT_TRUE(moved.contains({103, 0, 0}));
  EXPECT_FALSE(moved.contains({3, 0, 0}));
  // Bounds of a moved box, and of an unbounded solid.
  const csgray::Bounds b = Solid::box({1, 2, 3}).translate({1, 1, 1}).bounds();
  EXPECT_EQ(b.lo, (Vec3{1, 1, 1}));
  EXPECT_EQ(b.hi, (Vec3{2, 3, 4}));
  EXPECT_FALSE(Solid::halfSpace({0, 0, 1}).bounds().finite());
}

// A bad parameter is InvalidArgument with the message the script gives for
// the same call.
TEST(ApiSolid, BadParametersGiveTheScriptsMessages) {
  struct Case {
    std::string script;
    std::function<void()> call;
  } cases[] = {
      {"return sphere(-1)", [] { Solid::sphere(-1); }},
      {"return sphere(0)", [] { Solid::sphere(0); }},
      {"return box{0, 1, 1}",
       [] {
         Solid::box({0, 1, 1});
       }},
      {"return cylinder{h=2, r=-1}", [] { Solid::cylinder(2, -1); }},
      {"return cylinder{h=0, r=1}", [] { Solid::cylinder(0, 1); }},
      {"return cone{h=2, r1=-1}", [] { Solid::cone(2, -1); }},
      {"return cone{h=2, r1=0, r2=0}", [] { Solid::cone(2, 0, 0); }},
      {"return torus{R=-1, r=1}", [] { Solid::torus(-1, 1); }},
      {"return torus{R=2, r=0}", [] { Solid::torus(2, 0); }},
      {"return blob{balls={{r=1, strength=0}}}",
       [] {
         Solid::blob({{{0, 0, 0}, 1.0, 0.0}});
       }},
      {"return superellipsoid{radii=1, e=3, n=1}",
       [] {
         Solid::superellipsoid({1, 1, 1}, 3, 1);
       }},
      {"return superellipsoid{radii={1, 0, 1}, e=1, n=1}",
       [] {
         Solid::superellipsoid({1, 0, 1}, 1, 1);
       }},
      {"return ellipsoid{radii={1, 0, 1}}",
       [] {
         Solid::ellipsoid({1, 0, 1});
       }},
      {"return half_space{normal={0, 0, 0}}",
       [] {
         Solid::halfSpace({0, 0, 0});
       }},
      {"return hyperboloid1{a=1, b=-2, c=1}", [] { Solid::hyperboloid1(1, -2, 1); }},
      {"return parabolic_cylinder{p=0}", [] { Solid::parabolicCylinder(0); }},
      {"return elliptic_cylinder{a=1e-300, b=1}", [] { Solid::ellipticCylinder(1e-300, 1); }},
      {"return icosahedron(-2)", [] { Solid::icosahedron(-2); }},
      {"return convex{planes={{normal={0, 0, 0}, offset=1}}}",
       [] {
         Solid::convex({{{0, 0, 0}, 1}});
       }},
      {"return polyhedron{points={{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, faces={{0, 1, 2}}}",
       [] {
         Solid::polyhedron({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
       }},
      {"return clip(half_space{normal={0, 0, 1}}, {lo={0, 0, 0}, hi={1, -1, 1}})",
       [] {
         Solid::halfSpace({0, 0, 1}).clip(csgray::Bounds{{0, 0, 0}, {1, -1, 1}});
       }},
      {"return sphere(1):scale(1, 0, 1)",
       [] {
         Solid::sphere(1).scale({1, 0, 1});
       }},
      {"return sphere(1):material{ambient=2}",
       [] {
         csgray::Material m;
         m.ambient = 2;
         Solid::sphere(1).material(m);
       }},
      {"return sphere(1):material{color=checker{size=0}}",
       [] { csgray::Texture::checker(std::nullopt, 0); }},
      {"return sphere(1):material{color=wood{octaves=17}}",
       [] { csgray::Texture::noise(csgray::Texture::Noise::Wood, std::nullopt, 17); }},
      {"return sphere(1):material{color=julia{iterations=0}}",
       [] {
         csgray::Texture::fractal(csgray::Texture::Fractal::Julia, std::nullopt, {0, 0, 0}, 0);
       }},
      // A NaN or an infinity, as the script refuses one (1/0 and 0/0 there).
      {"return sphere(1/0)", [] { Solid::sphere(kInf); }},
      {"return sphere(0/0)", [] { Solid::sphere(kNaN); }},
      {"return box{1/0, 1, 1}",
       [] {
         Solid::box({kInf, 1, 1});
       }},
      {"return box(0/0)", [] { Solid::box(kNaN); }},
      {"return ellipsoid{radii={1, 0/0, 1}}",
       [] {
         Solid::ellipsoid({1, kNaN, 1});
       }},
      {"return cylinder{h=1/0, r=1}", [] { Solid::cylinder(kInf, 1); }},
      {"return cylinder{h=2, r=0/0}", [] { Solid::cylinder(2, kNaN); }},
      {"return cone{h=2, r1=1/0}", [] { Solid::cone(2, kInf); }},
      {"return cone{h=2, r1=1, r2=0/0}", [] { Solid::cone(2, 1, kNaN); }},
      {"return torus{R=1/0, r=1}", [] { Solid::torus(kInf, 1); }},
      {"return torus{R=2, r=0/0}", [] { Solid::torus(2, kNaN); }},
      {"return superellipsoid{radii=1, e=0/0, n=1}",
       [] {
         Solid::superellipsoid({1, 1, 1}, kNaN, 1);
       }},
      {"return half_space{normal={0, 0, 1/0}}",
       [] {
         Solid::halfSpace({0, 0, kInf});
       }},
      {"return half_space{normal={0, 0, 1}, offset=0/0}",
       [] {
         Solid::halfSpace({0, 0, 1}, kNaN);
       }},
      {"return hyperboloid1{a=1, b=1/0, c=1}", [] { Solid::hyperboloid1(1, kInf, 1); }},
      {"return parabolic_cylinder{p=0/0}", [] { Solid::parabolicCylinder(kNaN); }},
      {"return icosahedron(1/0)", [] { Solid::icosahedron(kInf); }},
      {"return tetrahedron{r=0/0}", [] { Solid::tetrahedron(kNaN); }},
      {"return disc{r=0}", [] { csgray::Surface::disc(0); }},
      {"return square{size=-1}", [] { csgray::Surface::square(-1); }},
      {"return plane{normal={0, 0, 0}}",
       [] {
         csgray::Surface::plane({0, 0, 0});
       }},
      {"return mesh_surface{points={{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, faces={{0, 1, 3}}}",
       [] {
         csgray::Surface::mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 3}});
       }},
  };
  for (const Case& c : cases) {
    auto [code, message] = errorOf(c.call);
    EXPECT_EQ(code, ErrorCode::InvalidArgument) << c.script;
    EXPECT_FALSE(message.empty());
    EXPECT_EQ(message, scriptMessage(c.script));
  }
}

TEST(ApiScene, BadValuesGiveTheScriptsMessages) {
  const std::string objects = "return scene{objects=sphere(1), ";
  struct Case {
    std::string script;
    std::function<void(csgray::Scene&)> call;
  } cases[] = {
      {objects + "camera=camera{eye={0, 0, 0}, look_at={0, 0, 0}}}",
       [](csgray::Scene& s) {
         csgray::Camera c;
         c.eye = c.lookAt = {0, 0, 0};
         s.setCamera(c);
       }},
      {objects + "camera=camera{fov=180}}",
       [](csgray::Scene& s) {
         csgray::Camera c;
         c.fov = 180;
         s.setCamera(c);
       }},
      {objects + "camera=camera{width=10}}",
       [](csgray::Scene& s) {
         csgray::Camera c;
         c.width = 10;
         s.setCamera(c);
       }},
      {objects + "camera=camera{up={0, 1, 0}, eye={0, -5, 0}}}",
       [](csgray::Scene& s) {
         csgray::Camera c;
         c.up = {0, 1, 0};
         c.eye = {0, -5, 0};
         s.setCamera(c);
       }},
      {objects + "camera=camera{aperture=1, focal_point={0, -20, 0}}}",
       [](csgray::Scene& s) {
         csgray::Camera c;
         c.aperture = 1;
         c.focalPoint = Vec3{0, -20, 0};
         s.setCamera(c);
       }},
      {objects + "fog={color={1, 1, 1}, distance=-2}}",
       [](csgray::Scene& s) {
         s.setFog(csgray::Fog{{1, 1, 1}, -2});
       }},
      {objects + "lights=spot_light{pos={0, 0, 1}, look_at={0, 0, 0}, angle=90}}",
       [](csgray::Scene& s) {
         s.add(csgray::Light::spot({0, 0, 1}, {0, 0, 0}, 90));
       }},
      {objects + "lights=area_light{pos={0, 0, 1}, u={1, 0, 0}, v={2, 0, 0}}}",
       [](csgray::Scene& s) {
         s.add(csgray::Light::area({0, 0, 1}, {1, 0, 0}, {2, 0, 0}));
       }},
      {objects + "lights=sphere_light{pos={0, 0, 1}, r=1, samples=0}}",
       [](csgray::Scene& s) {
         csgray::Light l = csgray::Light::sphere({0, 0, 1}, 1);
         l.samples = 0;
         s.add(l);
       }},
      {objects + "lights=point_light{pos={0, 0, 1}, intensity=-1}}",
       [](csgray::Scene& s) {
         csgray::Light l = csgray::Light::point({0, 0, 1});
         l.intensity = -1;
         s.add(l);
       }},
      {objects + "max_depth=65}", [](csgray::Scene& s) { s.setMaxDepth(65); }},
      {objects + "min_weight=2}", [](csgray::Scene& s) { s.setMinWeight(2); }},
      {objects + "background={-1, 0, 0}}",
       [](csgray::Scene& s) {
         s.setBackground({-1, 0, 0});
       }},
  };
  for (const Case& c : cases) {
    csgray::Scene scene(Solid::sphere(1));
    auto [code, message] = errorOf([&] { c.call(scene); });
    EXPECT_EQ(code, ErrorCode::InvalidArgument) << c.script;
    EXPECT_EQ(message, scriptMessage(c.script));
  }
  // A scene without objects renders nothing, as scene{} says.
  auto [code, message] = errorOf([] { csgray::render(csgray::Scene(), {16, 16}); });
  EXPECT_EQ(code, ErrorCode::InvalidArgument);
  EXPECT_EQ(message, scriptMessage("return scene{}"));
}

TEST(ApiScene, HoldsWhatItIsGivenAndCopiesAreValues) {
  csgray::Scene scene(Solid::sphere(1));
  scene.add(csgray::Surface::plane({0, 0, 1}, -1));
  scene.add(csgray::Light::spot({0, 0, 5}, {0, 0, 0}, 20));
  csgray::Camera camera;
  camera.projection = csgray::Camera::Projection::Orthographic;
  camera.width = 4;
  scene.setCamera(camera).setBackground({0.1, 0.2, 0.3}).setMaxDepth(3);
  EXPECT_FALSE(scene.fog());
  scene.setFog(csgray::Fog{{0.5, 0.6, 0.7}, 30});
  const csgray::Scene copy = scene;
  scene.add(Solid::box(1));
  EXPECT_EQ(scene.objects().size(), 2u);
  EXPECT_EQ(copy.objects().size(), 1u);
  ASSERT_EQ(copy.surfaces().size(), 1u);
  EXPECT_EQ(copy.surfaces()[0].kind(), "plane");
  ASSERT_EQ(copy.lights().size(), 1u);
  EXPECT_EQ(copy.lights()[0].kind, csgray::Light::Kind::Spot);
  EXPECT_EQ(copy.lights()[0].angle, 20.0);
  ASSERT_TRUE(copy.lights()[0].direction);
  EXPECT_EQ(*copy.lights()[0].direction, (Vec3{0, 0, -5}));
  ASSERT_TRUE(copy.camera());
  EXPECT_EQ(copy.camera()->width, 4.0);
  EXPECT_EQ(copy.camera()->aperture, 0.0);
  camera.projection = csgray::Camera::Projection::Perspective;
  camera.width.reset();
  camera.aperture = 0.25;
  camera.focalPoint = Vec3{0, 3, 0};
  camera.blurSamples = 9;
  const csgray::Camera lens = *csgray::Scene(scene).setCamera(camera).camera();
  EXPECT_EQ(lens.aperture, 0.25);
  EXPECT_EQ(lens.focalPoint, (Vec3{0, 3, 0}));
  EXPECT_EQ(lens.blurSamples, 9);
  EXPECT_EQ(copy.background(), (Vec3{0.1, 0.2, 0.3}));
  EXPECT_EQ(copy.maxDepth(), 3);
  ASSERT_TRUE(copy.fog());
  EXPECT_EQ(copy.fog()->color, (Vec3{0.5, 0.6, 0.7}));
  EXPECT_EQ(copy.fog()->distance, 30.0);
  EXPECT_FALSE(copy.fog()->altitude > 0.0);
  EXPECT_EQ(csgray::Scene(scene).setFog(csgray::Fog{{1, 1, 1}, 5, 2, 3}).fog()->altitude, 3.0);
  EXPECT_EQ(errorOf([&] {
              csgray::Scene(scene).setFog(csgray::Fog{{1, 1, 1}, 5, 2, -3});
            }).first,
            ErrorCode::InvalidArgument);
  EXPECT_FALSE(scene.setFog(std::nullopt).fog());
  EXPECT_FALSE(copy.backgroundTexture());
  csgray::Scene sky = copy;
  sky.setBackground(csgray::Texture::gradient());
  EXPECT_TRUE(sky.backgroundTexture());
  EXPECT_FALSE(sky.setBackground(Vec3{0, 0, 0}).backgroundTexture());  // a colour replaces it
  // Stops, as the script's colour maps.
  csgray::Texture::Colors map{
      {0, 0, 0}, {0, 0, 0}, {{0.0, {1, 0, 0}}, {0.5, {0, 1, 0}}, {1.0, {0, 0, 1}}}};
  EXPECT_EQ(csgray::Texture::gradient(map).colorAt({0, 0, 0.75}, {0, 0, 1}), (Vec3{0, 0.5, 0.5}));
  EXPECT_EQ(errorOf([&] { csgray::Texture::checker(map); }).second,
            "checker: colors must be two colours, not stops");
  // The fractals as the script's mandelbrot{} and julia{} (Douady's rabbit
  // by default): a floor of each, seen from above, renders the same pixels.
  const std::string floor =
      "return scene{objects=plane{}:material{ambient=1, diffuse=0, color=%s}, lights={}, "
      "camera=camera{eye={0, 0, 3}, look_at={0, 0, 0}, up={0, 1, 0}}}";
  const csgray::Texture::Colors rgb{
      {0, 0, 0}, {0, 0, 0}, {{0, {1, 0, 0}}, {0.5, {0, 1, 0}}, {1, {0, 0, 1}}}};
  const struct {
    const char* script;
    csgray::Texture texture;
  } fractals[] = {
      {"julia{}", csgray::Texture::fractal(csgray::Texture::Fractal::Julia)},
      {"mandelbrot{colors={{0, {1, 0, 0}}, {0.5, {0, 1, 0}}, {1, {0, 0, 1}}}, inside={1, 1, 1}, "
       "iterations=50}",
       csgray::Texture::fractal(csgray::Texture::Fractal::Mandelbrot, rgb, {1, 1, 1}, 50)},
  };
  for (const auto& f : fractals) {
    std::string source = floor;
    source.replace(source.find("%s"), 2, f.script);
    const csgray::Scene scripted = csgray::runScriptText(source, "fractal.lua");
    csgray::Material m;
    m.ambient = 1;
    m.diffuse = 0;
    m.texture = f.texture;
    csgray::Scene built;
    built.add(csgray::Surface::plane({0, 0, 1}, 0).material(m)).setDefaultLight(false);
    built.setCamera(*scripted.camera()).setBackground(scripted.background());
    const csgray::Image image = csgray::render(built, {32, 24});
    EXPECT_TRUE(image.rgb == csgray::render(scripted, {32, 24}).rgb) << f.script;
    EXPECT_NE(image.at(0, 0), image.at(16, 12)) << f.script;  // not one colour
  }
  map.stops[2].at = 0.25;
  EXPECT_EQ(errorOf([&] { csgray::Texture::noise(csgray::Texture::Noise::Marble, map); }).second,
            "marble: colors[3]: stops must be in order of their places");
  EXPECT_EQ(copy.part().kind(), "sphere");
  EXPECT_EQ(scene.part().kind(), "union");
  EXPECT_EQ(errorOf([] { csgray::Scene().part(); }).first, ErrorCode::InvalidArgument);
}

// Solids, surfaces and textures are immutable values: one moved from
// still holds what it held (it was empty, and using it crashed).
TEST(ApiScene, ValuesMovedFromStillHoldTheirShapes) {
  Solid ball = Solid::sphere(2);
  const Solid taken = std::move(ball);
  // NOLINTBEGIN(bugprone-use-after-move): the point of the test
  EXPECT_EQ(ball.kind(), "sphere");
  EXPECT_EQ(ball.bounds().hi, (Vec3{2, 2, 2}));
  EXPECT_TRUE(ball.translate({1, 0, 0}).contains({2.5, 0, 0}));
  Solid box = Solid::box(1);
  box = std::move(ball);
  EXPECT_EQ(box.kind(), "sphere");
  EXPECT_EQ(ball.kind(), "sphere");
  expectVolume(csgray::Scene(ball).part(), 4.0 / 3.0 * kPi * 8);
  csgray::Surface floor = csgray::Surface::plane();
  const csgray::Surface moved = std::move(floor);
  EXPECT_EQ(floor.kind(), "plane");
  EXPECT_EQ(csgray::Scene().add(floor).surfaces().size(), 1u);
  csgray::Texture checker = csgray::Texture::checker();
  const csgray::Texture other = std::move(checker);
  EXPECT_EQ(checker.colorAt({0.5, 0.5, 0.5}, {0, 0, 1}), other.colorAt({0.5, 0.5, 0.5}, {0, 0, 1}));
  // NOLINTEND(bugprone-use-after-move)
  EXPECT_EQ(taken.kind(), "sphere");
}

TEST(ApiScene, AMeshSurfaceIsASurface) {
  // Two triangles of the unit square at z = 1, moved up by 2: the sheet
  // renders as the script's mesh_surface{} does, and is no part.
  const csgray::Surface sheet =
      csgray::Surface::mesh({{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}, {{0, 1, 2}, {0, 2, 3}})
          .translate({0, 0, 2});
  EXPECT_EQ(sheet.kind(), "mesh surface");
  EXPECT_NEAR(sheet.bounds().lo.z, 3.0, 1e-6);
  EXPECT_NEAR(sheet.bounds().hi.x, 1.0, 1e-6);
  csgray::Scene scene;
  scene.add(sheet);
  EXPECT_EQ(errorOf([&] { scene.part(); }).first, ErrorCode::InvalidArgument);
}

TEST(ApiExport, ASphereIsClosedAndWithinTheTolerance) {
  const double r = 5, tolerance = 0.01;
  csgray::ExportOptions options;
  options.tolerance = tolerance;
  const csgray::Mesh mesh = csgray::exportMesh(Solid::sphere(r), options);
  ASSERT_GT(mesh.triangles.size(), 100u);
  const csgray::MeshDefect defect = csgray::meshDefect(mesh);
  EXPECT_EQ(defect.kind, csgray::MeshDefect::Kind::None) << defect.text;
  // Every point of the mesh is within the tolerance of the surface, so its
  // volume is within the tolerance times the area.
  const double exact = 4.0 / 3.0 * kPi * r * r * r;
  EXPECT_NEAR(mesh.volume(), exact, tolerance * 4 * kPi * r * r);
  for (const Vec3& p : mesh.vertices)
    EXPECT_NEAR(std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z), r, tolerance);
  // One triangle's material per triangle; the sphere has none.
  EXPECT_EQ(mesh.triangleMaterial.size(), mesh.triangles.size());
  ASSERT_EQ(mesh.materials.size(), 1u);
  EXPECT_FALSE(mesh.materials[0]);
}

// fromMesh holds a mesh as a mesh file is held: a box's mesh is a solid;
// two overlapping boxes in one mesh, or a box inside out, are refused
// (they were taken, and failed only at the export).
TEST(ApiSolid, FromMeshRefusesWhatIsNotASolidsBoundary) {
  const csgray::Mesh box = csgray::exportMesh(Solid::box(2));
  expectVolume(Solid::fromMesh(box), 8.0, 1e-9);
  csgray::Mesh two = box;
  const csgray::Mesh moved = csgray::exportMesh(Solid::box(2).translate({1, 1, 1}));
  for (const Vec3& p : moved.vertices) two.vertices.push_back(p);
  for (auto t : moved.triangles) {
    for (auto& i : t) i += std::uint32_t(box.vertices.size());
    two.triangles.push_back(t);
  }
  auto [code, message] = errorOf([&] { Solid::fromMesh(two); });
  EXPECT_EQ(code, ErrorCode::InvalidArgument);
  EXPECT_EQ(message.rfind("mesh: self-intersecting", 0), 0u) << message;
  csgray::Mesh inverted = box;
  for (auto& t : inverted.triangles) std::swap(t[1], t[2]);
  std::tie(code, message) = errorOf([&] { Solid::fromMesh(inverted); });
  EXPECT_EQ(code, ErrorCode::InvalidArgument);
  EXPECT_NE(message.find("inside out"), std::string::npos) << message;
}

TEST(ApiExport, DefectsAndFailuresAreTyped) {
  csgray::Mesh open = csgray::exportMesh(Solid::box(1));
  open.triangles.pop_back();
  const csgray::MeshDefect defect = csgray::meshDefect(open);
  EXPECT_EQ(defect.kind, csgray::MeshDefect::Kind::Open);
  EXPECT_EQ(defect.text.rfind("open: ", 0), 0u) << defect.text;
  EXPECT_EQ(csgray::meshDefect(csgray::Mesh()).kind, csgray::MeshDefect::Kind::Empty);
  // An unbounded part cannot be printed.
  EXPECT_EQ(errorOf([] {
              csgray::exportMesh(Solid::halfSpace({0, 0, 1}));
            }).first,
            ErrorCode::NotPrintable);
  csgray::ExportOptions coarse;
  coarse.tolerance = 0;
  EXPECT_EQ(errorOf([&] { csgray::exportMesh(Solid::box(1), coarse); }).first,
            ErrorCode::InvalidArgument);
}

class ApiFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = csgray::test::scratchPathFor("csgray_api_test_");
    std::filesystem::remove_all(folder_);
    std::filesystem::create_directories(folder_);
  }
  void TearDown() override { std::filesystem::remove_all(folder_); }
  std::string path(const std::string& name) const { return (folder_ / name).string(); }

  std::filesystem::path folder_;
};

TEST_F(ApiFiles, MeshesAndImagesAreWrittenAndReadBack) {
  const Solid part = Solid::box(10, true) - Solid::cylinder(12, 2, true);
  const csgray::Mesh mesh = csgray::exportMesh(part);
  csgray::writeMesh(mesh, path("part.stl"));
  const csgray::Mesh back = csgray::readMesh(path("part.stl"));
  EXPECT_EQ(back.triangles.size(), mesh.triangles.size());
  EXPECT_NEAR(back.volume(), mesh.volume(), 1e-3);
  EXPECT_EQ(csgray::meshDefect(back).kind, csgray::MeshDefect::Kind::None);
  // The mesh read back is a solid again.
  EXPECT_NEAR(Solid::fromMeshFile(path("part.stl")).volume(), mesh.volume(), 0.01 * mesh.volume());
  EXPECT_NEAR(Solid::fromMesh(back).volume(), mesh.volume(), 0.01 * mesh.volume());

  csgray::Image image = csgray::render(csgray::Scene(part), {64, 48});
  ASSERT_EQ(image.width, 64);
  ASSERT_EQ(image.height, 48);
  ASSERT_EQ(image.rgb.size(), 64u * 48u * 3u);
  csgray::writeImage(image, path("part.png"));
  EXPECT_GT(std::filesystem::file_size(path("part.png")), 100u);

  // Files that cannot be written or read are IoError; a format there is
  // none of is InvalidArgument.
  EXPECT_EQ(errorOf([&] { csgray::writeMesh(mesh, path("no/such/folder/part.stl")); }).first,
            ErrorCode::IoError);
  EXPECT_EQ(errorOf([&] { csgray::writeMesh(mesh, path("part.xyz")); }).first,
            ErrorCode::InvalidArgument);
  // A mesh without triangles would write a file that reads back as none.
  EXPECT_EQ(errorOf([&] { csgray::writeMesh(csgray::Mesh(), path("empty.stl")); }),
            std::make_pair(ErrorCode::InvalidArgument,
                           std::string("writeMesh: the mesh has no triangles")));
  EXPECT_FALSE(std::filesystem::exists(path("empty.stl")));
  EXPECT_EQ(errorOf([&] { csgray::readMesh(path("missing.stl")); }).first, ErrorCode::IoError);
  // A file that is not of its format cannot be read, as a mesh or as a
  // solid; a mesh that is read but bounds no solid is a bad argument.
  std::ofstream(path("garbage.stl")) << "solid x\nfacet normal 0 0 1\nouter loop\nvertex 1 2\n";
  std::ofstream(path("part.xyz")) << "1 2 3\n";
  std::ofstream(path("open.obj")) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  for (const char* name : {"garbage.stl", "part.xyz", "open.obj"}) {
    SCOPED_TRACE(name);
    const ErrorCode expected =
        std::string(name) == "garbage.stl" ? ErrorCode::IoError : ErrorCode::InvalidArgument;
    EXPECT_EQ(errorOf([&] { Solid::fromMeshFile(path(name)); }).first, expected);
    if (std::string(name) != "open.obj") {
      EXPECT_EQ(errorOf([&] { csgray::readMesh(path(name)); }).first, expected);
    }
  }
  EXPECT_EQ(csgray::readMesh(path("open.obj")).triangles.size(), 1u);
  EXPECT_EQ(errorOf([&] { csgray::writeImage(image, path("no/such/folder/x.png")); }).first,
            ErrorCode::IoError);
  // A name that names no image format is a bad argument, as for writeMesh.
  for (const char* name : {"x.xyz", "noext"}) {
    const auto [code, message] = errorOf([&] { csgray::writeImage(image, path(name)); });
    EXPECT_EQ(code, ErrorCode::InvalidArgument) << name;
    EXPECT_NE(message.find(name), std::string::npos) << message;
  }
}

// render() and writeImage() make the file the csgray command makes, with
// the default options: a bare part (bracket) in the CAD look, antialiased
// at its edges, as the others in their scenes.
// Height maps: over each cell, four triangles about its middle at the mean
// of its corners, so a cell's volume is its mean height less the base's;
// the base is one below the lowest height, or at z = 0 if that is lower.
// Heights 0, 2, 2, 4: mean 2, base −1, volume 3; a 3 × 3 grid of 2s: 8.
TEST_F(ApiFiles, HeightMapsFromRowsAndFilesAreOpenScadsSurfaces) {
  expectVolume(Solid::heightMap({{0, 2}, {2, 4}}), 3.0);
  expectVolume(Solid::heightMap({{2, 2, 2}, {2, 2, 2}, {2, 2, 2}}, true), 8.0);
  // A short row is filled up with 0: {5} is {5, 0}; mean 2.5, base −1.
  expectVolume(Solid::heightMap({{5}, {5, 0}}), 3.5);
  const csgray::Bounds centred = Solid::heightMap({{2, 2, 2}, {2, 2, 2}, {2, 2, 2}}, true).bounds();
  EXPECT_NEAR(centred.lo.x, -1.0, 1e-9);
  EXPECT_NEAR(centred.hi.y, 1.0, 1e-9);
  std::ofstream(path("heights.dat")) << "# two rows\n0 2\n2 4\n";
  expectVolume(Solid::heightMapFile(path("heights.dat")), 3.0);
  EXPECT_EQ(errorOf([] { Solid::heightMap({{1, 2}}); }).first, ErrorCode::InvalidArgument);
  EXPECT_EQ(errorOf([] {
              Solid::heightMap({{1, kNaN}, {1, 1}});
            }).first,
            ErrorCode::InvalidArgument);
  std::ofstream(path("bad.dat")) << "0 2\n2 x\n";
  const auto [code, message] = errorOf([&] { Solid::heightMapFile(path("bad.dat")); });
  EXPECT_EQ(code, ErrorCode::IoError);
  EXPECT_EQ(message.rfind("height_map: bad.dat:2:", 0), 0u) << message;
  EXPECT_EQ(errorOf([&] { Solid::heightMapFile(path("none.dat")); }).first, ErrorCode::IoError);
  // A file without a grid (empty, one row) holds nothing to build: IoError too.
  std::ofstream(path("row.dat")) << "1 2 3\n";
  EXPECT_EQ(errorOf([&] { Solid::heightMapFile(path("row.dat")); }).first, ErrorCode::IoError);
}

TEST_F(ApiFiles, ImagesAreTheCommandsPixelForPixel) {
  for (const char* name : {"spot_light", "textured_box", "glass_and_mirror", "bracket"}) {
    const std::string script = std::string(CSGRAY_SOURCE_DIR "/examples/") + name + ".lua";
    csgray::writeImage(csgray::render(csgray::runScript(script), {80, 60}), path("api.png"));
    const std::string command = std::string(CSGRAY_BINARY) + " render " + script + " -o " +
                                path("cli.png") + " --size 80x60 > /dev/null";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    std::ifstream api(path("api.png"), std::ios::binary), cli(path("cli.png"), std::ios::binary);
    const std::string apiBytes{std::istreambuf_iterator<char>(api), {}};
    const std::string cliBytes{std::istreambuf_iterator<char>(cli), {}};
    EXPECT_GT(apiBytes.size(), 100u) << name;
    EXPECT_TRUE(apiBytes == cliBytes) << name;
  }
}

TEST(ApiRender, ThePartFillsTheFrameOverTheBackground) {
  csgray::Scene scene(Solid::sphere(1));
  scene.setBackground({0, 0, 0});
  const csgray::Image image = csgray::render(scene, {40, 30});
  int lit = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) lit += image.at(x, y).x > 0;
  EXPECT_GT(lit, 40 * 30 / 10);
  EXPECT_GT(image.at(20, 15).x, 0.0f);  // the ball is in the middle
  EXPECT_EQ(image.at(0, 0), (Vec3{0, 0, 0}));
  EXPECT_EQ(errorOf([&] { csgray::render(scene, {0, 30}); }).first, ErrorCode::InvalidArgument);
}

// setDefaultLight(false) is the script's lights={}: no light beside the
// camera, so a ball without an ambient term is black, and the two renders
// are the same image.
TEST(ApiRender, WithoutTheDefaultLightAsTheScriptsEmptyLights) {
  const std::string ball =
      "return scene{objects=sphere(1):material{ambient=0}, background={0, 0, 0}, "
      "camera=camera{eye={0, -5, 0}, look_at={0, 0, 0}}";
  const csgray::Scene lit = csgray::runScriptText(ball + "}", "lit.lua");
  const csgray::Scene dark = csgray::runScriptText(ball + ", lights={}}", "dark.lua");
  EXPECT_TRUE(lit.defaultLight());
  EXPECT_FALSE(dark.defaultLight());
  csgray::Scene built = lit;
  built.setDefaultLight(false);
  EXPECT_FALSE(built.defaultLight());
  const csgray::Image image = csgray::render(built, {9, 9});
  EXPECT_TRUE(image.rgb == csgray::render(dark, {9, 9}).rgb);
  EXPECT_EQ(image.at(4, 4), (Vec3{0, 0, 0}));
  EXPECT_GT(csgray::render(lit, {9, 9}).at(4, 4).x, 0.1f);
}

// A material's bumps, ground fog, a lens and a sky reach the render as the
// script's do:
// the same pixels as the same scene{} of a script.
TEST(ApiRender, BumpsFogAndALensAsTheScriptsGiveThem) {
  const csgray::Scene script = csgray::runScriptText(
      "return scene{objects=sphere(1):material{bumps=perlin{scale=0.3}, bump_depth=0.2}, "
      "camera=camera{eye={0, -5, 0}, aperture=0.2, focal_point={0, 3, 0}, blur_samples=4}, "
      "fog={color={0.5, 0.6, 0.7}, distance=8, offset=0.5, altitude=2}, "
      "background=gradient{colors={{1, 1, 1}, {0, 0, 1}}, from={0, 0, 0}, to={0, 0, 1}}}",
      "bumps.lua");
  csgray::Material m;
  csgray::Texture::Placement smaller;
  smaller.scale = Vec3{0.3, 0.3, 0.3};
  m.bumps = csgray::Texture::noise(csgray::Texture::Noise::Perlin, std::nullopt, 6, 4.0, smaller);
  m.bumpDepth = 0.2;
  csgray::Camera camera;
  camera.eye = {0, -5, 0};
  camera.aperture = 0.2;
  camera.focalPoint = Vec3{0, 3, 0};
  camera.blurSamples = 4;
  csgray::Scene built;
  built.add(Solid::sphere(1).material(m)).setCamera(camera);
  built.setBackground(csgray::Texture::gradient(csgray::Texture::Colors{{1, 1, 1}, {0, 0, 1}}))
      .setFog(csgray::Fog{{0.5, 0.6, 0.7}, 8, 0.5, 2});
  const csgray::Image image = csgray::render(built, {24, 18});
  EXPECT_TRUE(image.rgb == csgray::render(script, {24, 18}).rgb);
  // Without the bumps the ball shades otherwise.
  m.bumps.reset();
  csgray::Scene smooth;
  smooth.add(Solid::sphere(1).material(m)).setCamera(camera);
  smooth.setBackground(csgray::Texture::gradient(csgray::Texture::Colors{{1, 1, 1}, {0, 0, 1}}))
      .setFog(csgray::Fog{{0.5, 0.6, 0.7}, 8, 0.5, 2});
  EXPECT_FALSE(image.rgb == csgray::render(smooth, {24, 18}).rgb);
}

// The default samples (0) are the command's: a bare part gets 9, adaptive
// (spent at its edges); a scene of the script's own one ray a pixel.
// Scene(part) is what a script that returns the part gives: the default
// look, the same image pixel for pixel. Its own background ends the look,
// as setDefaultLook(false) does.
TEST(ApiRender, ASceneOfOnePartIsTheScriptsBarePart) {
  const csgray::Scene script = csgray::runScriptText(
      "return box{size={40, 30, 8}, center=true} - cylinder{h=10, r=4, center=true}", "part.lua");
  csgray::Scene built(script.part());
  EXPECT_TRUE(script.defaultLook());
  EXPECT_TRUE(built.defaultLook());
  EXPECT_TRUE(csgray::render(built, {64, 48}).rgb == csgray::render(script, {64, 48}).rgb);
  // The gradient's corner, not the background colour of a scene{}.
  EXPECT_NE(csgray::render(built, {64, 48}).at(0, 0), built.background());
  csgray::Scene red = built;
  red.setBackground({1, 0, 0});
  EXPECT_FALSE(red.defaultLook());
  EXPECT_EQ(csgray::render(red, {64, 48}).at(0, 0), (Vec3{1, 0, 0}));
  csgray::Scene plain = built;
  plain.setDefaultLook(false);
  const Vec3 corner = csgray::render(plain, {64, 48}).at(0, 0);
  const Vec3 dark = plain.background();  // the image holds it as floats
  EXPECT_NEAR(corner.x, dark.x, 1e-7);
  EXPECT_NEAR(corner.y, dark.y, 1e-7);
  EXPECT_NEAR(corner.z, dark.z, 1e-7);
  EXPECT_FALSE(csgray::Scene().add(Solid::sphere(1)).defaultLook());
}

// A render another thread stops: set before the call, it stops at the
// first pixel; set while the threads are at work, at the pixel they are
// at (a render that long, 4096 × 4096 at 64 rays a pixel, would take
// minutes); left unset, the image is made.
TEST(ApiRender, ARenderStopsWhenCancelled) {
  const csgray::Scene scene(Solid::sphere(1) - Solid::box(1));
  std::atomic<bool> cancel = true;
  csgray::RenderOptions options{64, 48};
  options.cancel = &cancel;
  EXPECT_EQ(errorOf([&] { csgray::render(scene, options); }),
            std::make_pair(ErrorCode::Cancelled, std::string("render: cancelled")));
  cancel = false;
  EXPECT_EQ(csgray::render(scene, options).width, 64);
  options.width = options.height = 4096;
  options.samples = 64;
  std::thread stop([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    cancel = true;
  });
  EXPECT_EQ(errorOf([&] { csgray::render(scene, options); }).first, ErrorCode::Cancelled);
  stop.join();
}

TEST(ApiRender, DefaultSamplesAreTheCommands) {
  const csgray::Scene bare = csgray::runScriptText("return sphere(1)", "part.lua");
  csgray::RenderOptions nine{40, 30};
  nine.samples = 9;
  nine.adaptive = true;
  csgray::RenderOptions one{40, 30};
  one.samples = 1;
  const csgray::Image smooth = csgray::render(bare, {40, 30});
  EXPECT_TRUE(smooth.rgb == csgray::render(bare, nine).rgb);
  EXPECT_FALSE(smooth.rgb == csgray::render(bare, one).rgb);
  const csgray::Scene own = csgray::runScriptText("return scene{objects={sphere(1)}}", "part.lua");
  EXPECT_TRUE(csgray::render(own, {40, 30}).rgb == csgray::render(own, one).rgb);
  EXPECT_EQ(errorOf([&] {
              csgray::render(bare, {40, 30, 0, -1});
            }).first,
            ErrorCode::InvalidArgument);
}

// A ball drilled by 40 rods that all cross at its centre: seconds to
// export at a fine tolerance (8.6 s on a 2-core machine), each rod a
// boolean and most of them corefinements.
Solid drilledBall() {
  Solid ball = Solid::sphere(20);
  for (int i = 1; i <= 40; ++i)
    ball = ball - Solid::cylinder(60, 1.5, true).rotate({i * 37.0, i * 13.0, 0.0});
  return ball;
}

// What cancel does to a long call made on this thread: set before it, the
// call stops at its first step; set by another thread 0.2 s into it, at
// the step it is at (left alone, the call runs for seconds and gives no
// error, which the test reports).
void expectStopsWhenCancelled(std::atomic<bool>& cancel, const std::string& message,
                              const std::function<void()>& call) {
  cancel = true;
  EXPECT_EQ(errorOf(call), std::make_pair(ErrorCode::Cancelled, message));
  cancel = false;
  std::thread stop([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    cancel = true;
  });
  EXPECT_EQ(errorOf(call).first, ErrorCode::Cancelled);
  stop.join();
}

TEST(ApiMesh, AnExportStopsWhenCancelled) {
  std::atomic<bool> cancel = false;
  csgray::ExportOptions options;
  options.cancel = &cancel;
  // Unset, the export is made.
  EXPECT_NEAR(csgray::exportMesh(Solid::box(2), options).volume(), 8.0, 1e-9);
  options.tolerance = 0.002;
  expectStopsWhenCancelled(cancel, "exportMesh: cancelled",
                           [&] { csgray::exportMesh(drilledBall(), options); });
}

TEST(ApiCheck, ACheckStopsWhenCancelled) {
  std::atomic<bool> cancel = false;
  csgray::CheckOptions options;
  options.cancel = &cancel;
  options.samples = 1000;
  options.grid = 16;
  EXPECT_TRUE(csgray::check(Solid::box(2), options).ok);
  options.tolerance = 0.002;
  expectStopsWhenCancelled(cancel, "check: cancelled",
                           [&] { csgray::check(drilledBall(), options); });
  // A ball exports at once; its 10⁷ points and grids of 1024² rays take
  // seconds (2.3 s on 2 cores), the check's own steps.
  options.tolerance = 0.01;
  options.samples = 10'000'000;
  options.grid = 1024;
  expectStopsWhenCancelled(cancel, "check: cancelled",
                           [&] { csgray::check(Solid::sphere(10), options); });
}

TEST(ApiCheck, ASoundPartPasses) {
  csgray::CheckOptions options;
  options.samples = 20000;
  options.grid = 64;
  const csgray::CheckReport report =
      csgray::check(Solid::box(10, true) - Solid::cylinder(12, 2, true), options);
  EXPECT_TRUE(report.ok) << report.summary;
  EXPECT_TRUE(report.failure.empty());
  EXPECT_TRUE(report.mesh.ok);
  EXPECT_GT(report.mesh.triangles, 0u);
  EXPECT_EQ(report.classification.points, 20000u);
  EXPECT_NEAR(report.volume.exact, 1000 - kPi * 40, 1.0);
  EXPECT_TRUE(report.warnings.empty());
  EXPECT_NE(report.summary.find("check()"), std::string::npos);
  // Options out of range are refused with the script's message.
  options.grid = 1;
  auto [code, message] = errorOf([&] { csgray::check(Solid::box(1), options); });
  EXPECT_EQ(code, ErrorCode::InvalidArgument);
  EXPECT_EQ(message, scriptMessage("return check(box(1), {grid=1})"));
  // A part that cannot be meshed is a report that says why.
  options.grid = 64;
  const csgray::CheckReport unbounded = csgray::check(Solid::halfSpace({0, 0, 1}), options);
  EXPECT_FALSE(unbounded.ok);
  EXPECT_FALSE(unbounded.failure.empty());
  // An empty part is called empty (it was called unbounded).
  const csgray::CheckReport empty =
      csgray::check(Solid::sphere(1) * Solid::sphere(1).translate({5, 0, 0}), options);
  EXPECT_FALSE(empty.ok);
  EXPECT_NE(empty.failure.find("empty"), std::string::npos) << empty.failure;
  EXPECT_EQ(empty.failure.find("unbounded"), std::string::npos) << empty.failure;
}

TEST(ApiScript, AnExampleGivesItsScene) {
  const csgray::Scene scene = csgray::runScript(CSGRAY_SOURCE_DIR "/examples/spot_light.lua");
  // spot_light.lua: a floor, a part, a camera, two spots (the second with
  // a soft edge) and a point light.
  EXPECT_EQ(scene.objects().size(), 1u);
  EXPECT_EQ(scene.surfaces().size(), 1u);
  ASSERT_EQ(scene.lights().size(), 3u);
  EXPECT_EQ(scene.lights()[0].kind, csgray::Light::Kind::Spot);
  EXPECT_EQ(scene.lights()[0].angle, 20.0);
  EXPECT_FALSE(scene.lights()[0].inner);
  EXPECT_EQ(scene.lights()[1].inner, 6.0);
  EXPECT_EQ(scene.lights()[2].kind, csgray::Light::Kind::Point);
  ASSERT_TRUE(scene.camera());
  EXPECT_EQ(scene.camera()->eye, (Vec3{0, -9, 6}));
  EXPECT_EQ(scene.background(), (Vec3{0.01, 0.01, 0.02}));
  // The part: a box with a hole, 1.6 · 1.6 · 1.2 less π · 0.5² · 1.2.
  EXPECT_NEAR(scene.part().volume(), 1.6 * 1.6 * 1.2 - kPi * 0.25 * 1.2, 1e-3);
  // Scripts that fail say where, as ScriptError.
  auto [code, message] = errorOf([] { csgray::runScriptText("return box(", "part.lua"); });
  EXPECT_EQ(code, ErrorCode::ScriptError);
  EXPECT_EQ(message.rfind("part.lua:1:", 0), 0u) << message;
  EXPECT_EQ(errorOf([] { csgray::runScript("/no/such/script.lua"); }).first,
            ErrorCode::ScriptError);
  // Defines reach the script.
  csgray::ScriptOptions options;
  options.defines = {{"size", "3"}};
  EXPECT_NEAR(csgray::runScriptText("return box(size)", "part.lua", options).part().volume(), 27,
              1e-9);
}

// A host takes the script's print() lines; a callback that throws ends the
// script with its message at the line of the print.
TEST(ApiScript, PrintGoesToTheHostsCallback) {
  std::vector<std::string> lines;
  csgray::ScriptOptions options;
  options.onPrint = [&](const std::string& line) { lines.push_back(line); };
  csgray::runScriptText("print('size', 3)\nprint()\nreturn sphere(1)", "part.lua", options);
  EXPECT_EQ(lines, (std::vector<std::string>{"size\t3", ""}));
  options.onPrint = [](const std::string&) { throw std::runtime_error("log is full"); };
  const auto [code, message] = errorOf([&] {
    csgray::runScriptText("local a = 1\nprint(a)\nreturn sphere(1)", "part.lua", options);
  });
  EXPECT_EQ(code, ErrorCode::ScriptError);
  EXPECT_EQ(message, "part.lua:2: print: log is full");
}

TEST(ApiError, CodesHaveNames) {
  EXPECT_STREQ(csgray::errorCodeName(ErrorCode::InvalidArgument), "InvalidArgument");
  EXPECT_STREQ(csgray::errorCodeName(ErrorCode::NotPrintable), "NotPrintable");
  EXPECT_STREQ(csgray::errorCodeName(ErrorCode::Cancelled), "Cancelled");
  EXPECT_STREQ(csgray::version(), CSGRAY_VERSION);
}

}  // namespace
