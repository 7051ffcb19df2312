// Instances: a transformed boolean shares its tree rather than copying it.
// An instanced tree (nested instances, a non-uniform scale among their
// frames) answers as the copied tree does: the same spans, first
// boundaries, containment and volume; the surface at a boundary under the
// instances has the copy's normal; a material given to one use stays with
// that use; and a render of either is the same image.
#include "engine/instance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <random>

#include "engine/boolean.h"
#include "engine/instance_surface.h"
#include "engine/moved_box.h"
#include "primitives/box.h"
#include "primitives/cylinder.h"
#include "primitives/sphere.h"
#include "raytrace/renderer.h"
#include "scene/material.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

constexpr double kPi = std::numbers::pi;

// The copy a transform made before instances: every primitive moved.
SolidPtr copyMoved(const SolidPtr& solid, const Affine& frame) {
  return solid->mapPrimitives(
      [&](const Primitive& p) { return p.withFrame(p.frame().then(frame)); });
}

// One piece: a box and a ball, less a square hole through the box. Its
// volume: 1·2·3 + 4π/3 − 0.5·0.5·3.
SolidPtr piece() {
  SolidPtr ball = Primitive::create<Sphere>(1.0)->transformed(Affine::translation({3, 1, 1}));
  SolidPtr hole = Primitive::create<Box>(dvec3(0.5, 0.5, 10))
                      ->transformed(Affine::translation({0.25, 0.25, -1}));
  return differenceOf({unionOf({Primitive::create<Box>(dvec3(1, 2, 3)), ball}), hole});
}
const double kPieceVolume = 6.0 + 4.0 * kPi / 3.0 - 0.75;

// Two uses of the piece, and two uses of that pair: one scaled by 2 in z
// (twice the volume), one turned; all apart. Built by `move`, which is
// either the transform (instances) or the copy.
struct Frames {
  Affine a = Affine::translation({0, 0, 0});
  Affine b =
      Affine::rotation(0.7, glm::normalize(dvec3(1, 2, 3))).then(Affine::translation({12, 0, 0}));
  Affine c = Affine::scaling({1, 1, 2}).then(Affine::translation({0, 0, 5}));
  Affine d =
      Affine::rotation(1.1, glm::normalize(dvec3(0, 1, 1))).then(Affine::translation({0, 45, 0}));
};
const double kTreeVolume = 2 * kPieceVolume * 2 + 2 * kPieceVolume;

template <class Move>
SolidPtr tree(const SolidPtr& part, Move move) {
  const Frames f;
  SolidPtr pair = unionOf({move(part, f.a), move(part, f.b)});
  return unionOf({move(pair, f.c), move(pair, f.d)});
}

SolidPtr instanced() {
  return tree(piece(), [](const SolidPtr& s, const Affine& m) { return s->transformed(m); });
}
SolidPtr copied() { return tree(piece(), copyMoved); }

