// Affine frames: transformed solids give the same ray parameters as the
// untransformed problem, normals transform by the inverse transpose, bounds
// follow the map, composition order is that of the matrix product, and
// invalid matrices are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

#include "engine/boolean.h"
#include "primitives/box.h"
#include "primitives/cylinder.h"
#include "primitives/half_space.h"
#include "primitives/quadric.h"
#include "primitives/sphere.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

using test::expectSpansAgreeWithContainsOnRandomLines;
using test::expectVecNear;
using test::randomDirection;
using test::randomPoint;
using test::spansOf;

constexpr double kPi = std::numbers::pi;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void expectSameSpans(const SpanList& a, const SpanList& b, double tol) {
  ASSERT_EQ(a.size(), b.size());
  for (uint32_t k = 0; k < a.size(); ++k) {
    EXPECT_NEAR(a[k].in.t, b[k].in.t, tol);
    EXPECT_NEAR(a[k].out.t, b[k].out.t, tol);
  }
}

const Primitive& onlyPrimitive(const SolidPtr& s) {
  const Primitive* p = dynamic_cast<const Primitive*>(s.get());
  EXPECT_NE(p, nullptr);
  return *p;
}

// --------------------------------------------------------------- translation

// Sphere(2) moved to c: the ray o + c + t·d meets it at the same t as the
// ray o + t·d meets Sphere(2) at the origin.
TEST(TransformSpans, TranslatedSphereKeepsParameter) {
  dvec3 c(1, 2, 3);
  auto sphere = Primitive::create<Sphere>(2.0);
  SolidPtr moved = sphere->transformed(Affine::translation(c));
  SpanList axis = spansOf(*moved, Ray(dvec3(1, 2, -7), dvec3(0, 0, 1)));
  ASSERT_EQ(axis.size(), 1u);
  EXPECT_NEAR(axis[0].in.t, 8.0, 1e-12);
  EXPECT_NEAR(axis[0].out.t, 12.0, 1e-12);
  std::mt19937_64 rng(1);
  for (int i = 0; i < 1000; ++i) {
    dvec3 o = randomPoint(rng, Bounds{dvec3(-3.0), dvec3(3.0)});
    dvec3 d = randomDirection(rng) * (0.5 + i % 3);
    expectSameSpans(spansOf(*moved, Ray(o + c, d, -kInfinity)),
                    spansOf(*sphere, Ray(o, d, -kInfinity)), 1e-9);
  }
  EXPECT_TRUE(moved->contains(c + dvec3(1.9, 0, 0)));
  EXPECT_FALSE(moved->contains(dvec3(0.0)));
  EXPECT_NEAR(moved->bounds().lo.x, -1.0, 1e-12);
  EXPECT_NEAR(moved->bounds().hi.z, 5.0, 1e-12);
}

// ------------------------------------------------------------------- scaling

// Sphere(1) scaled by 2 is Sphere(2), ray parameters included.
TEST(TransformSpans, UniformScaleMatchesLargerSphere) {
  SolidPtr scaled = Primitive::create<Sphere>(1.0)->transformed(Affine::scaling(dvec3(2.0)));
  auto big = Primitive::create<Sphere>(2.0);
  std::mt19937_64 rng(2);
  for (int i = 0; i < 1000; ++i) {
    Ray line(randomPoint(rng, Bounds{dvec3(-3.0), dvec3(3.0)}), randomDirection(rng), -kInfinity);
    expectSameSpans(spansOf(*scaled, line), spansOf(*big, line), 1e-9);
  }
}

