// Bump mapping against the surface it stands for: a height that rises as
// d·x tilts a flat face's normal to the raised face's, (−d, 0, 1)/√(1 + d²),
// in the part's frame wherever the part was moved after its material;
// Lambert's law then dims the face by that tilt, and the silhouette stays
// the smooth shape's.
#include "raytrace/bumps.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "engine/boolean.h"
#include "engine/instance_surface.h"
#include "primitives/box.h"
#include "primitives/sphere.h"
#include "raytrace/renderer.h"
#include "scene/texture.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

// A grey ramp: brightness x (as luminance, whose weights sum to 1).
class Ramp : public Texture {
 protected:
  dvec3 pattern(const dvec3& p, const dvec3&) const override { return dvec3(p.x); }
};

MaterialPtr bumpy(double depth, dvec3 color = dvec3(0.8)) {
  auto m = std::make_shared<Material>();
  m->color = color;
  m->bumps = std::make_shared<Ramp>();
  m->bumpDepth = depth;
  return m;
}

TEST(Bumps, ARampTiltsTheNormalToTheRaisedFaces) {
  const double d = 0.75;
  const MaterialPtr m = bumpy(d);
  const dvec3 raised = glm::normalize(dvec3(-d, 0, 1));
  test::expectVecNear(
      bumpedNormal(*m, dvec3(0, 0, 1), 1.0, dvec3(3, 2, 0), dvec3(0, 0, 1), glm::dmat3(1.0)),
      raised, 1e-8);
  // Seen from below, the face's normal turned to the ray: the same raised
  // face, its normal turned.
  test::expectVecNear(
      bumpedNormal(*m, dvec3(0, 0, -1), -1.0, dvec3(3, 2, 0), dvec3(0, 0, 1), glm::dmat3(1.0)),
      -raised, 1e-8);
  // A face across the ramp (normal along x) is not tilted.
  test::expectVecNear(
      bumpedNormal(*m, dvec3(1, 0, 0), 1.0, dvec3(3, 2, 0), dvec3(1, 0, 0), glm::dmat3(1.0)),
      dvec3(1, 0, 0), 1e-8);
  EXPECT_NEAR(luminance(dvec3(1.0)), 1.0, 1e-12);
  // A depth past the doubles' squares tilts the normal all the way along
  // the surface, as a steep ramp would, not back to the smooth normal.
  const dvec3 steep = bumpedNormal(*bumpy(1e200), dvec3(0, 0, 1), 1.0, dvec3(3, 2, 0),
                                   dvec3(0, 0, 1), glm::dmat3(1.0));
  test::expectVecNear(steep, dvec3(-1, 0, 0), 1e-9);
}

// The bumps go with the part, made in the part's frame when the material
// was given: a box given the ramp and then stretched twice along x rises
// d·x/2 in the world; scaled twice in every direction, 2d·(x/2), the same
// slope; stretched three times along z, 3d·x; and a union of it turned a
// quarter about z (an instance) rises along the turned x, y.
TEST(Bumps, TheBumpsMoveWithThePart) {
  const double d = 0.5;
  const SolidPtr box = solidWithMaterial(
      Primitive::create<Box>(dvec3(10, 10, 1))->transformed(Affine::translation({-5, -5, -1})),
      bumpy(d));
  const SolidPtr stretched = box->transformed(Affine::scaling({2, 1, 1}));
  auto tilted = [&](const Solid& solid, const Ray& ray) {
    const SpanList spans = test::spansOf(solid, ray);
    EXPECT_FALSE(spans.empty());
    const Boundary& top = spans.front().in;
    const BoundarySurface s = boundarySurface(solid, ray, top, true);
    return bumpedNormal(*bumpy(d), s.normal, 1.0, s.texturePoint, s.textureNormal,
                        s.textureFromWorld);
  };
  const Ray down(dvec3(1, 1, 5), dvec3(0, 0, -1));
  test::expectVecNear(tilted(*stretched, down), glm::normalize(dvec3(-d / 2, 0, 1)), 1e-7);
  // Scaled alike in every direction, the bumps are as high as they are
  // wide, as before: the same slope.
  const SolidPtr doubled = box->transformed(Affine::scaling({2, 2, 2}));
  test::expectVecNear(tilted(*doubled, down), glm::normalize(dvec3(-d, 0, 1)), 1e-7);
  // Stretched across the ramp's rise (along z), the rise is stretched too.
  const SolidPtr tall = box->transformed(Affine::scaling({1, 1, 3}));
  test::expectVecNear(tilted(*tall, down), glm::normalize(dvec3(-3 * d, 0, 1)), 1e-7);
  const SolidPtr turned =
      unionOf({box, Primitive::create<Sphere>(0.5)->transformed(Affine::translation({20, 0, 0}))})
          ->transformed(Affine::rotation(std::numbers::pi / 2, dvec3(0, 0, 1)));
  ASSERT_NE(turned->asInstance(), nullptr);
  test::expectVecNear(tilted(*turned, down), glm::normalize(dvec3(0, -d, 1)), 1e-7);
}