// A turned, stretched use of a part of balls and cylinders (a lens less a
// hole, a cone's frustum less a ball): its box holds every point of the
// part and every boundary a ray finds on it, lies within the box of the
// turned corners of the part's box, and is the analytic one where that is
// known: a ball of radius r turned about any axis reaches r from its
// centre on every axis, where the turned corners of its cube reach up to
// r·√3.
TEST(Instance, TurnedBoxIsMadeFromTheParts) {
  auto ball = [](double r, double z) {
    return Primitive::create<Sphere>(r)->transformed(Affine::translation({0, 0, z}));
  };
  const SolidPtr lens =
      differenceOf({intersectionOf({ball(3, -2), ball(3, 2),
                                    Primitive::create<Cylinder>(2.0, 2.0, 4.0)
                                        ->transformed(Affine::translation({0, 0, -2}))}),
                    Primitive::create<Sphere>(0.8)->transformed(Affine::scaling({1, 1, 1.9}))});
  const SolidPtr cone = differenceOf({Primitive::create<Cylinder>(2.0, 0.5, 3.0), ball(0.4, 3)});
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int points = 0, boundaries = 0;
  for (const SolidPtr& part : {lens, cone}) {
    for (int f = 0; f < 40; ++f) {
      const Affine frame = Affine::rotation(6.0 * unit(rng), test::randomDirection(rng))
                               .then(Affine::scaling({1.0, 0.5 + unit(rng), 1.5}))
                               .then(Affine::translation({7, -3, 2}));
      const Instance moved(part, frame);
      const Bounds box = moved.rayBox(), corners = movedBox(part->bounds(), frame);
      for (int a = 0; a < 3; ++a) {
        EXPECT_GE(moved.bounds().lo[a], corners.lo[a]);
        EXPECT_LE(moved.bounds().hi[a], corners.hi[a]);
        EXPECT_GE(box.lo[a], moved.bounds().lo[a]);
        EXPECT_LE(box.hi[a], moved.bounds().hi[a]);
      }
      for (int i = 0; i < 2000; ++i) {
        const dvec3 p = test::randomPoint(rng, corners);
        if (!moved.contains(p)) continue;
        ++points;
        ASSERT_TRUE(box.contains(p)) << f << " " << i;
        ASSERT_TRUE(moved.bounds().contains(p)) << f << " " << i;
      }
      for (int i = 0; i < 200; ++i) {
        const Ray line(test::randomPoint(rng, corners), test::randomDirection(rng), -kInfinity,
                       kInfinity);
        for (const Span& s : test::spansOf(moved, line))
          for (double t : {s.in.t, s.out.t}) {
            ++boundaries;
            ASSERT_TRUE(box.contains(line.at(t))) << f << " " << i;
          }
      }
    }
  }
  EXPECT_GT(points, 10000);
  EXPECT_GT(boundaries, 2000);
  for (int f = 0; f < 100; ++f) {
    const dvec3 centre = test::randomPoint(rng, Bounds{dvec3(-50), dvec3(50)});
    const Affine frame = Affine::rotation(6.0 * unit(rng), test::randomDirection(rng))
                             .then(Affine::translation(centre));
    // (A union of one ball and a point-sized ball inside it: an instance
    // over a boolean node, as a script's turned part is.)
    const Instance moved(unionOf({ball(2.5, 0), ball(1e-3, 0)}), frame);
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(moved.rayBox().lo[a], centre[a] - 2.5, 1e-9);
      EXPECT_NEAR(moved.rayBox().hi[a], centre[a] + 2.5, 1e-9);
    }
  }
}

// A boolean turned again and again, as a script turns a gear at each
// tooth it adds: gear = (gear + tooth):rotate(0, 0, 10), 36 times. Had
// each instance's box been its child's box turned, it would grow by
// cos 10° + sin 10° a turn, to some 4 000 across, and a volume from a grid
// over it would miss the teeth. The box stays within the turned
// primitives' boxes, and the grid's volume is the analytic one.
TEST(Instance, ABooleanTurnedAgainAndAgainKeepsItsBox) {
  const SolidPtr tooth =
      Primitive::create<Box>(dvec3(2.5, 1, 2))->transformed(Affine::translation({9.5, -0.5, 0}));
  SolidPtr gear = Primitive::create<Cylinder>(10.0, 10.0, 2.0);
  for (int i = 0; i < 36; ++i)
    gear = unionOf({gear, tooth})->transformed(Affine::rotation(kPi / 18, dvec3(0, 0, 1)));
  // The teeth's outer corners are √(12² + 0.5²) from the axis; the disc,
  // turned a whole turn, is back where it was.
  const double reach = std::sqrt(144.25) + 1e-9;
  const Bounds box = gear->bounds();
  test::expectVecNear(box.lo, dvec3(-12, -12, 0), reach - 12.0);
  test::expectVecNear(box.hi, dvec3(12, 12, 2), reach - 12.0);
  // The disc, and 36 teeth less each one's part inside the rim: the
  // segment of the circle r = 10 over |y| <= 0.5, beyond x = 9.5, is
  // 0.5·√99.75 + 100·asin(0.05) − 9.5 (the area under a circle's arc,
  // ∫√(r² − y²) dy = y√(r² − y²)/2 + r²·asin(y/r)/2), 2 high.
  const double inside = 2.0 * (0.5 * std::sqrt(99.75) + 100.0 * std::asin(0.05) - 9.5);
  const double volume = 200.0 * kPi + 36.0 * (5.0 - inside);
  EXPECT_NEAR(test::gridVolume(*gear, box, 400), volume, 1e-3 * volume);

  // A centred cube and a small ball in it, turned 360 times by 1°: within
  // the turned cube's reach, √2 about the axis.
  SolidPtr cube = Primitive::create<Box>(dvec3(2))->transformed(Affine::translation(dvec3(-1)));
  for (int i = 0; i < 360; ++i)
    cube = unionOf({cube, Primitive::create<Sphere>(0.2)})
               ->transformed(Affine::rotation(kPi / 180, dvec3(0, 0, 1)));
  const double corner = std::sqrt(2.0) + 1e-9;
  test::expectVecNear(cube->bounds().lo, dvec3(-1, -1, -1), corner - 1.0);
  test::expectVecNear(cube->bounds().hi, dvec3(1, 1, 1), corner - 1.0);
  EXPECT_NEAR(test::gridVolume(*cube, cube->bounds(), 400), 8.0, 1e-3 * 8.0);
}

