// The primitives: analytic ray hits, face indices, unit outward normals,
// contains(), bounds, tMin/tMax culling, agreement of spans with contains()
// on random and near-tangent lines, and refusal of degenerate parameters.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <limits>
#include <random>
#include <stdexcept>

#include "engine/solvers/quadratic.h"
#include "primitives/box.h"
#include "primitives/cylinder.h"
#include "primitives/half_space.h"
#include "primitives/quadric.h"
#include "primitives/sphere.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

using test::diagonal;
using test::expectAgreementOnLinesThrough;
using test::expectOutwardUnitNormals;
using test::expectSpansAgreeWithContains;
using test::expectSpansAgreeWithContainsOnRandomLines;
using test::expectVecNear;
using test::randomDirection;
using test::spansOf;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void expectBoundsNear(const Bounds& b, const dvec3& lo, const dvec3& hi, double tol = 1e-9) {
  expectVecNear(b.lo, lo, tol);
  expectVecNear(b.hi, hi, tol);
}

// ---------------------------------------------------------------- quadratic

// {t : a t² + b t + c <= 0} for the four sign cases of a and the discriminant.
TEST(PrimitiveQuadratic, SublevelSets) {
  Interval iv[2];
  ASSERT_EQ(quadraticSublevel(1, 0, -4, iv), 1);  // t² <= 4
  EXPECT_DOUBLE_EQ(iv[0].lo, -2);
  EXPECT_DOUBLE_EQ(iv[0].hi, 2);
  ASSERT_EQ(quadraticSublevel(1, 0, 4, iv), 0);   // t² + 4 <= 0: never
  ASSERT_EQ(quadraticSublevel(-1, 0, 4, iv), 2);  // t² >= 4
  EXPECT_EQ(iv[0].lo, -kInfinity);
  EXPECT_DOUBLE_EQ(iv[0].hi, -2);
  EXPECT_DOUBLE_EQ(iv[1].lo, 2);
  EXPECT_EQ(iv[1].hi, kInfinity);
  ASSERT_EQ(quadraticSublevel(-1, 0, -4, iv), 1);  // -t² - 4 <= 0: always
  EXPECT_EQ(iv[0].lo, -kInfinity);
  EXPECT_EQ(iv[0].hi, kInfinity);
  // (t - 3)(t - 5) <= 0, with b large and of either sign.
  ASSERT_EQ(quadraticSublevel(1, -8, 15, iv), 1);
  EXPECT_DOUBLE_EQ(iv[0].lo, 3);
  EXPECT_DOUBLE_EQ(iv[0].hi, 5);
  ASSERT_EQ(quadraticSublevel(2, 16, 30, iv), 1);
  EXPECT_DOUBLE_EQ(iv[0].lo, -5);
  EXPECT_DOUBLE_EQ(iv[0].hi, -3);
  // No cancellation: roots 1e-8 and 1e8 of t² - (1e8 + 1e-8) t + 1.
  ASSERT_EQ(quadraticSublevel(1, -(1e8 + 1e-8), 1, iv), 1);
  EXPECT_NEAR(iv[0].lo, 1e-8, 1e-22);
  EXPECT_NEAR(iv[0].hi, 1e8, 1e-6);
}

TEST(PrimitiveQuadratic, LinearAndConstantCases) {
  Interval iv[2];
  ASSERT_EQ(quadraticSublevel(0, 2, -4, iv), 1);  // 2t - 4 <= 0
  EXPECT_EQ(iv[0].lo, -kInfinity);
  EXPECT_DOUBLE_EQ(iv[0].hi, 2);
  ASSERT_EQ(quadraticSublevel(0, -2, -4, iv), 1);  // -2t - 4 <= 0
  EXPECT_DOUBLE_EQ(iv[0].lo, -2);
  EXPECT_EQ(iv[0].hi, kInfinity);
  EXPECT_EQ(quadraticSublevel(0, 0, 1, iv), 0);
  ASSERT_EQ(quadraticSublevel(0, 0, 0, iv), 1);
  EXPECT_EQ(iv[0].lo, -kInfinity);
  EXPECT_EQ(iv[0].hi, kInfinity);
}

// A double root with a < 0: -(t - 1)² <= 0 holds everywhere, so the answer
// is the whole line, not two intervals that touch at t = 1 (which would
// break the span-list invariant).
TEST(PrimitiveQuadratic, DoubleRootWithNegativeLeadingIsWholeLine) {
  Interval iv[2];
  int n = quadraticSublevel(-1, 2, -1, iv);
  ASSERT_EQ(n, 1);
  EXPECT_EQ(iv[0].lo, -kInfinity);
  EXPECT_EQ(iv[0].hi, kInfinity);
  // With a > 0 a double root is the single point.
  ASSERT_EQ(quadraticSublevel(1, -2, 1, iv), 1);
  EXPECT_DOUBLE_EQ(iv[0].lo, 1);
  EXPECT_DOUBLE_EQ(iv[0].hi, 1);
}

// ------------------------------------------------------------------- sphere

// A sphere of radius 2 at the origin, hit along each axis from distance
// d = 10, is inside for t in [d - 2, d + 2].
TEST(SpherePrimitive, HitsAlongAxis) {
  auto s = Primitive::create<Sphere>(2.0);
  for (int axis = 0; axis < 3; ++axis) {
    for (double sign : {1.0, -1.0}) {
      dvec3 dir(0.0);
      dir[axis] = sign;
      SpanList spans = spansOf(*s, Ray(-10.0 * dir, dir));
      ASSERT_EQ(spans.size(), 1u);
      EXPECT_DOUBLE_EQ(spans[0].in.t, 8.0);
      EXPECT_DOUBLE_EQ(spans[0].out.t, 12.0);
      EXPECT_EQ(spans[0].in.primitive, s.get());
      EXPECT_EQ(spans[0].out.primitive, s.get());
      EXPECT_FALSE(spans[0].in.flip);
    }
  }
}

// t is the parameter of origin + t·dir: a direction of length 4 divides it by 4.
TEST(SpherePrimitive, KeepsParameterOfNonUnitDirection) {
  auto s = Primitive::create<Sphere>(2.0);
  SpanList spans = spansOf(*s, Ray(dvec3(0, 0, -10), dvec3(0, 0, 4)));
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_DOUBLE_EQ(spans[0].in.t, 2.0);
  EXPECT_DOUBLE_EQ(spans[0].out.t, 3.0);
}

// A line at distance h from the centre cuts a chord of length 2·sqrt(r² - h²)
// centred on the foot of the perpendicular.
TEST(SpherePrimitive, OffAxisChordLength) {
  auto s = Primitive::create<Sphere>(2.0);
  for (double h : {0.0, 0.5, 1.0, 1.5, 1.9, 1.999}) {
    dvec3 dir = glm::normalize(dvec3(1, 1, 1));
    dvec3 perp = glm::normalize(dvec3(1, -1, 0));
    SpanList spans = spansOf(*s, Ray(h * perp - 7.0 * dir, dir));
    ASSERT_EQ(spans.size(), 1u) << h;
    EXPECT_NEAR(spans[0].length(), 2.0 * std::sqrt(4.0 - h * h), 1e-12) << h;
    EXPECT_NEAR(0.5 * (spans[0].in.t + spans[0].out.t), 7.0, 1e-12) << h;
  }
}