// Sphere(1) scaled by (a, b, c) = (3, 2, 1) is the ellipsoid
// (x/a)² + (y/b)² + (z/c)² <= 1; a line meets it where
// Σ ((oᵢ + t dᵢ)/aᵢ)² = 1, a quadratic in t.
TEST(TransformSpans, EllipsoidMatchesAnalyticRoots) {
  dvec3 axes(3, 2, 1);
  SolidPtr e = Primitive::create<Sphere>(1.0)->transformed(Affine::scaling(axes));
  SpanList x = spansOf(*e, Ray(dvec3(-10, 0, 0), dvec3(1, 0, 0)));
  SpanList y = spansOf(*e, Ray(dvec3(0, -10, 0), dvec3(0, 1, 0)));
  SpanList z = spansOf(*e, Ray(dvec3(0, 0, -10), dvec3(0, 0, 1)));
  ASSERT_EQ(x.size(), 1u);
  ASSERT_EQ(y.size(), 1u);
  ASSERT_EQ(z.size(), 1u);
  EXPECT_NEAR(x[0].in.t, 7.0, 1e-12);
  EXPECT_NEAR(x[0].out.t, 13.0, 1e-12);
  EXPECT_NEAR(y[0].in.t, 8.0, 1e-12);
  EXPECT_NEAR(z[0].out.t, 11.0, 1e-12);
  std::mt19937_64 rng(3);
  int hits = 0;
  for (int i = 0; i < 1000; ++i) {
    dvec3 o = randomPoint(rng, Bounds{-axes - 0.5, axes + 0.5});
    dvec3 d = randomDirection(rng);
    double qa = glm::dot(d / axes, d / axes), qb = 2.0 * glm::dot(o / axes, d / axes),
           qc = glm::dot(o / axes, o / axes) - 1.0;
    double disc = qb * qb - 4 * qa * qc;
    SpanList spans = spansOf(*e, Ray(o, d, -kInfinity));
    if (disc <= 1e-9) {
      EXPECT_LE(spans.size(), disc < -1e-9 ? 0u : 1u);
      continue;
    }
    ASSERT_EQ(spans.size(), 1u);
    EXPECT_NEAR(spans[0].in.t, (-qb - std::sqrt(disc)) / (2 * qa), 1e-9);
    EXPECT_NEAR(spans[0].out.t, (-qb + std::sqrt(disc)) / (2 * qa), 1e-9);
    ++hits;
  }
  EXPECT_GT(hits, 300);
}