TEST(Instance, TransformOfABooleanSharesItsTree) {
  SolidPtr part = piece();
  SolidPtr moved = part->transformed(Affine::translation({1, 2, 3}));
  auto* instance = dynamic_cast<const Instance*>(moved.get());
  ASSERT_NE(instance, nullptr);
  EXPECT_EQ(instance->child(), part);
  // A transform of an instance composes the frames and keeps the child.
  SolidPtr twice = moved->transformed(Affine::scaling({2, 2, 2}));
  auto* again = dynamic_cast<const Instance*>(twice.get());
  ASSERT_NE(again, nullptr);
  EXPECT_EQ(again->child(), part);
  // A primitive is still moved as a copy.
  SolidPtr ball = Primitive::create<Sphere>(1.0)->transformed(Affine::translation({1, 0, 0}));
  EXPECT_NE(dynamic_cast<const Primitive*>(ball.get()), nullptr);
  EXPECT_TRUE(instanced()->hasInstances());
  EXPECT_FALSE(copied()->hasInstances());
  EXPECT_EQ(instanced()->primitiveCount(), copied()->primitiveCount());
}

TEST(Instance, AnswersAsTheCopiedTree) {
  SolidPtr shared = instanced(), copy = copied();
  shared->prepare();
  copy->prepare();
  // Bounds: the instance's box holds the copy's.
  const Bounds bs = shared->bounds(), bc = copy->bounds();
  for (int a = 0; a < 3; ++a) {
    EXPECT_LE(bs.lo[a], bc.lo[a] + 1e-9);
    EXPECT_GE(bs.hi[a], bc.hi[a] - 1e-9);
  }
  std::mt19937_64 rng(7);
  int met = 0;
  for (int i = 0; i < 4000; ++i) {
    const Ray ray = test::randomRayThrough(rng, *copy);
    const SpanList a = test::spansOf(*shared, ray), b = test::spansOf(*copy, ray);
    ASSERT_EQ(a.size(), b.size()) << i;
    met += !a.empty();
    for (std::uint32_t k = 0; k < a.size(); ++k) {
      EXPECT_NEAR(a[k].in.t, b[k].in.t, 1e-9 * (1 + std::abs(b[k].in.t)));
      EXPECT_NEAR(a[k].out.t, b[k].out.t, 1e-9 * (1 + std::abs(b[k].out.t)));
      EXPECT_EQ(a[k].in.face, b[k].in.face);
      EXPECT_EQ(a[k].in.flip, b[k].in.flip);
      EXPECT_EQ(a[k].in.primitive->kind(), b[k].in.primitive->kind());
    }
    SpanList fa, fb;
    shared->spansToFirstBoundary(ray, fa);
    copy->spansToFirstBoundary(ray, fb);
    ASSERT_EQ(fa.empty(), fb.empty());
    if (!fa.empty()) {
      EXPECT_NEAR(fa[0].in.t, fb[0].in.t, 1e-9 * (1 + std::abs(fb[0].in.t)));
    }
    const dvec3 p = test::randomPoint(rng, bc);
    EXPECT_EQ(shared->contains(p), copy->contains(p)) << p.x << " " << p.y << " " << p.z;
  }
  EXPECT_GT(met, 2000);
  test::expectSpansAgreeWithContainsOnRandomLines(*shared);
  EXPECT_NEAR(test::gridVolume(*shared, bc, 400), kTreeVolume, 0.01 * kTreeVolume);
  EXPECT_NEAR(test::gridVolume(*copy, bc, 400), kTreeVolume, 0.01 * kTreeVolume);
  // Multiplied out, the instances are the copy.
  SolidPtr flat = flattened(shared);
  EXPECT_FALSE(flat->hasInstances());
  EXPECT_EQ(flat->primitiveCount(), copy->primitiveCount());
  EXPECT_NEAR(test::gridVolume(*flat, bc, 400), kTreeVolume, 0.01 * kTreeVolume);
}