TEST(SpherePrimitive, MissesAndGrazes) {
  auto s = Primitive::create<Sphere>(2.0);
  EXPECT_TRUE(spansOf(*s, Ray(dvec3(2.0 + 1e-9, 0, -10), dvec3(0, 0, 1))).empty());
  EXPECT_TRUE(spansOf(*s, Ray(dvec3(5, 5, -10), dvec3(0, 0, 1))).empty());
  // Exactly tangent: at most a single point, at t = 10.
  SpanList tangent = spansOf(*s, Ray(dvec3(2, 0, -10), dvec3(0, 0, 1)));
  ASSERT_LE(tangent.size(), 1u);
  if (!tangent.empty()) {
    EXPECT_DOUBLE_EQ(tangent[0].in.t, 10.0);
    EXPECT_DOUBLE_EQ(tangent[0].out.t, 10.0);
  }
}

// The outward unit normal of a sphere at p is p / r.
TEST(SpherePrimitive, NormalIsRadial) {
  auto s = Primitive::create<Sphere>(2.0);
  std::mt19937_64 rng(11);
  for (int i = 0; i < 100; ++i) {
    dvec3 u = randomDirection(rng);
    expectVecNear(s->normal(2.0 * u, 0), u, 1e-15);
  }
  expectOutwardUnitNormals(*s);
}

TEST(SpherePrimitive, ContainsClosedBall) {
  auto s = Primitive::create<Sphere>(2.0);
  EXPECT_TRUE(s->contains(dvec3(0.0)));
  EXPECT_TRUE(s->contains(dvec3(1.999, 0, 0)));
  EXPECT_TRUE(s->contains(dvec3(0, -2, 0)));  // on the surface: closed
  EXPECT_FALSE(s->contains(dvec3(0, 0, 2.001)));
  EXPECT_FALSE(s->contains(dvec3(1.5, 1.5, 0)));   // |p|² = 4.5 > 4
  EXPECT_TRUE(s->contains(dvec3(1.1, 1.1, 1.1)));  // |p|² = 3.63
}

TEST(SpherePrimitive, Bounds) {
  auto s = Primitive::create<Sphere>(2.0);
  expectBoundsNear(s->bounds(), dvec3(-2.0), dvec3(2.0));
  EXPECT_EQ(s->kind(), "sphere");
}

// Spans lying wholly before tMin or after tMax are dropped; a span that
// overlaps the window is reported whole, not clipped.
TEST(SpherePrimitive, CullsToRayWindow) {
  auto s = Primitive::create<Sphere>(2.0);
  dvec3 o(0, 0, -10), d(0, 0, 1);
  EXPECT_TRUE(spansOf(*s, Ray(o, d, 13.0, kInfinity)).empty());
  EXPECT_TRUE(spansOf(*s, Ray(o, d, 0.0, 7.0)).empty());
  for (auto [t0, t1] : {std::pair{11.0, kInfinity}, {0.0, 9.0}, {9.0, 9.5}, {-kInfinity, 8.0}}) {
    SpanList spans = spansOf(*s, Ray(o, d, t0, t1));
    ASSERT_EQ(spans.size(), 1u) << t0 << " " << t1;
    EXPECT_DOUBLE_EQ(spans[0].in.t, 8.0);
    EXPECT_DOUBLE_EQ(spans[0].out.t, 12.0);
  }
  // A ray starting inside keeps the span's start behind it.
  SpanList inside = spansOf(*s, Ray(dvec3(0.0), d));
  ASSERT_EQ(inside.size(), 1u);
  EXPECT_DOUBLE_EQ(inside[0].in.t, -2.0);
  EXPECT_DOUBLE_EQ(inside[0].out.t, 2.0);
}

TEST(SpherePrimitive, SpansAgreeWithContains) {
  auto s = Primitive::create<Sphere>(2.0);
  expectSpansAgreeWithContainsOnRandomLines(*s);
  // Far away: the precision-preserving discriminant keeps the chord.
  auto far = Primitive::create<Sphere>(1.0);
  SpanList spans = spansOf(*far, Ray(dvec3(0.5, 0, -1e7), dvec3(0, 0, 1)));
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_NEAR(spans[0].length(), 2.0 * std::sqrt(0.75), 1e-8);
}

// Near-tangent lines, just inside and just outside the sphere.
TEST(SpherePrimitive, SpansAgreeWithContainsNearTangent) {
  auto s = Primitive::create<Sphere>(2.0);
  std::mt19937_64 rng(5);
  for (int i = 0; i < 1000; ++i) {
    dvec3 dir = randomDirection(rng);
    dvec3 perp = glm::normalize(glm::cross(dir, randomDirection(rng)));
    double h = 2.0 * (1.0 + (i % 2 ? 1e-9 : -1e-9));
    Ray line(h * perp, dir, -kInfinity, kInfinity);
    expectSpansAgreeWithContains(*s, line);
    SpanList spans = spansOf(*s, line);
    EXPECT_EQ(spans.size(), i % 2 ? 0u : 1u);
    if (::testing::Test::HasFailure()) return;
  }
}

TEST(SpherePrimitive, RejectsDegenerateRadius) {
  for (double r : {0.0, -1.0, -0.0, kNaN, kInfinity})
    EXPECT_THROW(Primitive::create<Sphere>(r), std::invalid_argument) << r;
  EXPECT_NO_THROW(Primitive::create<Sphere>(1e-6));
}

// ---------------------------------------------------------------------- box

// Box (1, 2, 3) from the origin; faces are axis·2 + (0 low, 1 high).
TEST(BoxPrimitive, HitsFacesAlongAxes) {
  auto b = Primitive::create<Box>(dvec3(1, 2, 3));
  dvec3 centre(0.5, 1.0, 1.5), size(1, 2, 3);
  for (int axis = 0; axis < 3; ++axis) {
    for (double sign : {1.0, -1.0}) {
      dvec3 dir(0.0);
      dir[axis] = sign;
      dvec3 origin = centre - 10.0 * dir;
      SpanList spans = spansOf(*b, Ray(origin, dir));
      ASSERT_EQ(spans.size(), 1u);
      EXPECT_DOUBLE_EQ(spans[0].in.t, 10.0 - size[axis] / 2);
      EXPECT_DOUBLE_EQ(spans[0].out.t, 10.0 + size[axis] / 2);
      int low = 2 * axis, high = 2 * axis + 1;
      EXPECT_EQ(spans[0].in.face, sign > 0 ? low : high);
      EXPECT_EQ(spans[0].out.face, sign > 0 ? high : low);
      EXPECT_EQ(spans[0].in.primitive, b.get());
    }
  }
}

