// Unions nested under transforms, flattened for rays: the flat union holds
// the nesting's leaves (primitives copied into place, other nodes used in
// place) and answers every ray and point as the nesting does: the same
// spans, first boundaries, shadow tests, containment and surface normals.
#include "engine/flat_union.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <random>

#include "engine/boolean.h"
#include "engine/instance.h"
#include "engine/instance_surface.h"
#include "primitives/box.h"
#include "primitives/cylinder.h"
#include "primitives/sphere.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

// A part of a box, a ball and a drilled cylinder (a difference, which stays
// a node of its own); a pair of its uses; and two uses of that pair, one
// turned and stretched, beside a plain ball: 4 uses of 3 leaves, and a
// ball, as a fractal's or an assembly's levels nest.
struct Nesting {
  SolidPtr drilled = differenceOf(
      {Primitive::create<Cylinder>(1.0, 1.0, 2.0),
       Primitive::create<Cylinder>(0.4, 0.4, 4.0)->transformed(Affine::translation({0, 0, -1}))});
  SolidPtr part =
      unionOf({Primitive::create<Box>(dvec3(1, 2, 3)),
               Primitive::create<Sphere>(1.0)->transformed(Affine::translation({3, 1, 1})),
               drilled->transformed(Affine::translation({0, 5, 0}))});
  SolidPtr pair = unionOf({part->transformed(Affine::translation({0, 0, 0})),
                           part->transformed(Affine::rotation(0.7, glm::normalize(dvec3(1, 2, 3)))
                                                 .then(Affine::translation({12, 0, 0})))});
  SolidPtr top =
      unionOf({pair->transformed(Affine::scaling({1, 1, 2}).then(Affine::translation({0, 0, 9}))),
               pair->transformed(Affine::rotation(1.1, glm::normalize(dvec3(0, 1, 1)))
                                     .then(Affine::translation({0, 45, 0}))),
               Primitive::create<Sphere>(2.0)->transformed(Affine::translation({30, 30, 30}))});
};

TEST(FlatUnion, NestedUsesBecomeOneUnionOfTheirLeaves) {
  const Nesting n;
  EXPECT_TRUE(nestsMovedUnions(*n.top));
  const SolidPtr flat = flatUnion(n.top);
  const Boolean* node = flat->asBoolean();
  ASSERT_NE(node, nullptr);
  EXPECT_EQ(node->op(), Boolean::Op::Union);
  // 4 uses of the part's 3 leaves, and the ball.
  ASSERT_EQ(node->children().size(), 13u);
  int primitives = 0, drilled = 0;
  for (const SolidPtr& leaf : node->children()) {
    EXPECT_FALSE(leaf->asBoolean() && leaf->asBoolean()->op() == Boolean::Op::Union);
    if (const Instance* use = leaf->asInstance()) {
      // The difference stays shared: a use of the one node.
      EXPECT_EQ(use->child(), n.drilled);
      ++drilled;
    } else {
      EXPECT_EQ(leaf->asBoolean(), nullptr);
      ++primitives;
    }
  }
  EXPECT_EQ(primitives, 9);
  EXPECT_EQ(drilled, 4);
  EXPECT_EQ(flat->primitiveCount(), n.top->primitiveCount());
}