// Along random rays through copy, the normals at the boundaries of
// shared (the same solid under instances) are the copy's to 1e-9; the
// copy, without instances, gives its own primitives' normals. Returns how
// many boundaries were compared.
int compareNormalsWithCopy(const SolidPtr& shared, const SolidPtr& copy, std::mt19937_64& rng,
                           int rays) {
  int compared = 0;
  for (int i = 0; i < rays; ++i) {
    const Ray ray = test::randomRayThrough(rng, *copy);
    const SpanList a = test::spansOf(*shared, ray), b = test::spansOf(*copy, ray);
    EXPECT_EQ(a.size(), b.size());
    if (a.size() != b.size()) return compared;
    for (std::uint32_t k = 0; k < a.size(); ++k)
      for (int end = 0; end < 2; ++end) {
        const Boundary& x = end ? a[k].out : a[k].in;
        const Boundary& y = end ? b[k].out : b[k].in;
        const dvec3 expected = y.primitive->normal(ray.at(y.t), int(y.face));
        test::expectVecNear(boundarySurface(*shared, ray, x).normal, expected, 1e-9);
        test::expectVecNear(boundarySurface(*copy, ray, y).normal, expected, 0.0);
        ++compared;
      }
  }
  return compared;
}

TEST(Instance, NormalsUnderNestedInstancesAreTheCopys) {
  std::mt19937_64 rng(11);
  EXPECT_GT(compareNormalsWithCopy(instanced(), copied(), rng, 4000), 4000);
}

// A boolean moved as a whole (one instance, or instances of instances,
// over a tree without any) has its normals found through the frames of
// the chain, without the search: the copy's, also under a non-uniform
// scale between them.
TEST(Instance, NormalsUnderAChainOfInstancesAreTheCopys) {
  const Frames f;
  const SolidPtr part = piece();
  const SolidPtr once = part->transformed(f.b);
  const SolidPtr chain = std::make_shared<Instance>(std::make_shared<Instance>(part, f.c), f.d);
  const SolidPtr onceCopy = copyMoved(part, f.b), chainCopy = copyMoved(copyMoved(part, f.c), f.d);
  std::mt19937_64 rng(13);
  int compared = 0;
  for (const auto& [shared, copy] : {std::pair(once, onceCopy), std::pair(chain, chainCopy)}) {
    ASSERT_TRUE(shared->hasInstances());
    compared += compareNormalsWithCopy(shared, copy, rng, 2000);
  }
  EXPECT_GT(compared, 2000);
}

// A hint kept from boundary to boundary (as a render thread keeps one)
// changes nothing: along bundles of neighbouring rays through the nested
// instances, every boundary's normal, use and texture frame are the ones
// the search alone finds, bit for bit, while most of them come from the
// hint's way.
TEST(Instance, AHintGivesTheSearchsSurface) {
  const SolidPtr shared = instanced();
  shared->prepare();
  std::mt19937_64 rng(19);
  std::uniform_real_distribution<double> jitter(-0.01, 0.01);
  UseHint hint;
  int compared = 0, hinted = 0;
  for (int i = 0; i < 1500; ++i) {
    const Ray first = test::randomRayThrough(rng, *shared);
    for (int k = 0; k < 4; ++k) {
      const Ray ray(first.origin + dvec3(jitter(rng), jitter(rng), jitter(rng)), first.dir);
      for (const Span& s : test::spansOf(*shared, ray))
        for (const Boundary* b : {&s.in, &s.out}) {
          hinted += hint.root == shared.get() && hint.knows(hint.wayEnd(), b->primitive);
          const BoundarySurface with = boundarySurface(*shared, ray, *b, true, &hint);
          const BoundarySurface without = boundarySurface(*shared, ray, *b, true);
          EXPECT_EQ(with.normal, without.normal) << i << " " << k;
          EXPECT_EQ(with.use, without.use) << i << " " << k;
          EXPECT_EQ(with.texturePoint, without.texturePoint) << i << " " << k;
          EXPECT_EQ(with.textureNormal, without.textureNormal) << i << " " << k;
          ++compared;
        }
    }
  }
  EXPECT_GT(compared, 5000);
  EXPECT_GT(hinted, compared / 3);
}