// Oblique rays: from (-1, 0.5, 0.5) along (1, 0.5, 0) the ray enters the
// x = 0 face at t = 1 and leaves the x = 1 face at t = 2; from
// (0.5, -1, 1) along (0.25, 1, 0.5) it enters y = 0 at t = 1 and leaves
// x = 1 at t = 2.
TEST(BoxPrimitive, ObliqueHits) {
  auto b = Primitive::create<Box>(dvec3(1, 2, 3));
  SpanList s1 = spansOf(*b, Ray(dvec3(-1, 0.5, 0.5), dvec3(1, 0.5, 0)));
  ASSERT_EQ(s1.size(), 1u);
  EXPECT_DOUBLE_EQ(s1[0].in.t, 1.0);
  EXPECT_EQ(s1[0].in.face, 0);
  EXPECT_DOUBLE_EQ(s1[0].out.t, 2.0);
  EXPECT_EQ(s1[0].out.face, 1);
  SpanList s2 = spansOf(*b, Ray(dvec3(0.5, -1, 1), dvec3(0.25, 1, 0.5)));
  ASSERT_EQ(s2.size(), 1u);
  EXPECT_DOUBLE_EQ(s2[0].in.t, 1.0);
  EXPECT_EQ(s2[0].in.face, 2);
  EXPECT_DOUBLE_EQ(s2[0].out.t, 2.0);
  EXPECT_EQ(s2[0].out.face, 1);
  // Missing past a corner: from (-1, 2.5, 1) along (1, -0.2, 0) it reaches
  // x = 0 at y = 2.3 > 2 and y = 2 at x = 1.5 > 1.
  EXPECT_TRUE(spansOf(*b, Ray(dvec3(-1, 2.5, 1), dvec3(1, -0.2, 0))).empty());
  // Along (1, -0.25, 0) it passes exactly through the edge x = 1, y = 2.
  SpanList edge = spansOf(*b, Ray(dvec3(-1, 2.5, 1), dvec3(1, -0.25, 0)));
  ASSERT_LE(edge.size(), 1u);
  if (!edge.empty()) {
    EXPECT_DOUBLE_EQ(edge[0].length(), 0.0);
  }
}

TEST(BoxPrimitive, ParallelRays) {
  auto b = Primitive::create<Box>(dvec3(1, 2, 3));
  EXPECT_TRUE(spansOf(*b, Ray(dvec3(-5, 2.5, 1), dvec3(1, 0, 0))).empty());
  EXPECT_TRUE(spansOf(*b, Ray(dvec3(-5, 1, -0.1), dvec3(1, 0, 0))).empty());
  // In the plane of a face: the closed box includes it.
  SpanList onFace = spansOf(*b, Ray(dvec3(-5, 2, 1), dvec3(1, 0, 0)));
  ASSERT_EQ(onFace.size(), 1u);
  EXPECT_DOUBLE_EQ(onFace[0].in.t, 5.0);
  EXPECT_DOUBLE_EQ(onFace[0].out.t, 6.0);
}

TEST(BoxPrimitive, FaceNormals) {
  auto b = Primitive::create<Box>(dvec3(1, 2, 3));
  for (int face = 0; face < 6; ++face) {
    dvec3 n(0.0);
    n[face / 2] = face % 2 ? 1.0 : -1.0;
    dvec3 p(0.5, 1.0, 1.5);
    p[face / 2] = face % 2 ? dvec3(1, 2, 3)[face / 2] : 0.0;
    EXPECT_EQ(b->normal(p, face), n) << face;
  }
  expectOutwardUnitNormals(*b);
}

TEST(BoxPrimitive, ContainsClosedBox) {
  auto b = Primitive::create<Box>(dvec3(1, 2, 3));
  EXPECT_TRUE(b->contains(dvec3(0.5, 1, 1.5)));
  EXPECT_TRUE(b->contains(dvec3(0, 0, 0)));  // corners and faces belong
  EXPECT_TRUE(b->contains(dvec3(1, 2, 3)));
  EXPECT_TRUE(b->contains(dvec3(1, 0.3, 2)));
  EXPECT_FALSE(b->contains(dvec3(-1e-9, 1, 1)));
  EXPECT_FALSE(b->contains(dvec3(0.5, 2.001, 1)));
  EXPECT_FALSE(b->contains(dvec3(0.5, 1, 3.5)));
}

TEST(BoxPrimitive, Bounds) {
  auto b = Primitive::create<Box>(dvec3(1, 2, 3));
  expectBoundsNear(b->bounds(), dvec3(0.0), dvec3(1, 2, 3));
  EXPECT_EQ(b->size(), dvec3(1, 2, 3));
  EXPECT_EQ(b->kind(), "box");
}

TEST(BoxPrimitive, CullsToRayWindow) {
  auto b = Primitive::create<Box>(dvec3(1, 2, 3));
  dvec3 o(-5, 1, 1), d(1, 0, 0);  // inside for t in [5, 6]
  EXPECT_TRUE(spansOf(*b, Ray(o, d, 6.5, kInfinity)).empty());
  EXPECT_TRUE(spansOf(*b, Ray(o, d, 0.0, 4.5)).empty());
  SpanList straddle = spansOf(*b, Ray(o, d, 5.5, kInfinity));
  ASSERT_EQ(straddle.size(), 1u);
  EXPECT_DOUBLE_EQ(straddle[0].in.t, 5.0);
  EXPECT_DOUBLE_EQ(straddle[0].out.t, 6.0);
}

TEST(BoxPrimitive, SpansAgreeWithContains) {
  auto b = Primitive::create<Box>(dvec3(1, 2, 3));
  expectSpansAgreeWithContainsOnRandomLines(*b);
  // Lines through corners, edges and in face planes.
  expectAgreementOnLinesThrough(*b, dvec3(0, 0, 0));
  expectAgreementOnLinesThrough(*b, dvec3(1, 2, 1.5));
  std::mt19937_64 rng(9);
  for (int i = 0; i < 500; ++i) {
    dvec3 d = randomDirection(rng);
    d.z = 0.0;
    if (glm::length(d) < 1e-3) continue;
    Ray inPlane(dvec3(0.5, 1.0, i % 2 ? 3.0 : 0.0), glm::normalize(d), -kInfinity, kInfinity);
    expectSpansAgreeWithContains(*b, inPlane);
    ASSERT_FALSE(spansOf(*b, inPlane).empty());
  }
}

TEST(BoxPrimitive, RejectsDegenerateSize) {
  for (dvec3 size : {dvec3(0, 1, 1), dvec3(1, 0, 1), dvec3(1, 1, 0), dvec3(1, -1, 1),
                     dvec3(kNaN, 1, 1), dvec3(1, 1, kInfinity)})
    EXPECT_THROW(Primitive::create<Box>(size), std::invalid_argument);
}

// ----------------------------------------------------------------- cylinder