// A bumped floor under a light straight above it shows cos of the tilt,
// 1/√(1 + d²) of the smooth floor's light, at every pixel; a bumped red
// ball covers the same pixels as the smooth one.
TEST(Bumps, LambertSeesTheTiltAndTheSilhouetteStays) {
  const double d = 0.75;
  auto sceneWith = [&](bool bumps) {
    auto floor = std::make_shared<Material>();
    if (bumps) floor = std::make_shared<Material>(*bumpy(d));
    floor->color = dvec3(1.0);
    floor->ambient = 0.0;
    floor->diffuse = 1.0;
    auto ball = std::make_shared<Material>(*bumpy(bumps ? 0.3 : 0.0, dvec3(1, 0, 0)));
    if (!bumps) ball->bumps = nullptr;
    ball->ambient = 0.2;
    Scene scene;
    scene.objects.push_back(
        solidWithMaterial(Primitive::create<Box>(dvec3(100, 100, 1))
                              ->transformed(Affine::translation({-50, -50, -1})),
                          floor));
    scene.objects.push_back(solidWithMaterial(
        Primitive::create<Sphere>(1.0)->transformed(Affine::translation({0, 0, 3})), ball));
    scene.camera = CameraSpec{dvec3(0, 0, 10), dvec3(0), dvec3(0, 1, 0), 40.0};
    LightParams light;
    light.position = dvec3(0, 0, 1e7);
    scene.lights.push_back(makeLight(light));
    scene.background = dvec3(0.0);
    return scene;
  };
  const Image smooth = Renderer(sceneWith(false), {60, 40, 1}).render();
  const Image bumped = Renderer(sceneWith(true), {60, 40, 1}).render();
  int ballPixels = 0, floorPixels = 0;
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 60; ++x) {
      // Clear of the ball and its shadow, which lies under it.
      if (std::hypot(x + 0.5 - 30, y + 0.5 - 20) > 13.0) {
        ++floorPixels;
        ASSERT_NEAR(smooth.at(x, y).x, 1.0, 1e-6);
        ASSERT_NEAR(bumped.at(x, y).x, 1.0 / std::sqrt(1.0 + d * d), 1e-6) << x << ", " << y;
      }
      // The ball is the red of its pixels (the floor is grey or black).
      auto red = [](const dvec3& c) { return c.x > 0.0 && c.y == 0.0; };
      ASSERT_EQ(red(smooth.at(x, y)), red(bumped.at(x, y))) << x << ", " << y;
      ballPixels += red(smooth.at(x, y));
    }
  EXPECT_GT(ballPixels, 100);
  EXPECT_GT(floorPixels, 1000);
  // The bumps changed the ball's shading, not only the floor's.
  int shadedOtherwise = 0;
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 60; ++x)
      shadedOtherwise += smooth.at(x, y).y == 0.0 && smooth.at(x, y).x > 0.0 &&
                         std::abs(smooth.at(x, y).x - bumped.at(x, y).x) > 1e-3;
  EXPECT_GT(shadedOtherwise, 50);
}

// A part used through instances (a difference turned as a whole, and
// placed twice) shows the bumps of the same part built from primitives
// turned one by one: the renderer's way to a shaded use through the
// instances, the hint of neighbouring pixels included, brings the
// texture's frame along. (A union of moved unions is flattened for rays;
// a difference under a turn stays a use.)
TEST(Bumps, UsesThroughInstancesShowTheSameBumps) {
  auto m = std::make_shared<Material>();
  m->bumps =
      placedNoise(NoiseKind::Perlin, std::nullopt, 1, 0.0, TexturePlacement{dvec3(0.3), {}, {}});
  m->bumpDepth = 0.4;
  const SolidPtr box = solidWithMaterial(
      Primitive::create<Box>(dvec3(2, 2, 2))->transformed(Affine::translation({-1, -1, -1})), m);
  const SolidPtr ball = solidWithMaterial(
      Primitive::create<Sphere>(1.0)->transformed(Affine::translation({1, -1, 1})), m);
  const Affine turn = Affine::rotation(0.7, glm::normalize(dvec3(1, 2, 3)));
  const Affine place = Affine::translation({0, 0, 3});
  const SolidPtr part = differenceOf({box, ball})->transformed(turn);
  ASSERT_NE(part->asInstance(), nullptr);
  auto moved = [&](const Affine& a) {
    return differenceOf({box->transformed(a), ball->transformed(a)});
  };
  Scene instanced, flat;
  instanced.objects = {part, part->transformed(place)};
  flat.objects = {moved(turn), moved(turn.then(place))};
  for (Scene* s : {&instanced, &flat}) {
    s->camera = CameraSpec{dvec3(8, -10, 6), dvec3(0, 0, 1.5), dvec3(0, 0, 1), 40.0};
    s->background = dvec3(0.0);
  }
  const Image a = Renderer(instanced, {64, 48, 1}).render();
  const Image b = Renderer(flat, {64, 48, 1}).render();
  int lit = 0;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x) {
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(a.at(x, y)[c], b.at(x, y)[c], 1e-4) << x << ", " << y;
      lit += a.at(x, y).x > 0.0;
    }
  EXPECT_GT(lit, 300);
}

}  // namespace
}  // namespace csgray::detail