TEST(FlatUnion, AnswersAsTheNesting) {
  const Nesting n;
  const SolidPtr flat = flatUnion(n.top);
  ASSERT_NE(flat, n.top);
  n.top->prepare();
  std::mt19937_64 rng(5);
  int met = 0, inside = 0;
  for (int i = 0; i < 5000; ++i) {
    const Ray ray = test::randomRayThrough(rng, *n.top);
    const SpanList a = test::spansOf(*flat, ray), b = test::spansOf(*n.top, ray);
    ASSERT_EQ(a.size(), b.size()) << i;
    for (std::uint32_t k = 0; k < a.size(); ++k) {
      EXPECT_NEAR(a[k].in.t, b[k].in.t, 1e-9 * (1 + std::abs(b[k].in.t))) << i;
      EXPECT_NEAR(a[k].out.t, b[k].out.t, 1e-9 * (1 + std::abs(b[k].out.t))) << i;
      EXPECT_EQ(a[k].in.face, b[k].in.face) << i;
      EXPECT_EQ(a[k].in.flip, b[k].in.flip) << i;
    }
    SpanList fa, fb;
    flat->spansToFirstBoundary(ray, fa);
    n.top->spansToFirstBoundary(ray, fb);
    ASSERT_EQ(fa.empty(), fb.empty()) << i;
    if (!fa.empty()) {
      ++met;
      const Boundary &x = fa[0].in, &y = fb[0].in;
      EXPECT_NEAR(x.t, y.t, 1e-9 * (1 + std::abs(y.t))) << i;
      EXPECT_EQ(x.primitive->kind(), y.primitive->kind()) << i;
      // The surface there: the copy's normal in the world, where the
      // nesting's is found through its uses.
      const dvec3 na = boundarySurface(*flat, ray, x).normal;
      const dvec3 nb = boundarySurface(*n.top, ray, y).normal;
      EXPECT_NEAR(glm::length(na - nb), 0.0, 1e-9) << i;
    }
    // A shadow ray's question, on a window that ends halfway.
    Ray window = ray;
    window.tMax = 200.0;
    SpanList scratch;
    EXPECT_EQ(flat->meetsWindow(window, scratch), n.top->meetsWindow(window, scratch)) << i;
    // Points: the middle of each span (inside), and one anywhere in the box.
    for (const Span& s : b) {
      const dvec3 mid = ray.at(0.5 * (s.in.t + s.out.t));
      inside += flat->contains(mid);
      EXPECT_TRUE(flat->contains(mid)) << i;
    }
    const dvec3 p = test::randomPoint(rng, n.top->bounds());
    EXPECT_EQ(flat->contains(p), n.top->contains(p)) << i;
  }
  EXPECT_GT(met, 3000);
  EXPECT_GT(inside, 3000);
}

TEST(FlatUnion, AUseOfAUnionIsFlattenedInPlace) {
  const Nesting n;
  const SolidPtr moved = n.part->transformed(
      Affine::rotation(0.3, dvec3(0, 0, 1)).then(Affine::translation({5, 0, 0})));
  ASSERT_NE(moved->asInstance(), nullptr);
  const SolidPtr flat = flatUnion(moved);
  ASSERT_NE(flat->asBoolean(), nullptr);
  EXPECT_EQ(flat->children().size(), 3u);
  std::mt19937_64 rng(9);
  for (int i = 0; i < 20000; ++i) {
    const dvec3 p = test::randomPoint(rng, moved->bounds());
    EXPECT_EQ(flat->contains(p), moved->contains(p)) << i;
  }
}

TEST(FlatUnion, KeepsWhatHasNoNestingOrTooManyLeaves) {
  const Nesting n;
  // A union of primitives and of a use of a difference: nothing nested.
  const SolidPtr plain = unionOf(
      {Primitive::create<Sphere>(1.0), n.drilled->transformed(Affine::translation({3, 0, 0}))});
  EXPECT_FALSE(nestsMovedUnions(*plain));
  EXPECT_EQ(flatUnion(plain), plain);
  EXPECT_EQ(plain->forRays(), plain);
  EXPECT_EQ(n.drilled->forRays(), n.drilled);
  // More uses than allowed: kept, sharing its nodes.
  EXPECT_EQ(flatUnion(n.top, n.top->primitiveCount() - 1), n.top);
  EXPECT_NE(flatUnion(n.top, n.top->primitiveCount()), n.top);
  // The renderer's way in: made once and kept by the node.
  const SolidPtr once = n.top->forRays();
  EXPECT_NE(once, n.top);
  EXPECT_EQ(n.top->forRays(), once);
}

}  // namespace
}  // namespace csgray::detail