// Cylinder r = 1, h = 3: a horizontal line through the axis is inside for a
// chord of 2r, one at distance y from the axis for 2·sqrt(r² - y²).
TEST(CylinderPrimitive, HitsSide) {
  auto c = Primitive::create<Cylinder>(1.0, 1.0, 3.0);
  SpanList spans = spansOf(*c, Ray(dvec3(-5, 0, 1.5), dvec3(1, 0, 0)));
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_DOUBLE_EQ(spans[0].in.t, 4.0);
  EXPECT_DOUBLE_EQ(spans[0].out.t, 6.0);
  EXPECT_EQ(spans[0].in.face, 0);
  EXPECT_EQ(spans[0].out.face, 0);
  SpanList off = spansOf(*c, Ray(dvec3(-5, 0.6, 2.9), dvec3(1, 0, 0)));
  ASSERT_EQ(off.size(), 1u);
  EXPECT_NEAR(off[0].length(), 2.0 * std::sqrt(1.0 - 0.36), 1e-12);
  EXPECT_TRUE(spansOf(*c, Ray(dvec3(-5, 1.01, 1), dvec3(1, 0, 0))).empty());
  EXPECT_TRUE(spansOf(*c, Ray(dvec3(-5, 0, 3.01), dvec3(1, 0, 0))).empty());
}

// Along the axis the span is [0, h] in z with the bottom (1) and top (2)
// caps as faces, swapped when the ray goes down.
TEST(CylinderPrimitive, HitsCaps) {
  auto c = Primitive::create<Cylinder>(1.0, 1.0, 3.0);
  SpanList up = spansOf(*c, Ray(dvec3(0.2, 0.3, -2), dvec3(0, 0, 1)));
  ASSERT_EQ(up.size(), 1u);
  EXPECT_DOUBLE_EQ(up[0].in.t, 2.0);
  EXPECT_DOUBLE_EQ(up[0].out.t, 5.0);
  EXPECT_EQ(up[0].in.face, 1);
  EXPECT_EQ(up[0].out.face, 2);
  SpanList down = spansOf(*c, Ray(dvec3(0.2, 0.3, 5), dvec3(0, 0, -1)));
  ASSERT_EQ(down.size(), 1u);
  EXPECT_DOUBLE_EQ(down[0].in.t, 2.0);
  EXPECT_DOUBLE_EQ(down[0].out.t, 5.0);
  EXPECT_EQ(down[0].in.face, 2);
  EXPECT_EQ(down[0].out.face, 1);
  EXPECT_TRUE(spansOf(*c, Ray(dvec3(1.1, 0, -2), dvec3(0, 0, 1))).empty());
  // From (0, 0, -1) along (0.5, 0, 1): through the bottom at t = 1 (x = 0.5),
  // out through the side at t = 2 (x = 1, z = 1).
  SpanList slanted = spansOf(*c, Ray(dvec3(0, 0, -1), dvec3(0.5, 0, 1)));
  ASSERT_EQ(slanted.size(), 1u);
  EXPECT_DOUBLE_EQ(slanted[0].in.t, 1.0);
  EXPECT_EQ(slanted[0].in.face, 1);
  EXPECT_DOUBLE_EQ(slanted[0].out.t, 2.0);
  EXPECT_EQ(slanted[0].out.face, 0);
}

// Cone frustum r1 = 2, r2 = 1, h = 4: at z = 2 the radius is 1.5, so a
// horizontal line through the axis is inside for a chord of 2·1.5.
TEST(CylinderPrimitive, ConeFrustumChord) {
  auto c = Primitive::create<Cylinder>(2.0, 1.0, 4.0);
  SpanList spans = spansOf(*c, Ray(dvec3(-5, 0, 2), dvec3(1, 0, 0)));
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_NEAR(spans[0].in.t, 3.5, 1e-12);
  EXPECT_NEAR(spans[0].out.t, 6.5, 1e-12);
  EXPECT_EQ(spans[0].in.face, 0);
  // At z = 1 the radius is 1.75, at z = 3.9 it is 1.025.
  EXPECT_NEAR(spansOf(*c, Ray(dvec3(0, -5, 1), dvec3(0, 1, 0)))[0].length(), 3.5, 1e-12);
  EXPECT_NEAR(spansOf(*c, Ray(dvec3(0, -5, 3.9), dvec3(0, 1, 0)))[0].length(), 2.05, 1e-12);
  EXPECT_EQ(c->kind(), "cone");
  EXPECT_EQ(Primitive::create<Cylinder>(1.0, 1.0, 1.0)->kind(), "cylinder");
}

// From far off (an orthographic camera placed 10⁸ away) the chords are
// those seen from near: the side's quadratic, solved at the far origin,
// lost the radius to cancellation and broke into noise.
TEST(CylinderPrimitive, ChordsFromFarAwayAreExact) {
  auto cylinder = Primitive::create<Cylinder>(3.0, 3.0, 6.0);
  auto cone = Primitive::create<Cylinder>(2.0, 1.0, 4.0);
  for (const double far : {1e5, 1e8, 1e12}) {
    for (const double y : {0.0, 1.0, 2.9}) {
      // A horizontal line at height 3, distance y from the axis: a chord
      // of 2·sqrt(9 − y²), entered at far − sqrt(9 − y²).
      const SpanList spans = spansOf(*cylinder, Ray(dvec3(-far, y, 3), dvec3(1, 0, 0)));
      ASSERT_EQ(spans.size(), 1u) << far << " " << y;
      const double half = std::sqrt(9.0 - y * y);
      EXPECT_NEAR(spans[0].length(), 2.0 * half, 1e-15 * far + 1e-12) << far << " " << y;
      EXPECT_NEAR(spans[0].in.t, far - half, 1e-15 * far + 1e-12) << far << " " << y;
    }
    // The frustum at z = 2, radius 1.5, along an oblique line.
    const dvec3 dir = glm::normalize(dvec3(1, 1, 0));
    const SpanList chord = spansOf(*cone, Ray(dvec3(0, 0, 2) - far * dir, dir));
    ASSERT_EQ(chord.size(), 1u) << far;
    EXPECT_NEAR(chord[0].length(), 3.0, 1e-15 * far + 1e-12) << far;
  }
}