// The ellipsoid's outward normal at a surface point is ∝ (x/a², y/b², z/c²),
// the gradient of its equation. This is what the inverse transpose gives;
// transforming the sphere's normal by the scaling itself would not.
TEST(TransformNormals, EllipsoidNormalUsesInverseTranspose) {
  dvec3 axes(3, 2, 1);
  SolidPtr e = Primitive::create<Sphere>(1.0)->transformed(Affine::scaling(axes));
  const Primitive& p = onlyPrimitive(e);
  std::mt19937_64 rng(4);
  int checked = 0;
  for (int i = 0; i < 1000; ++i) {
    Ray line(randomPoint(rng, Bounds{-axes, axes}), randomDirection(rng), -kInfinity);
    SpanList spans = spansOf(*e, line);
    for (const Span& s : spans) {
      for (const Boundary* b : {&s.in, &s.out}) {
        dvec3 x = line.at(b->t);
        EXPECT_NEAR(glm::dot(x / axes, x / axes), 1.0, 1e-9);  // on the surface
        dvec3 expected = glm::normalize(x / (axes * axes));
        expectVecNear(p.normal(x, b->face), expected, 1e-9);
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 500);
  // At (3/√2, 2/√2, 0) the normal is ∝ (1/3, 1/2, 0), not the radial (3, 2, 0).
  dvec3 x(3 / std::sqrt(2.0), 2 / std::sqrt(2.0), 0);
  expectVecNear(p.normal(x, 0), glm::normalize(dvec3(2, 3, 0)), 1e-12);
}

// ------------------------------------------------------------------ rotation

// A turn about a coordinate axis leaves that coordinate exactly as it was,
// for every whole degree: Rodrigues' c + (1 − c)·1 rounds off 1 at 95°,
// 105°, ..., which tilted a hole turned about a plate's axis off the
// plate's face.
TEST(TransformRotation, ATurnAboutAnAxisKeepsThatCoordinate) {
  for (int degrees = 0; degrees < 360; ++degrees)
    for (int axis = 0; axis < 3; ++axis) {
      SCOPED_TRACE(std::to_string(degrees) + "° about axis " + std::to_string(axis));
      dvec3 k(0.0);
      k[axis] = 1.0;
      const Affine turn = Affine::rotation(degrees * kPi / 180.0, k);
      dvec3 p(0.3, 5.0, -7.25);
      EXPECT_EQ(turn.pointToWorld(p)[axis], p[axis]);
    }
}

// A 90° turn about z maps (x, y, z) to (-y, x, z): Box(1, 2, 3) goes to
// x in [-2, 0], y in [0, 1], z in [0, 3]; its +x face (1) now faces +y and
// its +y face (3) faces -x.
TEST(TransformRotation, QuarterTurnMapsBoxBoundsAndFaces) {
  SolidPtr r = Primitive::create<Box>(dvec3(1, 2, 3))
                   ->transformed(Affine::rotation(kPi / 2, dvec3(0, 0, 1)));
  const Primitive& p = onlyPrimitive(r);
  expectVecNear(r->bounds().lo, dvec3(-2, 0, 0), 1e-12);
  expectVecNear(r->bounds().hi, dvec3(0, 1, 3), 1e-12);
  expectVecNear(p.normal(dvec3(-1, 1, 1), 1), dvec3(0, 1, 0), 1e-15);
  expectVecNear(p.normal(dvec3(-2, 0.5, 1), 3), dvec3(-1, 0, 0), 1e-15);
  // Along +x at y = 0.5, z = 1 from x = -5: in through x = -2 (the object's
  // +y face) at t = 3, out through x = 0 (the object's -y face, 2) at t = 5.
  SpanList spans = spansOf(*r, Ray(dvec3(-5, 0.5, 1), dvec3(1, 0, 0)));
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_NEAR(spans[0].in.t, 3.0, 1e-12);
  EXPECT_NEAR(spans[0].out.t, 5.0, 1e-12);
  EXPECT_EQ(spans[0].in.face, 3);
  EXPECT_EQ(spans[0].out.face, 2);
  EXPECT_TRUE(r->contains(dvec3(-1.5, 0.5, 2)));
  EXPECT_FALSE(r->contains(dvec3(0.5, 1.5, 2)));  // where the unrotated box is
}

// A cylinder along +z turned 90° about x lies along -y: y in [-h, 0].
TEST(TransformRotation, QuarterTurnAboutXLaysCylinderDown) {
  SolidPtr c = Primitive::create<Cylinder>(1.0, 1.0, 3.0)
                   ->transformed(Affine::rotation(kPi / 2, dvec3(1, 0, 0)));
  expectVecNear(c->bounds().lo, dvec3(-1, -3, -1), 1e-12);
  expectVecNear(c->bounds().hi, dvec3(1, 0, 1), 1e-12);
  SpanList spans = spansOf(*c, Ray(dvec3(0.2, 5, 0.1), dvec3(0, -1, 0)));
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_NEAR(spans[0].in.t, 5.0, 1e-12);
  EXPECT_NEAR(spans[0].out.t, 8.0, 1e-12);
  EXPECT_EQ(spans[0].in.face, 1);  // the bottom cap now faces +y
  expectVecNear(onlyPrimitive(c).normal(dvec3(0.2, 0, 0.1), 1), dvec3(0, 1, 0), 1e-15);
}

// Rotation about an arbitrary axis moves a ball's centre by Rodrigues'
// formula and changes nothing else.
TEST(TransformRotation, RotatedBallMatchesMovedBall) {
  dvec3 axis = glm::normalize(dvec3(1, 2, -0.5)), c(1.5, -0.5, 0.25);
  double angle = 0.7;
  dvec3 rc = c * std::cos(angle) + glm::cross(axis, c) * std::sin(angle) +
             axis * glm::dot(axis, c) * (1 - std::cos(angle));
  SolidPtr ball = Primitive::create<Sphere>(1.0)->transformed(Affine::translation(c));
  SolidPtr rotated = ball->transformed(Affine::rotation(angle, 3.0 * axis));  // axis any length
  SolidPtr moved = Primitive::create<Sphere>(1.0)->transformed(Affine::translation(rc));
  std::mt19937_64 rng(5);
  for (int i = 0; i < 500; ++i) {
    Ray line(rc + randomPoint(rng, Bounds{dvec3(-1.5), dvec3(1.5)}), randomDirection(rng),
             -kInfinity);
    expectSameSpans(spansOf(*rotated, line), spansOf(*moved, line), 1e-9);
  }
}

// -------------------------------------------------------------------- mirror

// Mirror in the plane x = 0: Box(1, 2, 3) goes to x in [-1, 0]; its +x face
// (1) lies at x = -1 and its outward normal is (-1, 0, 0). Reflections
// reverse orientation, yet normals must stay outward.
TEST(TransformMirror, MirrorFlipsBoxAndKeepsNormalsOutward) {
  SolidPtr m = Primitive::create<Box>(dvec3(1, 2, 3))->transformed(Affine::mirror(dvec3(1, 0, 0)));
  const Primitive& p = onlyPrimitive(m);
  expectVecNear(m->bounds().lo, dvec3(-1, 0, 0), 1e-12);
  expectVecNear(m->bounds().hi, dvec3(0, 2, 3), 1e-12);
  expectVecNear(p.normal(dvec3(-1, 1, 1), 1), dvec3(-1, 0, 0), 1e-15);
  SpanList spans = spansOf(*m, Ray(dvec3(-5, 1, 1), dvec3(1, 0, 0)));
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_NEAR(spans[0].in.t, 4.0, 1e-12);
  EXPECT_EQ(spans[0].in.face, 1);
  std::mt19937_64 rng(6);
  for (int i = 0; i < 500; ++i) {
    Ray line(randomPoint(rng, Bounds{dvec3(-1.5, -0.5, -0.5), dvec3(0.5, 2.5, 3.5)}),
             randomDirection(rng), -kInfinity);
    for (const Span& s : spansOf(*m, line)) {
      if (s.length() < 1e-9) continue;
      EXPECT_LT(glm::dot(p.normal(line.at(s.in.t), s.in.face), line.dir), 1e-12);
      EXPECT_GT(glm::dot(p.normal(line.at(s.out.t), s.out.face), line.dir), -1e-12);
    }
  }
}

// A mirror in a tilted plane maps p to p - 2(n·p)n; p is in the mirrored
// solid iff its reflection is in the original. Mirroring twice is the identity.
TEST(TransformMirror, TiltedMirrorReflectsPointsAndIsInvolution) {
  dvec3 n = glm::normalize(dvec3(1, 1, 0));
  SolidPtr part = differenceOf(
      {Primitive::create<Box>(dvec3(2, 1, 1)),
       Primitive::create<Sphere>(0.6)->transformed(Affine::translation(dvec3(2, 0.5, 0.5)))});
  SolidPtr once = part->transformed(Affine::mirror(dvec3(2, 2, 0)));
  SolidPtr twice = once->transformed(Affine::mirror(n));
  std::mt19937_64 rng(7);
  for (int i = 0; i < 5000; ++i) {
    dvec3 p = randomPoint(rng, Bounds{dvec3(-3.0), dvec3(3.0)});
    dvec3 reflected = p - 2.0 * glm::dot(n, p) * n;
    EXPECT_EQ(once->contains(p), part->contains(reflected));
  }
  for (int i = 0; i < 300; ++i) {
    Ray line(randomPoint(rng, Bounds{dvec3(-0.5), dvec3(2.5)}), randomDirection(rng), -kInfinity);
    expectSameSpans(spansOf(*twice, line), spansOf(*part, line), 1e-9);
  }
}

// --------------------------------------------------------------- composition

// a.then(b) places by a, then by b: its matrix is B·A. Translating by
// (5, 0, 0) then turning 90° about z puts the origin at (0, 5, 0); the
// other order leaves it at (5, 0, 0).
TEST(TransformComposition, ThenAppliesOuterLast) {
  Affine t = Affine::translation(dvec3(5, 0, 0));
  Affine r = Affine::rotation(kPi / 2, dvec3(0, 0, 1));
  Affine tr = t.then(r), rt = r.then(t);
  expectVecNear(tr.pointToWorld(dvec3(0.0)), dvec3(0, 5, 0), 1e-12);
  expectVecNear(rt.pointToWorld(dvec3(0.0)), dvec3(5, 0, 0), 1e-12);
  expectVecNear(tr.pointToWorld(dvec3(1, 0, 0)), dvec3(0, 6, 0), 1e-12);
  glm::dmat4 product = r.worldFromObject() * t.worldFromObject();
  for (int c = 0; c < 4; ++c)
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(tr.worldFromObject()[c][k], product[c][k], 1e-15);
  // The inverse really is the inverse.
  glm::dmat4 id = tr.objectFromWorld() * tr.worldFromObject();
  for (int c = 0; c < 4; ++c)
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(id[c][k], c == k ? 1.0 : 0.0, 1e-15);

  auto ball = Primitive::create<Sphere>(1.0);
  SolidPtr a = ball->transformed(tr), b = ball->transformed(rt);
  EXPECT_TRUE(a->contains(dvec3(0, 5, 0)));
  EXPECT_FALSE(a->contains(dvec3(5, 0, 0)));
  EXPECT_TRUE(b->contains(dvec3(5, 0, 0)));
  EXPECT_FALSE(b->contains(dvec3(0, 5, 0)));
}

// transformed(A) then transformed(B) is transformed(A.then(B)), on a tree.
TEST(TransformComposition, SuccessiveTransformsCompose) {
  SolidPtr tree = unionOf({Primitive::create<Box>(dvec3(1, 2, 0.5)),
                           Primitive::create<Cylinder>(0.5, 0.2, 2.0)
                               ->transformed(Affine::translation(dvec3(0.5, 1, 0)))});
  Affine a = Affine::scaling(dvec3(1, 2, 0.5)).then(Affine::translation(dvec3(1, -1, 2)));
  Affine b = Affine::rotation(1.1, dvec3(0.3, -1, 2));
  SolidPtr stepwise = tree->transformed(a)->transformed(b);
  SolidPtr direct = tree->transformed(a.then(b));
  std::mt19937_64 rng(8);
  Bounds box = direct->bounds();
  for (int i = 0; i < 500; ++i) {
    Ray line(randomPoint(rng, box), randomDirection(rng), -kInfinity);
    expectSameSpans(spansOf(*stepwise, line), spansOf(*direct, line), 1e-9);
  }
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(stepwise->bounds().lo[k], box.lo[k], 1e-9);
    EXPECT_NEAR(stepwise->bounds().hi[k], box.hi[k], 1e-9);
  }
}

// ---------------------------------------------------------------- fromMatrix

// A shear: the normal of a face is perpendicular to the images of the
// face's edges and on the outer side (inverse transpose again).
TEST(TransformFromMatrix, ShearNormalsArePerpendicularToFaces) {
  glm::dmat4 m(1.0);
  m[1][0] = 0.7;   // x += 0.7 y
  m[2][1] = -0.4;  // y -= 0.4 z
  m[3] = glm::dvec4(1, 2, 3, 1);
  Affine shear = Affine::fromMatrix(m);
  SolidPtr box = Primitive::create<Box>(dvec3(1, 2, 3))->transformed(shear);
  const Primitive& p = onlyPrimitive(box);
  glm::dmat3 lin(m);
  for (int face = 0; face < 6; ++face) {
    int axis = face / 2;
    dvec3 centre(0.5, 1.0, 1.5);
    centre[axis] = face % 2 ? dvec3(1, 2, 3)[axis] : 0.0;
    dvec3 world = shear.pointToWorld(centre);
    dvec3 n = p.normal(world, face);
    EXPECT_NEAR(glm::length(n), 1.0, 1e-12);
    for (int edge = 0; edge < 3; ++edge) {
      if (edge == axis) continue;
      EXPECT_NEAR(glm::dot(n, lin[edge]), 0.0, 1e-12) << face;
    }
    dvec3 outward = lin[axis] * (face % 2 ? 1.0 : -1.0);
    EXPECT_GT(glm::dot(n, outward), 0.0) << face;
    EXPECT_TRUE(box->contains(world - 1e-6 * n));
    EXPECT_FALSE(box->contains(world + 1e-6 * n));
  }
  expectSpansAgreeWithContainsOnRandomLines(*box);
}

// A ray mapped into the object keeps t: world point at t ↦ object point at t.
TEST(TransformFromMatrix, RayToObjectKeepsParameter) {
  glm::dmat4 m(1.0);
  m[0] = glm::dvec4(2, 0.5, 0, 0);
  m[1] = glm::dvec4(0, 1, -1, 0);
  m[2] = glm::dvec4(0.3, 0, 3, 0);
  m[3] = glm::dvec4(-1, 4, 2, 1);
  Affine a = Affine::fromMatrix(m);
  EXPECT_FALSE(a.isIdentity());
  Ray world(dvec3(1, 2, 3), dvec3(-0.3, 0.8, 0.1), -1.0, 7.0);
  Ray object = a.rayToObject(world);
  EXPECT_EQ(object.tMin, -1.0);
  EXPECT_EQ(object.tMax, 7.0);
  for (double t : {-1.0, 0.0, 2.5, 7.0}) {
    expectVecNear(object.at(t), a.pointToObject(world.at(t)), 1e-12);
    expectVecNear(a.pointToWorld(object.at(t)), world.at(t), 1e-12);
  }
  EXPECT_TRUE(Affine().isIdentity());
  EXPECT_TRUE(Affine::translation(dvec3(0.0)).isIdentity());
}

TEST(TransformFromMatrix, RejectsInvalidMatrices) {
  glm::dmat4 singular(1.0);
  singular[2] = glm::dvec4(1, 1, 0, 0);  // z column = x + y column
  singular[1] = glm::dvec4(0, 1, 0, 0);
  singular[0] = glm::dvec4(1, 0, 0, 0);
  EXPECT_THROW(Affine::fromMatrix(singular), std::invalid_argument);
  glm::dmat4 flat(1.0);
  flat[2][2] = 0.0;
  EXPECT_THROW(Affine::fromMatrix(flat), std::invalid_argument);
  EXPECT_THROW(Affine::fromMatrix(glm::dmat4(0.0)), std::invalid_argument);
  glm::dmat4 projective(1.0);
  projective[0][3] = 0.5;  // last row (0.5, 0, 0, 1)
  EXPECT_THROW(Affine::fromMatrix(projective), std::invalid_argument);
  glm::dmat4 weighted(1.0);
  weighted[3][3] = 2.0;
  EXPECT_THROW(Affine::fromMatrix(weighted), std::invalid_argument);
  glm::dmat4 nan(1.0);
  nan[1][2] = kNaN;
  EXPECT_THROW(Affine::fromMatrix(nan), std::invalid_argument);
  glm::dmat4 inf(1.0);
  inf[3][0] = kInfinity;
  EXPECT_THROW(Affine::fromMatrix(inf), std::invalid_argument);
  EXPECT_THROW(Affine::scaling(dvec3(1, 0, 1)), std::invalid_argument);
  EXPECT_THROW(Affine::rotation(1.0, dvec3(0.0)), std::invalid_argument);
  EXPECT_THROW(Affine::rotation(kNaN, dvec3(0, 0, 1)), std::invalid_argument);
  EXPECT_THROW(Affine::mirror(dvec3(0.0)), std::invalid_argument);
  EXPECT_THROW(Affine::translation(dvec3(kNaN, 0, 0)), std::invalid_argument);
  // Small but regular maps are fine: singularity is judged relative to scale.
  EXPECT_NO_THROW(Affine::scaling(dvec3(1e-6)));
  EXPECT_NO_THROW(Affine::scaling(dvec3(-1, 1, 1)));
}

// -------------------------------------------------- agreement with contains

TEST(TransformSpans, TransformedSolidsAgreeWithContains) {
  glm::dmat4 shear(1.0);
  shear[1][0] = 0.7;
  shear[2][0] = -0.2;
  glm::dmat4 hyperboloid(0.0);
  hyperboloid[0][0] = hyperboloid[1][1] = hyperboloid[3][3] = 1.0;
  hyperboloid[2][2] = -1.0;
  std::vector<std::pair<const char*, SolidPtr>> solids = {
      {"sheared box",
       Primitive::create<Box>(dvec3(1, 2, 3))->transformed(Affine::fromMatrix(shear))},
      {"rotated cone", Primitive::create<Cylinder>(2.0, 0.5, 3.0)
                           ->transformed(Affine::rotation(0.8, dvec3(1, 1, 0)))},
      {"ellipsoid", Primitive::create<Sphere>(1.0)->transformed(Affine::scaling(dvec3(3, 2, 1)))},
      {"mirrored half-space", Primitive::create<HalfSpace>(dvec3(1, 2, 3), 1.0)
                                  ->transformed(Affine::mirror(dvec3(0, 1, 1)))},
      {"rotated hyperboloid",
       Primitive::create<Quadric>(hyperboloid)->transformed(Affine::rotation(0.5, dvec3(1, 0, 0)))},
      {"scaled and moved tree",
       differenceOf({Primitive::create<Box>(dvec3(2.0)),
                     Primitive::create<Sphere>(1.0)->transformed(Affine::translation(dvec3(1.0))),
                     Primitive::create<Cylinder>(0.3, 0.3, 4.0)
                         ->transformed(Affine::translation(dvec3(1, 1, -1)))})
           ->transformed(Affine::scaling(dvec3(1, 0.5, 2))
                             .then(Affine::rotation(0.3, dvec3(0, 0, 1)))
                             .then(Affine::translation(dvec3(10, 0, 0))))},
  };
  for (const auto& [name, solid] : solids) {
    SCOPED_TRACE(name);
    expectSpansAgreeWithContainsOnRandomLines(*solid);
  }
}

// Transformed bounds hold the transformed solid: every contained random
// point lies in the box, and an unbounded shape moved off-axis is unbounded.
TEST(TransformBounds, BoundsHoldTransformedSolid) {
  SolidPtr cone =
      Primitive::create<Cylinder>(2.0, 0.5, 3.0)
          ->transformed(
              Affine::rotation(0.8, dvec3(1, 1, 0)).then(Affine::translation(dvec3(3, -1, 2))));
  Bounds b = cone->bounds();
  ASSERT_TRUE(b.finite());
  Bounds around{b.lo - 1.0, b.hi + 1.0};
  std::mt19937_64 rng(9);
  int inside = 0;
  for (int i = 0; i < 20000; ++i) {
    dvec3 p = randomPoint(rng, around);
    if (cone->contains(p)) {
      ++inside;
      ASSERT_TRUE(b.contains(p));
    }
  }
  EXPECT_GT(inside, 300);  // the test saw the solid
  SolidPtr plane = Primitive::create<HalfSpace>(dvec3(0, 0, 1), 0.0)
                       ->transformed(Affine::translation(dvec3(0, 0, 1)));
  EXPECT_FALSE(plane->bounds().finite());
  EXPECT_TRUE(plane->contains(dvec3(100, -100, 0.99)));
  EXPECT_FALSE(plane->contains(dvec3(0, 0, 1.01)));
}

}  // namespace
}  // namespace csgray::detail