// The shadow ray's question, whether a solid meets a window of the ray,
// has the answer of the solid's spans there: for unions of instances
// (which stop at the first operand that meets it), their copies, and the
// differences within, on random windows along random lines.
TEST(Instance, MeetsAWindowWhereItsSpansLie) {
  const SolidPtr shared = instanced(), copy = copied(), part = piece();
  shared->prepare();
  copy->prepare();
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> along(150.0, 250.0);
  int met = 0, missed = 0;
  SpanList scratch;
  for (int i = 0; i < 4000; ++i) {
    Ray ray = test::randomRayThrough(rng, *copy);
    ray.tMin = along(rng);
    ray.tMax = ray.tMin + 0.25 * along(rng) - 37.0;
    for (const SolidPtr& solid : {shared, copy, part}) {
      Ray whole = ray;
      whole.tMin = -kInfinity;
      whole.tMax = kInfinity;
      bool inWindow = false;
      for (const Span& s : test::spansOf(*solid, whole))
        inWindow = inWindow || (s.out.t > ray.tMin && s.in.t < ray.tMax);
      EXPECT_EQ(solid->meetsWindow(ray, scratch), inWindow) << i;
      (inWindow ? met : missed)++;
    }
  }
  EXPECT_GT(met, 500);
  EXPECT_GT(missed, 500);
}

TEST(Instance, AMaterialGivenToOneUseStaysWithIt) {
  auto red = std::make_shared<Material>();
  red->color = dvec3(1, 0, 0);
  const Frames f;
  SolidPtr part = piece();
  SolidPtr painted = part->transformed(f.a)->withDefaultMaterial(red);
  SolidPtr plain = part->transformed(f.b);
  // Still a use of a shared tree, now a painted copy of it; the piece
  // itself and its other use keep no material.
  ASSERT_TRUE(painted->hasInstances());
  SolidPtr both = unionOf({painted, plain});
  std::mt19937_64 rng(3);
  int redHits = 0, plainHits = 0;
  for (int i = 0; i < 2000; ++i) {
    const Ray ray = test::randomRayThrough(rng, *both);
    for (const Span& s : test::spansOf(*both, ray)) {
      const bool inPainted = painted->contains(ray.at(0.5 * (s.in.t + s.out.t)));
      EXPECT_EQ(s.in.primitive->material(), inPainted ? red : nullptr);
      (inPainted ? redHits : plainHits)++;
    }
    for (const Span& s : test::spansOf(*part, ray)) EXPECT_EQ(s.in.primitive->material(), nullptr);
  }
  EXPECT_GT(redHits, 50);
  EXPECT_GT(plainHits, 50);
}

TEST(Instance, RendersAsTheCopiedTree) {
  // One camera for both: the instances' boxes are larger than the copy's.
  const dvec3 centre = copied()->bounds().center();
  const CameraSpec camera{centre + dvec3(20, -30, 25), centre, dvec3(0, 0, 1), 50.0};
  auto render = [&](const SolidPtr& solid) {
    Scene scene;
    auto gold = std::make_shared<Material>();
    gold->color = dvec3(0.9, 0.7, 0.2);
    gold->specular = 0.5;
    scene.objects.push_back(solidWithMaterial(solid, gold));
    scene.camera = camera;
    scene.lights.push_back(Light{Light::Kind::Point, dvec3(100, -100, 200)});
    RenderOptions options(240, 180, 1);
    options.normalAov = true;
    options.depthAov = true;
    return Renderer(scene, options).renderAll();
  };
  const RenderResult a = render(instanced()), b = render(copied());
  int part = 0;
  for (int y = 0; y < 180; ++y)
    for (int x = 0; x < 240; ++x) {
      test::expectVecNear(a.color.at(x, y), b.color.at(x, y), 1e-6);
      test::expectVecNear(a.normal.at(x, y), b.normal.at(x, y), 1e-6);
      part += std::isfinite(a.depth.at(x, y).x);
    }
  EXPECT_GT(part, 200);  // the uses cover some hundreds of pixels
}

}  // namespace
}  // namespace csgray::detail