// Side normals: (x, y, 0)/r on a cylinder; on the frustum r1 = 2, r2 = 1,
// h = 4 the side's generator runs along (-1, 0, 4), so the outward normal
// in the xz-plane is (4, 0, 1)/sqrt(17), rotated about z with the point.
TEST(CylinderPrimitive, Normals) {
  auto cyl = Primitive::create<Cylinder>(1.0, 1.0, 3.0);
  expectVecNear(cyl->normal(dvec3(0.6, 0.8, 1.0), 0), dvec3(0.6, 0.8, 0.0), 1e-15);
  expectVecNear(cyl->normal(dvec3(0.1, 0.2, 0.0), 1), dvec3(0, 0, -1), 0.0);
  expectVecNear(cyl->normal(dvec3(0.1, 0.2, 3.0), 2), dvec3(0, 0, 1), 0.0);
  auto cone = Primitive::create<Cylinder>(2.0, 1.0, 4.0);
  for (double phi : {0.0, 1.0, 2.5, 4.0}) {
    double r = 1.5;
    dvec3 p(r * std::cos(phi), r * std::sin(phi), 2.0);
    dvec3 expected = dvec3(4 * std::cos(phi), 4 * std::sin(phi), 1.0) / std::sqrt(17.0);
    expectVecNear(cone->normal(p, 0), expected, 1e-14);
  }
  // A cone widening upwards (r1 = 1, r2 = 2) has its side normal tilted down.
  auto up = Primitive::create<Cylinder>(1.0, 2.0, 4.0);
  expectVecNear(up->normal(dvec3(1.5, 0, 2), 0), dvec3(4, 0, -1) / std::sqrt(17.0), 1e-14);
  expectOutwardUnitNormals(*cyl);
  expectOutwardUnitNormals(*cone);
  expectOutwardUnitNormals(*up);
  expectOutwardUnitNormals(*Primitive::create<Cylinder>(0.0, 1.5, 2.0));
}

TEST(CylinderPrimitive, Contains) {
  auto cone = Primitive::create<Cylinder>(2.0, 1.0, 4.0);
  EXPECT_TRUE(cone->contains(dvec3(0, 0, 0)));
  EXPECT_TRUE(cone->contains(dvec3(1.99, 0, 0)));
  EXPECT_TRUE(cone->contains(dvec3(0, 1.49, 2)));
  EXPECT_FALSE(cone->contains(dvec3(0, 1.51, 2)));
  EXPECT_TRUE(cone->contains(dvec3(0.7, 0.7, 4)));  // top cap, r = 0.99 < 1
  EXPECT_FALSE(cone->contains(dvec3(0, 0, 4.001)));
  EXPECT_FALSE(cone->contains(dvec3(0, 0, -0.001)));
  auto pointed = Primitive::create<Cylinder>(1.0, 0.0, 2.0);
  EXPECT_TRUE(pointed->contains(dvec3(0, 0, 2)));  // the apex
  EXPECT_FALSE(pointed->contains(dvec3(0.01, 0, 2)));
  EXPECT_TRUE(pointed->contains(dvec3(0.49, 0, 1)));
  EXPECT_FALSE(pointed->contains(dvec3(0.51, 0, 1)));
}

TEST(CylinderPrimitive, Bounds) {
  expectBoundsNear(Primitive::create<Cylinder>(1.0, 1.0, 3.0)->bounds(), dvec3(-1, -1, 0),
                   dvec3(1, 1, 3));
  expectBoundsNear(Primitive::create<Cylinder>(2.0, 1.0, 4.0)->bounds(), dvec3(-2, -2, 0),
                   dvec3(2, 2, 4));
  expectBoundsNear(Primitive::create<Cylinder>(0.0, 1.5, 2.0)->bounds(), dvec3(-1.5, -1.5, 0),
                   dvec3(1.5, 1.5, 2));
}

TEST(CylinderPrimitive, CullsToRayWindow) {
  auto c = Primitive::create<Cylinder>(1.0, 1.0, 3.0);
  dvec3 o(-5, 0, 1.5), d(1, 0, 0);  // inside for t in [4, 6]
  EXPECT_TRUE(spansOf(*c, Ray(o, d, 6.5, kInfinity)).empty());
  EXPECT_TRUE(spansOf(*c, Ray(o, d, 0.0, 3.5)).empty());
  SpanList straddle = spansOf(*c, Ray(o, d, 5.0, kInfinity));
  ASSERT_EQ(straddle.size(), 1u);
  EXPECT_DOUBLE_EQ(straddle[0].in.t, 4.0);
  EXPECT_DOUBLE_EQ(straddle[0].out.t, 6.0);
}

TEST(CylinderPrimitive, SpansAgreeWithContains) {
  for (auto c :
       {Primitive::create<Cylinder>(1.0, 1.0, 3.0), Primitive::create<Cylinder>(2.0, 1.0, 4.0),
        Primitive::create<Cylinder>(1.0, 2.0, 0.5), Primitive::create<Cylinder>(0.0, 1.5, 2.0),
        Primitive::create<Cylinder>(1.0, 0.0, 2.0)}) {
    SCOPED_TRACE(c->kind() + " r1=" + std::to_string(c->r1()) + " r2=" + std::to_string(c->r2()));
    expectSpansAgreeWithContainsOnRandomLines(*c);
    // Tangent-ish: lines through points of the rim circles.
    expectAgreementOnLinesThrough(*c, dvec3(c->r1(), 0.0, 0.0), 300);
    expectAgreementOnLinesThrough(*c, dvec3(0.0, c->r2(), c->height()), 300);
  }
}

// Lines through the apex of a pointed cone, inside it, cross the apex: the
// spans must still be a valid (disjoint) list.
TEST(CylinderPrimitive, LinesThroughConeApex) {
  auto top = Primitive::create<Cylinder>(1.0, 0.0, 2.0);
  SpanList axis = spansOf(*top, Ray(dvec3(0, 0, -1), dvec3(0, 0, 1), -kInfinity, kInfinity));
  ASSERT_TRUE(axis.valid());
  ASSERT_EQ(axis.size(), 1u);
  EXPECT_DOUBLE_EQ(axis[0].in.t, 1.0);
  EXPECT_DOUBLE_EQ(axis[0].out.t, 3.0);
  EXPECT_EQ(axis[0].in.face, 1);
  expectAgreementOnLinesThrough(*top, dvec3(0, 0, 2));
  auto bottom = Primitive::create<Cylinder>(0.0, 1.0, 2.0);
  SpanList down = spansOf(*bottom, Ray(dvec3(0, 0, 5), dvec3(0, 0, -1), -kInfinity, kInfinity));
  ASSERT_TRUE(down.valid());
  ASSERT_EQ(down.size(), 1u);
  EXPECT_DOUBLE_EQ(down[0].in.t, 3.0);
  EXPECT_DOUBLE_EQ(down[0].out.t, 5.0);
  expectAgreementOnLinesThrough(*bottom, dvec3(0, 0, 0));
}

TEST(CylinderPrimitive, RejectsDegenerateParameters) {
  EXPECT_THROW(Primitive::create<Cylinder>(1.0, 1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(Primitive::create<Cylinder>(1.0, 1.0, -1.0), std::invalid_argument);
  EXPECT_THROW(Primitive::create<Cylinder>(0.0, 0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(Primitive::create<Cylinder>(-1.0, 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(Primitive::create<Cylinder>(1.0, -0.5, 1.0), std::invalid_argument);
  EXPECT_THROW(Primitive::create<Cylinder>(kNaN, 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(Primitive::create<Cylinder>(1.0, kInfinity, 1.0), std::invalid_argument);
  EXPECT_THROW(Primitive::create<Cylinder>(1.0, 1.0, kNaN), std::invalid_argument);
  EXPECT_THROW(Primitive::create<Cylinder>(1.0, 1.0, kInfinity), std::invalid_argument);
  EXPECT_NO_THROW(Primitive::create<Cylinder>(0.0, 1.0, 1.0));
  EXPECT_NO_THROW(Primitive::create<Cylinder>(1.0, 0.0, 1.0));
}

// --------------------------------------------------------------- half-space

// z <= 2: a ray going up from the origin is inside for t in (-inf, 2], one
// coming down from z = 5 for t in [3, inf); the infinite end has no primitive.
TEST(HalfSpacePrimitive, UnboundedSpans) {
  auto h = Primitive::create<HalfSpace>(dvec3(0, 0, 1), 2.0);
  SpanList up = spansOf(*h, Ray(dvec3(0.0), dvec3(0, 0, 1)));
  ASSERT_EQ(up.size(), 1u);
  EXPECT_EQ(up[0].in.t, -kInfinity);
  EXPECT_EQ(up[0].in.primitive, nullptr);
  EXPECT_DOUBLE_EQ(up[0].out.t, 2.0);
  EXPECT_EQ(up[0].out.primitive, h.get());
  SpanList down = spansOf(*h, Ray(dvec3(0, 0, 5), dvec3(0, 0, -1)));
  ASSERT_EQ(down.size(), 1u);
  EXPECT_DOUBLE_EQ(down[0].in.t, 3.0);
  EXPECT_EQ(down[0].in.primitive, h.get());
  EXPECT_EQ(down[0].out.t, kInfinity);
  EXPECT_EQ(down[0].out.primitive, nullptr);
  // Oblique: along (0, 0.6, 0.8) from z = 0 the plane is reached at t = 2.5.
  SpanList slant = spansOf(*h, Ray(dvec3(1, 1, 0), dvec3(0, 0.6, 0.8), -kInfinity));
  ASSERT_EQ(slant.size(), 1u);
  EXPECT_NEAR(slant[0].out.t, 2.5, 1e-15);
}

TEST(HalfSpacePrimitive, ParallelLines) {
  auto h = Primitive::create<HalfSpace>(dvec3(0, 0, 1), 2.0);
  SpanList inside = spansOf(*h, Ray(dvec3(0, 0, 1), dvec3(1, 0, 0), -kInfinity, kInfinity));
  ASSERT_EQ(inside.size(), 1u);
  EXPECT_EQ(inside[0].in.t, -kInfinity);
  EXPECT_EQ(inside[0].out.t, kInfinity);
  EXPECT_EQ(inside[0].in.primitive, nullptr);
  EXPECT_EQ(inside[0].out.primitive, nullptr);
  EXPECT_TRUE(spansOf(*h, Ray(dvec3(0, 0, 3), dvec3(1, 0, 0))).empty());
}

// The normal need not be unit: (0, 0, 2)·p <= 4 is the set z <= 2.
TEST(HalfSpacePrimitive, NonUnitNormalIsNormalised) {
  auto h = Primitive::create<HalfSpace>(dvec3(0, 0, 2), 4.0);  // 2z <= 4
  SpanList up = spansOf(*h, Ray(dvec3(0.0), dvec3(0, 0, 1)));
  ASSERT_EQ(up.size(), 1u);
  EXPECT_DOUBLE_EQ(up[0].out.t, 2.0);
  EXPECT_EQ(h->normal(dvec3(0, 0, 2), up[0].out.face), dvec3(0, 0, 1));
  auto tilted = Primitive::create<HalfSpace>(dvec3(3, 4, 0), 10.0);  // 0.6x + 0.8y <= 2
  expectVecNear(tilted->normal(dvec3(0, 2.5, 0), 0), dvec3(0.6, 0.8, 0), 1e-15);
  EXPECT_TRUE(tilted->contains(dvec3(2, 1, 7)));  // 6 + 4 = 10
  EXPECT_FALSE(tilted->contains(dvec3(2, 1.01, 0)));
  EXPECT_TRUE(tilted->contains(dvec3(-100, -100, 0)));
  expectOutwardUnitNormals(*tilted);
}

// Bounds are tight on the axis of an axis-aligned half-space: z <= 2 has
// hi.z = 2, -x <= 1 (x >= -1) has lo.x = -1; a tilted one is unbounded.
TEST(HalfSpacePrimitive, Bounds) {
  Bounds z = Primitive::create<HalfSpace>(dvec3(0, 0, 1), 2.0)->bounds();
  EXPECT_EQ(z.hi.z, 2.0);
  EXPECT_EQ(z.lo.z, -kInfinity);
  EXPECT_EQ(z.lo.x, -kInfinity);
  EXPECT_EQ(z.hi.y, kInfinity);
  Bounds x = Primitive::create<HalfSpace>(dvec3(-1, 0, 0), 1.0)->bounds();
  EXPECT_EQ(x.lo.x, -1.0);
  EXPECT_EQ(x.hi.x, kInfinity);
  Bounds t = Primitive::create<HalfSpace>(dvec3(1, 1, 0), 1.0)->bounds();
  EXPECT_EQ(t.lo, dvec3(-kInfinity));
  EXPECT_EQ(t.hi, dvec3(kInfinity));
}

TEST(HalfSpacePrimitive, CullsToRayWindow) {
  auto h = Primitive::create<HalfSpace>(dvec3(0, 0, 1), 2.0);
  dvec3 o(0.0), up(0, 0, 1);  // inside for t in (-inf, 2]
  EXPECT_TRUE(spansOf(*h, Ray(o, up, 3.0, kInfinity)).empty());
  SpanList straddle = spansOf(*h, Ray(o, up, 1.0, kInfinity));
  ASSERT_EQ(straddle.size(), 1u);
  EXPECT_EQ(straddle[0].in.t, -kInfinity);
  SpanList before = spansOf(*h, Ray(dvec3(0, 0, 5), -up, 0.0, 2.0));  // inside from t = 3
  EXPECT_TRUE(before.empty());
}

TEST(HalfSpacePrimitive, SpansAgreeWithContains) {
  expectSpansAgreeWithContainsOnRandomLines(*Primitive::create<HalfSpace>(dvec3(1, -2, 0.5), 0.7));
  expectSpansAgreeWithContainsOnRandomLines(*Primitive::create<HalfSpace>(dvec3(0, 1, 0), -1));
  // Nearly parallel lines.
  auto h = Primitive::create<HalfSpace>(dvec3(0, 0, 1), 0.0);
  for (double dz : {1e-12, -1e-12, 1e-300, 0.0}) {
    Ray line(dvec3(0, 0, 1e-3), glm::normalize(dvec3(1, 0, dz)), -kInfinity, kInfinity);
    expectSpansAgreeWithContains(*h, line);
  }
}

TEST(HalfSpacePrimitive, RejectsDegenerateParameters) {
  EXPECT_THROW(Primitive::create<HalfSpace>(dvec3(0.0), 1.0), std::invalid_argument);
  EXPECT_THROW(Primitive::create<HalfSpace>(dvec3(kNaN, 0, 1), 1.0), std::invalid_argument);
  EXPECT_THROW(Primitive::create<HalfSpace>(dvec3(kInfinity, 0, 0), 1.0), std::invalid_argument);
  EXPECT_THROW(Primitive::create<HalfSpace>(dvec3(0, 0, 1), kNaN), std::invalid_argument);
  EXPECT_THROW(Primitive::create<HalfSpace>(dvec3(0, 0, 1), kInfinity), std::invalid_argument);
}

// ------------------------------------------------------------------ quadric

// The sphere of radius r about c: |p - c|² - r² = pᵀMp with
// M = [I, -c; -cᵀ, |c|² - r²].
glm::dmat4 sphereMatrix(const dvec3& c, double r) {
  glm::dmat4 m = diagonal(1, 1, 1, glm::dot(c, c) - r * r);
  for (int i = 0; i < 3; ++i) m[3][i] = m[i][3] = -c[i];
  return m;
}

// diagonal(1, 1, 1, -1) is x² + y² + z² <= 1: the same spans as Sphere(1).
TEST(QuadricPrimitive, UnitSphereMatchesSphere) {
  auto q = Primitive::create<Quadric>(diagonal(1, 1, 1, -1));
  auto s = Primitive::create<Sphere>(1.0);
  std::mt19937_64 rng(21);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    Ray line(test::randomPoint(rng, Bounds{dvec3(-1.5), dvec3(1.5)}), randomDirection(rng),
             -kInfinity, kInfinity);
    SpanList a = spansOf(*q, line), b = spansOf(*s, line);
    ASSERT_EQ(a.size(), b.size());
    for (uint32_t k = 0; k < a.size(); ++k) {
      EXPECT_NEAR(a[k].in.t, b[k].in.t, 1e-12);
      EXPECT_NEAR(a[k].out.t, b[k].out.t, 1e-12);
      EXPECT_EQ(a[k].in.primitive, q.get());
      expectVecNear(q->normal(line.at(a[k].in.t), 0), s->normal(line.at(b[k].in.t), 0), 1e-9);
      ++hits;
    }
    dvec3 p = line.origin;
    EXPECT_EQ(q->contains(p), s->contains(p));
  }
  EXPECT_GT(hits, 500);
  EXPECT_EQ(q->kind(), "quadric");
}

// x² + y² - z² + 1 <= 0 (two sheets, |z| >= sqrt(1 + x² + y²)): along the z
// axis through the origin, inside for t in (-inf, -1] and [1, inf).
TEST(QuadricPrimitive, HyperboloidOfTwoSheets) {
  auto q = Primitive::create<Quadric>(diagonal(1, 1, -1, 1));
  SpanList spans = spansOf(*q, Ray(dvec3(0.0), dvec3(0, 0, 1), -kInfinity, kInfinity));
  ASSERT_EQ(spans.size(), 2u);
  EXPECT_EQ(spans[0].in.t, -kInfinity);
  EXPECT_EQ(spans[0].in.primitive, nullptr);
  EXPECT_DOUBLE_EQ(spans[0].out.t, -1.0);
  EXPECT_EQ(spans[0].out.primitive, q.get());
  EXPECT_DOUBLE_EQ(spans[1].in.t, 1.0);
  EXPECT_EQ(spans[1].out.t, kInfinity);
  EXPECT_EQ(spans[1].out.primitive, nullptr);
  // Outward normals at the vertices point towards the gap between the sheets.
  expectVecNear(q->normal(dvec3(0, 0, 1), 0), dvec3(0, 0, -1), 1e-15);
  expectVecNear(q->normal(dvec3(0, 0, -1), 0), dvec3(0, 0, 1), 1e-15);
  // The line x = 1 along z: 1 - z² + 1 <= 0 for |z| >= sqrt(2).
  SpanList off = spansOf(*q, Ray(dvec3(1, 0, 0), dvec3(0, 0, 1), -kInfinity, kInfinity));
  ASSERT_EQ(off.size(), 2u);
  EXPECT_NEAR(off[1].in.t, std::sqrt(2.0), 1e-15);
  // A horizontal line never meets it.
  EXPECT_TRUE(spansOf(*q, Ray(dvec3(0, 0, 0.5), dvec3(1, 0, 0), -kInfinity)).empty());
  EXPECT_EQ(q->bounds().lo, dvec3(-kInfinity));
  EXPECT_EQ(q->bounds().hi, dvec3(kInfinity));
}

// x² + y² <= 1 as diagonal(1, 1, 0, -1): a line along z inside it is inside
// everywhere, one outside nowhere; across it the chord is 2.
TEST(QuadricPrimitive, InfiniteCylinder) {
  auto q = Primitive::create<Quadric>(diagonal(1, 1, 0, -1));
  SpanList inside = spansOf(*q, Ray(dvec3(0.5, 0.3, 7), dvec3(0, 0, 1), -kInfinity, kInfinity));
  ASSERT_EQ(inside.size(), 1u);
  EXPECT_EQ(inside[0].in.t, -kInfinity);
  EXPECT_EQ(inside[0].out.t, kInfinity);
  EXPECT_EQ(inside[0].in.primitive, nullptr);
  EXPECT_EQ(inside[0].out.primitive, nullptr);
  EXPECT_TRUE(spansOf(*q, Ray(dvec3(1.5, 0, 0), dvec3(0, 0, 1), -kInfinity)).empty());
  SpanList across = spansOf(*q, Ray(dvec3(-5, 0, 100), dvec3(1, 0, 0)));
  ASSERT_EQ(across.size(), 1u);
  EXPECT_DOUBLE_EQ(across[0].in.t, 4.0);
  EXPECT_DOUBLE_EQ(across[0].out.t, 6.0);
  expectVecNear(q->normal(dvec3(0.6, -0.8, 42), 0), dvec3(0.6, -0.8, 0), 1e-15);
}

// The paraboloid x² + y² - z <= 0 (M has -1/2 at (2,3) and (3,2)): its
// normal ∝ gradient (2x, 2y, -1).
TEST(QuadricPrimitive, Paraboloid) {
  glm::dmat4 m = diagonal(1, 1, 0, 0);
  m[2][3] = m[3][2] = -0.5;
  auto q = Primitive::create<Quadric>(m);
  SpanList up = spansOf(*q, Ray(dvec3(1, 0, -3), dvec3(0, 0, 1), -kInfinity, kInfinity));
  ASSERT_EQ(up.size(), 1u);
  EXPECT_DOUBLE_EQ(up[0].in.t, 4.0);  // z = 1
  EXPECT_EQ(up[0].out.t, kInfinity);
  expectVecNear(q->normal(dvec3(1, 0, 1), 0), dvec3(2, 0, -1) / std::sqrt(5.0), 1e-15);
  EXPECT_TRUE(q->contains(dvec3(1, 1, 2)));
  EXPECT_FALSE(q->contains(dvec3(1, 1, 1.9)));
}

// With M = [A b; bᵀ m], A positive definite, the solid is an ellipsoid with
// half-extents sqrt(k·(A⁻¹)ᵢᵢ), k = bᵀA⁻¹b - m: diagonal(1/4, 1, 1, -1) is
// x²/4 + y² + z² <= 1, so x in [-2, 2].
TEST(QuadricPrimitive, EllipsoidBounds) {
  auto q = Primitive::create<Quadric>(diagonal(0.25, 1, 1, -1));
  expectBoundsNear(q->bounds(), dvec3(-2, -1, -1), dvec3(2, 1, 1));
  // Off-centre sphere about (1, 2, 3) of radius 2.
  auto moved = Primitive::create<Quadric>(sphereMatrix(dvec3(1, 2, 3), 2.0));
  expectBoundsNear(moved->bounds(), dvec3(-1, 0, 1), dvec3(3, 4, 5), 1e-12);
  SpanList spans = spansOf(*moved, Ray(dvec3(1, 2, -10), dvec3(0, 0, 1)));
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_NEAR(spans[0].in.t, 11.0, 1e-12);
  EXPECT_NEAR(spans[0].out.t, 15.0, 1e-12);
}

// A tilted ellipse 2x² + 2xy + 2y² + z² <= 1: the bound on x is reached at
// the extreme point p* = sqrt(k)·A⁻¹e / sqrt(eᵀA⁻¹e), which lies in the
// solid, and no point beyond it does.
TEST(QuadricPrimitive, TiltedEllipsoidBoundsAreTight) {
  glm::dmat4 m = diagonal(2, 2, 1, -1);
  m[0][1] = m[1][0] = 1.0;
  auto q = Primitive::create<Quadric>(m);
  Bounds b = q->bounds();
  EXPECT_NEAR(b.hi.x, std::sqrt(2.0 / 3.0), 1e-12);  // (A⁻¹)₀₀ = 2/3
  EXPECT_NEAR(b.lo.y, -std::sqrt(2.0 / 3.0), 1e-12);
  EXPECT_NEAR(b.hi.z, 1.0, 1e-12);
  dvec3 extreme = dvec3(2.0 / 3.0, -1.0 / 3.0, 0.0) / std::sqrt(2.0 / 3.0);
  EXPECT_TRUE(q->contains(extreme * (1 - 1e-12)));
  EXPECT_FALSE(q->contains(extreme * (1 + 1e-9)));
  std::mt19937_64 rng(4);
  for (int i = 0; i < 10000; ++i) {
    dvec3 p = test::randomPoint(rng, Bounds{dvec3(-1.5), dvec3(1.5)});
    if (q->contains(p)) {
      ASSERT_TRUE(b.contains(p)) << p.x << " " << p.y << " " << p.z;
    }
  }
}

// diagonal(1, 1, 1, 1) is x² + y² + z² + 1 <= 0: empty everywhere.
TEST(QuadricPrimitive, EmptyQuadric) {
  auto q = Primitive::create<Quadric>(diagonal(1, 1, 1, 1));
  EXPECT_TRUE(q->bounds().empty());
  EXPECT_FALSE(q->contains(dvec3(0.0)));
  EXPECT_TRUE(spansOf(*q, Ray(dvec3(0, 0, -5), dvec3(0, 0, 1), -kInfinity)).empty());
}

TEST(QuadricPrimitive, CullsToRayWindow) {
  auto q = Primitive::create<Quadric>(diagonal(1, 1, -1, 1));
  dvec3 o(0.0), d(0, 0, 1);
  SpanList ahead = spansOf(*q, Ray(o, d, 2.0, kInfinity));
  ASSERT_EQ(ahead.size(), 1u);
  EXPECT_DOUBLE_EQ(ahead[0].in.t, 1.0);  // straddles tMin: kept whole
  SpanList behind = spansOf(*q, Ray(o, d, -kInfinity, -2.0));
  ASSERT_EQ(behind.size(), 1u);
  EXPECT_DOUBLE_EQ(behind[0].out.t, -1.0);
  EXPECT_TRUE(spansOf(*q, Ray(o, d, -0.5, 0.5)).empty());
}

TEST(QuadricPrimitive, SpansAgreeWithContains) {
  glm::dmat4 paraboloid = diagonal(1, 1, 0, 0);
  paraboloid[2][3] = paraboloid[3][2] = -0.5;
  glm::dmat4 tilted = diagonal(2, 2, 1, -1);
  tilted[0][1] = tilted[1][0] = 1.0;
  for (const glm::dmat4& m :
       {diagonal(1, 1, 1, -1), diagonal(0.25, 1, 1, -1), diagonal(1, 1, -1, 1),
        diagonal(1, 1, -1, -1), diagonal(1, 1, 0, -1), diagonal(1, -1, 0, 0), paraboloid, tilted,
        sphereMatrix(dvec3(1, 2, 3), 2.0)}) {
    auto q = Primitive::create<Quadric>(m);
    expectSpansAgreeWithContainsOnRandomLines(*q);
    expectOutwardUnitNormals(*q);
  }
}

// x² + y² - z² <= 0 is a double cone; lines through its apex inside it are
// inside everywhere, and must not come back as two spans touching at the apex.
TEST(QuadricPrimitive, LinesThroughConeApex) {
  auto q = Primitive::create<Quadric>(diagonal(1, 1, -1, 0));
  SpanList axis = spansOf(*q, Ray(dvec3(0.0), dvec3(0, 0, 1), -kInfinity, kInfinity));
  EXPECT_TRUE(axis.valid());
  ASSERT_EQ(axis.size(), 1u);
  EXPECT_EQ(axis[0].in.t, -kInfinity);
  EXPECT_EQ(axis[0].out.t, kInfinity);
  expectAgreementOnLinesThrough(*q, dvec3(0.0));
  // Tangent-ish: lines grazing the unit sphere quadric.
  auto s = Primitive::create<Quadric>(diagonal(1, 1, 1, -1));
  expectAgreementOnLinesThrough(*s, dvec3(1, 0, 0));
}

TEST(QuadricPrimitive, RejectsDegenerateMatrix) {
  glm::dmat4 nonSymmetric = diagonal(1, 1, 1, -1);
  nonSymmetric[0][1] = 0.5;
  EXPECT_THROW(Primitive::create<Quadric>(nonSymmetric), std::invalid_argument);
  EXPECT_THROW(Primitive::create<Quadric>(glm::dmat4(0.0)), std::invalid_argument);
  EXPECT_THROW(Primitive::create<Quadric>(diagonal(1, kNaN, 1, -1)), std::invalid_argument);
  EXPECT_THROW(Primitive::create<Quadric>(diagonal(1, 1, kInfinity, -1)), std::invalid_argument);
  glm::dmat4 nanOffDiagonal = diagonal(1, 1, 1, -1);
  nanOffDiagonal[3][0] = nanOffDiagonal[0][3] = kNaN;
  EXPECT_THROW(Primitive::create<Quadric>(nanOffDiagonal), std::invalid_argument);
}

}  // namespace
}  // namespace csgray::detail
