// Boolean nodes: bounds rules, contains() semantics against analytic
// predicates, spans against contains() on random lines for nested trees,
// provenance and orientation of boundaries (flip on the faces of holes),
// and the tree utilities (mapPrimitives, withDefaultMaterial, treeStats).
#include "engine/boolean.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <random>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "engine/instance.h"
#include "primitives/box.h"
#include "primitives/cylinder.h"
#include "primitives/half_space.h"
#include "primitives/sphere.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

using test::expectSpansAgreeWithContainsOnRandomLines;
using test::randomDirection;
using test::randomPoint;
using test::spansOf;

SolidPtr sphereAt(double r, const dvec3& c) {
  return Primitive::create<Sphere>(r)->transformed(Affine::translation(c));
}

// The box [lo, hi].
SolidPtr boxFromTo(const dvec3& lo, const dvec3& hi) {
  return Primitive::create<Box>(hi - lo)->transformed(Affine::translation(lo));
}

SolidPtr cylinderAt(double r, double h, const dvec3& base) {
  return Primitive::create<Cylinder>(r, r, h)->transformed(Affine::translation(base));
}

const Primitive* asPrimitive(const SolidPtr& s) { return dynamic_cast<const Primitive*>(s.get()); }

void expectBoundsNear(const Bounds& b, const dvec3& lo, const dvec3& hi, double tol = 1e-9) {
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(b.lo[a], lo[a], tol) << "axis " << a;
    EXPECT_NEAR(b.hi[a], hi[a], tol) << "axis " << a;
  }
}

// At every finite boundary on random lines: it names a primitive on whose
// surface the point lies (inside just behind its outward normal n, outside
// just in front), the shading normal (n, negated if flip) faces against the
// ray where it enters and along it where it leaves, and the solid itself
// has material just behind the shading normal and none in front.
void expectBoundariesOrientedOnRandomLines(const Solid& solid, int count = 1000,
                                           unsigned seed = 2) {
  std::mt19937_64 rng(seed);
  Bounds box = solid.bounds();
  if (!box.finite()) box = Bounds{dvec3(-5.0), dvec3(5.0)};
  const double eps = 1e-6;
  for (int i = 0; i < count; ++i) {
    Ray line(randomPoint(rng, box), randomDirection(rng), -kInfinity, kInfinity);
    SpanList spans = spansOf(solid, line);
    for (const Span& s : spans) {
      for (bool entering : {true, false}) {
        const Boundary& b = entering ? s.in : s.out;
        if (std::isinf(b.t)) {
          EXPECT_EQ(b.primitive, nullptr);
          continue;
        }
        ASSERT_NE(b.primitive, nullptr);
        dvec3 p = line.at(b.t);
        dvec3 n = b.primitive->normal(p, b.face);
        EXPECT_TRUE(b.primitive->contains(p - eps * n)) << "t=" << b.t;
        EXPECT_FALSE(b.primitive->contains(p + eps * n)) << "t=" << b.t;
        dvec3 shading = b.flip ? -n : n;
        double along = glm::dot(shading, line.dir);
        if (entering) {
          EXPECT_LT(along, 1e-9) << "t=" << b.t << " flip=" << b.flip;
        } else {
          EXPECT_GT(along, -1e-9) << "t=" << b.t << " flip=" << b.flip;
        }
        EXPECT_TRUE(solid.contains(p - eps * shading)) << "t=" << b.t;
        EXPECT_FALSE(solid.contains(p + eps * shading)) << "t=" << b.t;
      }
    }
    if (::testing::Test::HasFailure()) return;
  }
}

// Spans of a ray with a window [tMin, tMax] describe the solid correctly
// inside the window: membership at probes in the window equals that of
// the spans of the whole line.
void expectWindowedSpansAgreeWithLine(const Solid& solid, int count = 1000, unsigned seed = 4) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-4.0, 4.0);
  Bounds box = solid.bounds();
  if (!box.finite()) box = Bounds{dvec3(-5.0), dvec3(5.0)};
  auto member = [](const SpanList& spans, double t) {
    for (const Span& s : spans)
      if (s.in.t <= t && t <= s.out.t) return true;
    return false;
  };
  for (int i = 0; i < count; ++i) {
    dvec3 o = randomPoint(rng, box), d = randomDirection(rng);
    double t0 = u(rng), t1 = t0 + std::abs(u(rng));
    SpanList whole = spansOf(solid, Ray(o, d, -kInfinity, kInfinity));
    SpanList window = spansOf(solid, Ray(o, d, t0, t1));
    ASSERT_TRUE(window.valid());
    for (int k = 0; k <= 16; ++k) {
      double t = t0 + (t1 - t0) * (k + 0.5) / 17.0;
      EXPECT_EQ(member(window, t), member(whole, t))
          << "t=" << t << " in [" << t0 << ", " << t1 << "]";
    }
    if (::testing::Test::HasFailure()) return;
  }
}

// ------------------------------------------------------------------ bounds

// Union: the box of the operands' boxes.
TEST(BooleanBounds, UnionIsBoxOfBoxes) {
  SolidPtr u = unionOf({sphereAt(1.0, dvec3(0.0)), boxFromTo(dvec3(5, 5, 5), dvec3(6, 7, 8)),
                        sphereAt(0.5, dvec3(2, -3, 0))});
  expectBoundsNear(u->bounds(), dvec3(-1, -3.5, -1), dvec3(6, 7, 8));
}

// Intersection: the overlap of the operands' boxes; empty if disjoint.
TEST(BooleanBounds, IntersectionIsOverlapOfBoxes) {
  SolidPtr i =
      intersectionOf({sphereAt(2.0, dvec3(0.0)), boxFromTo(dvec3(1, 1, 1), dvec3(5, 5, 5))});
  expectBoundsNear(i->bounds(), dvec3(1, 1, 1), dvec3(2, 2, 2));
  SolidPtr disjoint = intersectionOf({sphereAt(1.0, dvec3(0.0)), sphereAt(1.0, dvec3(5, 0, 0))});
  EXPECT_TRUE(disjoint->bounds().empty());
  EXPECT_TRUE(spansOf(*disjoint, Ray(dvec3(-10, 0, 0), dvec3(1, 0, 0))).empty());
  EXPECT_FALSE(disjoint->contains(dvec3(0.0)));
  // With an unbounded operand: z <= 0.5 cuts the sphere's box at z = 0.5.
  SolidPtr cut = intersectionOf(
      {Primitive::create<HalfSpace>(dvec3(0, 0, 1), 0.5), sphereAt(1.0, dvec3(0.0))});
  expectBoundsNear(cut->bounds(), dvec3(-1, -1, -1), dvec3(1, 1, 0.5));
}

// Difference: the first operand's box, whatever is subtracted.
TEST(BooleanBounds, DifferenceIsFirstOperandsBox) {
  SolidPtr d = differenceOf({boxFromTo(dvec3(0.0), dvec3(4.0)), sphereAt(10.0, dvec3(0.0)),
                             Primitive::create<HalfSpace>(dvec3(1, 1, 1), 0.0)});
  expectBoundsNear(d->bounds(), dvec3(0.0), dvec3(4.0));
  SolidPtr unbounded =
      differenceOf({Primitive::create<HalfSpace>(dvec3(1, 1, 0), 0.0), sphereAt(1.0, dvec3(0.0))});
  EXPECT_FALSE(unbounded->bounds().finite());
}

// An intersection's spans() leaves its first operand's box untested, and a
// difference of an intersection its own box, because the slab test of a box
// within another, on the same ray, passes only if the other's does:
// nearer planes give nearer distances however they round. Random boxes,
// each an intersection's box within its operands' (as Boolean builds it),
// and rays from random points, from points on the inner box's planes, and
// along the axes (1/dir infinite, 0 times infinity on a plane), with random
// windows.
TEST(BooleanBounds, SlabTestOfABoxWithinAnotherPassesForTheOther) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  auto randomBox = [&] {
    dvec3 a(unit(rng), unit(rng), unit(rng)), b(unit(rng), unit(rng), unit(rng));
    return Bounds{glm::min(a, b), glm::max(a, b)};
  };
  int innerHits = 0, outerOnly = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    const Bounds outer = randomBox();
    // Mostly towards a point of the outer box, reached at t = 1, which the
    // inner box (the outer one cut by a box about that point) holds.
    const dvec3 towards =
        glm::mix(outer.lo, outer.hi, 0.5 * dvec3(unit(rng), unit(rng), unit(rng)) + 0.5);
    const dvec3 half = 0.5 * glm::abs(dvec3(unit(rng), unit(rng), unit(rng)));
    const Bounds inner = outer.intersected(Bounds{towards - half, towards + 0.5 * half});
    dvec3 origin = 3.0 * dvec3(unit(rng), unit(rng), unit(rng));
    dvec3 dir = trial % 7 == 0 ? randomDirection(rng) : towards - origin;
    const int axis = trial % 3;
    switch (trial % 5) {
      case 1:  // from a plane of the inner box
        origin[axis] = inner.lo[axis];
        break;
      case 2:  // along an axis, in a plane of the inner box
        dir = dvec3(0.0);
        dir[(axis + 1) % 3] = unit(rng) < 0.0 ? -1.0 : 1.0;
        origin[axis] = inner.hi[axis];
        break;
      case 3:  // along an axis
        dir = dvec3(0.0);
        dir[axis] = unit(rng) < 0.0 ? -1.0 : 1.0;
        break;
      default:
        break;
    }
    const double t0 = unit(rng), t1 = t0 + 2.0 * std::abs(unit(rng));
    const Ray ray(origin, dir, t0, t1);
    const bool innerHit = !inner.empty() && inner.hitBy(ray);
    const bool outerHit = outer.hitBy(ray);
    if (innerHit) {
      ++innerHits;
      ASSERT_TRUE(outerHit) << "trial " << trial;
    } else if (outerHit) {
      ++outerOnly;
    }
  }
  // Both kinds of ray are common: the premise was tested, not assumed.
  EXPECT_GT(innerHits, 10000);
  EXPECT_GT(outerOnly, 2000);
}

// A difference whose first operand is an intersection (a lens: two balls
// and a cylinder less a ball) leaves the test of its box to that operand:
// the same spans, first boundaries and shadow answers as the tree whose
// first operand, moved by the identity, is an instance (which tests the
// box itself), on random rays and windows.
TEST(BooleanSpans, DifferenceOfAnIntersectionTestsItsBoxOnce) {
  SolidPtr cylinder =
      Primitive::create<Cylinder>(2.0, 2.0, 4.0)->transformed(Affine::translation(dvec3(0, 0, -2)));
  SolidPtr lens =
      intersectionOf({sphereAt(3.0, dvec3(0, 0, -2)), sphereAt(3.0, dvec3(0, 0, 2)), cylinder});
  SolidPtr hole = sphereAt(0.8, dvec3(0.3, 0, 0));
  SolidPtr part = differenceOf({lens, hole});
  SolidPtr reference = differenceOf({std::make_shared<Instance>(lens, Affine()), hole});
  expectSpansAgreeWithContainsOnRandomLines(*part);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  auto same = [](const SpanList& a, const SpanList& b) {
    if (a.size() != b.size()) return false;
    for (std::uint32_t i = 0; i < a.size(); ++i) {
      const Span &x = a[i], &y = b[i];
      if (x.in.t != y.in.t || x.out.t != y.out.t || x.in.primitive != y.in.primitive ||
          x.out.primitive != y.out.primitive || x.in.flip != y.in.flip || x.out.flip != y.out.flip)
        return false;
    }
    return true;
  };
  int met = 0;
  SpanList a, b;
  for (int i = 0; i < 20000; ++i) {
    const dvec3 origin = 4.0 * dvec3(unit(rng), unit(rng), unit(rng));
    const dvec3 towards = 2.2 * dvec3(unit(rng), unit(rng), 0.5 * unit(rng));
    const double t0 = 0.5 * unit(rng), t1 = t0 + 2.0 * std::abs(unit(rng));
    const Ray ray(origin, towards - origin, t0, t1);
    part->spans(ray, a);
    reference->spans(ray, b);
    ASSERT_TRUE(same(a, b)) << "spans, ray " << i;
    part->spansToFirstBoundary(ray, a);
    reference->spansToFirstBoundary(ray, b);
    ASSERT_TRUE(same(a, b)) << "first boundary, ray " << i;
    const bool meets = part->meetsWindow(ray, a);
    ASSERT_EQ(meets, reference->meetsWindow(ray, b)) << "shadow, ray " << i;
    met += meets;
  }
  EXPECT_GT(met, 2000);
}

// ---------------------------------------------------------------- contains

// contains() is the set operation on the operands, checked against the
// analytic predicates of the shapes at random points.
TEST(BooleanContains, MatchesAnalyticPredicates) {
  auto inBall = [](const dvec3& p, const dvec3& c, double r) {
    return glm::dot(p - c, p - c) <= r * r;
  };
  auto inCube = [](const dvec3& p, double lo, double hi) {
    return p.x >= lo && p.y >= lo && p.z >= lo && p.x <= hi && p.y <= hi && p.z <= hi;
  };
  dvec3 c1(0.0), c2(1.2, 0, 0), c3(0.5, 1, 0.3);
  SolidPtr u = unionOf({sphereAt(1.0, c1), sphereAt(0.8, c2), sphereAt(0.7, c3)});
  SolidPtr i = intersectionOf({sphereAt(1.3, c1), boxFromTo(dvec3(-1.0), dvec3(1.0))});
  SolidPtr d = differenceOf(
      {boxFromTo(dvec3(-1.0), dvec3(1.0)), sphereAt(0.8, c2), sphereAt(0.5, dvec3(-1, -1, -1))});
  std::mt19937_64 rng(17);
  int counts[3] = {0, 0, 0};
  for (int k = 0; k < 20000; ++k) {
    dvec3 p = randomPoint(rng, Bounds{dvec3(-2.0), dvec3(2.5)});
    bool inU = inBall(p, c1, 1.0) || inBall(p, c2, 0.8) || inBall(p, c3, 0.7);
    bool inI = inBall(p, c1, 1.3) && inCube(p, -1, 1);
    bool inD = inCube(p, -1, 1) && !inBall(p, c2, 0.8) && !inBall(p, dvec3(-1.0), 0.5);
    ASSERT_EQ(u->contains(p), inU);
    ASSERT_EQ(i->contains(p), inI);
    ASSERT_EQ(d->contains(p), inD);
    counts[0] += inU, counts[1] += inI, counts[2] += inD;
  }
  for (int c : counts) EXPECT_GT(c, 500);  // every set was actually sampled
}

// ------------------------------------------------------------------- spans

// A − A is empty, A ∪ A and A ∩ A are A (regularised: no zero-length leftovers).
TEST(BooleanSpans, IdempotenceAndSelfDifference) {
  SolidPtr s = sphereAt(1.0, dvec3(0.2, 0.1, 0));
  SolidPtr b = boxFromTo(dvec3(-1.0), dvec3(1.0, 2.0, 0.5));
  std::mt19937_64 rng(8);
  for (int k = 0; k < 500; ++k) {
    Ray line(randomPoint(rng, Bounds{dvec3(-1.5), dvec3(1.5)}), randomDirection(rng), -kInfinity,
             kInfinity);
    for (const SolidPtr& a : {s, b}) {
      SpanList direct = spansOf(*a, line);
      EXPECT_TRUE(spansOf(*differenceOf({a, a}), line).empty());
      for (const SolidPtr& same : {unionOf({a, a}), intersectionOf({a, a}), unionOf({a})}) {
        SpanList got = spansOf(*same, line);
        ASSERT_EQ(got.size(), direct.size());
        for (uint32_t j = 0; j < got.size(); ++j) {
          EXPECT_EQ(got[j].in.t, direct[j].in.t);
          EXPECT_EQ(got[j].out.t, direct[j].out.t);
        }
      }
    }
  }
}

// Box [0, 4]³ minus a ball of radius 1 about (2, 2, 2): along the line
// y = z = 2 the spans are [0, 1] and [3, 4] in x.
TEST(BooleanSpans, BoxMinusSphereAnalytic) {
  SolidPtr d = differenceOf({boxFromTo(dvec3(0.0), dvec3(4.0)), sphereAt(1.0, dvec3(2.0))});
  SpanList spans = spansOf(*d, Ray(dvec3(-1, 2, 2), dvec3(1, 0, 0)));
  ASSERT_EQ(spans.size(), 2u);
  EXPECT_NEAR(spans[0].in.t, 1.0, 1e-12);
  EXPECT_NEAR(spans[0].out.t, 2.0, 1e-12);
  EXPECT_NEAR(spans[1].in.t, 4.0, 1e-12);
  EXPECT_NEAR(spans[1].out.t, 5.0, 1e-12);
  // Off the ball's shadow, the box's full chord.
  SpanList clear = spansOf(*d, Ray(dvec3(-1, 0.5, 0.5), dvec3(1, 0, 0)));
  ASSERT_EQ(clear.size(), 1u);
  EXPECT_NEAR(clear[0].length(), 4.0, 1e-12);
}

// Union of two balls far apart: a line through both has two spans, one
// through a single ball skips the other (missed bounds) and has one.
TEST(BooleanSpans, UnionSkipsMissedOperands) {
  SolidPtr u = unionOf({sphereAt(1.0, dvec3(-3, 0, 0)), sphereAt(1.0, dvec3(3, 0, 0))});
  SpanList both = spansOf(*u, Ray(dvec3(-10, 0, 0), dvec3(1, 0, 0)));
  ASSERT_EQ(both.size(), 2u);
  EXPECT_NEAR(both[0].in.t, 6.0, 1e-12);
  EXPECT_NEAR(both[1].out.t, 14.0, 1e-12);
  SpanList one = spansOf(*u, Ray(dvec3(3, -10, 0), dvec3(0, 1, 0)));
  ASSERT_EQ(one.size(), 1u);
  EXPECT_NEAR(one[0].in.t, 9.0, 1e-12);
  SpanList none = spansOf(*u, Ray(dvec3(0, -10, 0), dvec3(0, 1, 0)));
  EXPECT_TRUE(none.empty());
}

// A difference whose first operand the ray misses is empty, even where the
// subtracted operands are hit; so is one whose first operand's box is hit
// but not the operand itself.
TEST(BooleanSpans, DifferenceWithMissedFirstOperandIsEmpty) {
  SolidPtr far = differenceOf({boxFromTo(dvec3(10.0), dvec3(11.0)), sphereAt(1.0, dvec3(0.0))});
  EXPECT_TRUE(spansOf(*far, Ray(dvec3(-5, 0, 0), dvec3(1, 0, 0))).empty());
  SolidPtr corner = differenceOf({sphereAt(1.0, dvec3(0.0)), boxFromTo(dvec3(0.0), dvec3(3.0))});
  // Through the corner of the ball's box at (0.95, 0.95, z): outside the ball.
  EXPECT_TRUE(spansOf(*corner, Ray(dvec3(0.95, 0.95, -5), dvec3(0, 0, 1))).empty());
  // A subtracted operand that is missed removes nothing.
  SpanList kept = spansOf(*corner, Ray(dvec3(-0.5, -0.5, -5), dvec3(0, 0, 1)));
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_NEAR(kept[0].length(), 2.0 * std::sqrt(0.5), 1e-12);
}

TEST(BooleanSpans, AgreeWithContainsOnRandomLines) {
  SolidPtr box = boxFromTo(dvec3(0.0), dvec3(4.0));
  std::vector<std::pair<const char*, SolidPtr>> trees = {
      {"box minus inner sphere", differenceOf({box, sphereAt(1.5, dvec3(2.0))})},
      {"box minus sphere on a face", differenceOf({box, sphereAt(1.5, dvec3(4.5, 2, 2))})},
      {"union of three spheres",
       unionOf({sphereAt(1.0, dvec3(0.0)), sphereAt(0.8, dvec3(1.2, 0, 0)),
                sphereAt(0.7, dvec3(0.5, 1, 0.3))})},
      {"sphere and box",
       intersectionOf({sphereAt(1.3, dvec3(0.0)), boxFromTo(dvec3(-1.0), dvec3(1.0))})},
      {"box minus half-space",
       differenceOf({box, Primitive::create<HalfSpace>(dvec3(1, 1, 1), 5.0)})},
      {"half-space minus sphere", differenceOf({Primitive::create<HalfSpace>(dvec3(0, 1, 2), 0.5),
                                                sphereAt(2.0, dvec3(0.0))})},
      {"n-ary difference",
       differenceOf({box, sphereAt(1.0, dvec3(0.0)), cylinderAt(0.5, 6.0, dvec3(2, 2, -1)),
                     sphereAt(1.0, dvec3(4, 4, 4))})},
      {"nested tree",
       unionOf({differenceOf({box, cylinderAt(1.0, 6.0, dvec3(2, 2, -1))}),
                intersectionOf({sphereAt(1.5, dvec3(2, 2, 5)), sphereAt(1.5, dvec3(2, 2, 6))}),
                Primitive::create<Cylinder>(0.0, 1.0, 2.0)})},
      {"box minus (shell)",
       differenceOf({boxFromTo(dvec3(-3.0), dvec3(3.0)),
                     differenceOf({sphereAt(2.0, dvec3(0.0)), sphereAt(1.0, dvec3(0.0))})})},
  };
  for (const auto& [name, tree] : trees) {
    SCOPED_TRACE(name);
    expectSpansAgreeWithContainsOnRandomLines(*tree);
    expectBoundariesOrientedOnRandomLines(*tree);
    expectWindowedSpansAgreeWithLine(*tree);
  }
}

// Box (0..4, 0..4, 0..2) minus a cylinder of radius 1 about the vertical
// line x = y = 2: along y = 2, z = 1 the material is x in [0, 1] and [3, 4];
// the hole's walls come from the cylinder with flip set, and the negated
// cylinder normal there points into the hole, towards its axis.
TEST(BooleanSpans, HoleFacesAreFlipped) {
  SolidPtr box = boxFromTo(dvec3(0.0), dvec3(4, 4, 2));
  SolidPtr hole = cylinderAt(1.0, 4.0, dvec3(2, 2, -1));
  SolidPtr d = differenceOf({box, hole});
  const Primitive* cylinder = asPrimitive(d->children()[1]);
  ASSERT_NE(cylinder, nullptr);
  Ray ray(dvec3(-1, 2, 1), dvec3(1, 0, 0));
  SpanList spans = spansOf(*d, ray);
  ASSERT_EQ(spans.size(), 2u);
  EXPECT_NEAR(spans[0].out.t, 2.0, 1e-12);
  EXPECT_NEAR(spans[1].in.t, 4.0, 1e-12);
  EXPECT_FALSE(spans[0].in.flip);
  EXPECT_EQ(spans[0].in.primitive, asPrimitive(d->children()[0]));
  for (const Boundary* wall : {&spans[0].out, &spans[1].in}) {
    EXPECT_EQ(wall->primitive, cylinder);
    EXPECT_TRUE(wall->flip);
    dvec3 p = ray.at(wall->t);
    dvec3 intoHole = -cylinder->normal(p, wall->face);
    dvec3 towardsAxis = glm::normalize(dvec3(2, 2, p.z) - p);
    EXPECT_NEAR(glm::dot(intoHole, towardsAxis), 1.0, 1e-12);
  }
  // The same at random points of the wall, hit from inside the hole.
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    // Nearly horizontal, so the ray meets the wall within the box's height.
    double phi = 3.2 * u(rng);
    dvec3 dir = glm::normalize(dvec3(std::cos(phi), std::sin(phi), 0.3 * u(rng)));
    SpanList s = spansOf(*d, Ray(dvec3(2, 2, 1), dir));
    // Material behind the ray (t < 0) may be reported too; take the first ahead.
    const Span* ahead = nullptr;
    for (const Span& span : s)
      if (!ahead && span.in.t >= 0.0) ahead = &span;
    ASSERT_NE(ahead, nullptr);
    ASSERT_EQ(ahead->in.primitive, cylinder);
    ASSERT_TRUE(ahead->in.flip);
    dvec3 p = dvec3(2, 2, 1) + ahead->in.t * dir;
    EXPECT_NEAR(glm::length(dvec3(p.x - 2, p.y - 2, 0)), 1.0, 1e-9);
    dvec3 intoHole = -cylinder->normal(p, ahead->in.face);
    EXPECT_GT(glm::dot(intoHole, dvec3(2, 2, p.z) - p), 0.0);
  }
}

// A − (B − C): C's faces are subtracted twice and so are not flipped; B's
// once and are. Box [-3, 3]³ minus a shell between radii 1 and 2.
TEST(BooleanSpans, NestedDifferenceFlipsTwiceBack) {
  SolidPtr box = boxFromTo(dvec3(-3.0), dvec3(3.0));
  SolidPtr outer = sphereAt(2.0, dvec3(0.0)), inner = sphereAt(1.0, dvec3(0.0));
  SolidPtr d = differenceOf({box, differenceOf({outer, inner})});
  const Primitive* pb = asPrimitive(d->children()[0]);
  const Primitive* po = asPrimitive(d->children()[1]->children()[0]);
  const Primitive* pi = asPrimitive(d->children()[1]->children()[1]);
  SpanList spans = spansOf(*d, Ray(dvec3(-5, 0, 0), dvec3(1, 0, 0)));
  ASSERT_EQ(spans.size(), 3u);
  double t[6] = {2, 3, 4, 6, 7, 8};
  const Primitive* who[6] = {pb, po, pi, pi, po, pb};
  bool flip[6] = {false, true, false, false, true, false};
  for (int k = 0; k < 6; ++k) {
    const Boundary& b = k % 2 ? spans[k / 2].out : spans[k / 2].in;
    EXPECT_NEAR(b.t, t[k], 1e-12) << k;
    EXPECT_EQ(b.primitive, who[k]) << k;
    EXPECT_EQ(b.flip, flip[k]) << k;
  }
}

// Intersection boundaries come from the operand whose surface bounds the
// result: the unit-ish ball ∩ cube [-1, 1]³ along x through the centre is
// bounded by the cube faces, along the diagonal by the sphere.
TEST(BooleanSpans, IntersectionTakesInnermostSurfaces) {
  SolidPtr s = sphereAt(1.3, dvec3(0.0)), b = boxFromTo(dvec3(-1.0), dvec3(1.0));
  SolidPtr i = intersectionOf({s, b});
  SpanList axis = spansOf(*i, Ray(dvec3(-5, 0, 0), dvec3(1, 0, 0)));
  ASSERT_EQ(axis.size(), 1u);
  EXPECT_EQ(axis[0].in.primitive, asPrimitive(b));
  EXPECT_EQ(axis[0].out.primitive, asPrimitive(b));
  EXPECT_NEAR(axis[0].length(), 2.0, 1e-12);
  dvec3 diag = glm::normalize(dvec3(1, 1, 1));
  SpanList corner = spansOf(*i, Ray(-5.0 * diag, diag));
  ASSERT_EQ(corner.size(), 1u);
  EXPECT_EQ(corner[0].in.primitive, asPrimitive(s));
  EXPECT_NEAR(corner[0].length(), 2.6, 1e-12);
}

// ------------------------------------------------------------------- trees

void collectPrimitives(const SolidPtr& s, std::vector<const Primitive*>& out) {
  if (const Primitive* p = asPrimitive(s)) {
    out.push_back(p);
    return;
  }
  for (const SolidPtr& c : s->children()) collectPrimitives(c, out);
}

std::vector<std::string> kindsInOrder(const SolidPtr& s) {
  std::vector<std::string> out{s->kind()};
  for (const SolidPtr& c : s->children())
    for (const std::string& k : kindsInOrder(c)) out.push_back(k);
  return out;
}

// withDefaultMaterial fills in only the primitives that have no material,
// and leaves the original tree untouched (solids are immutable values).
TEST(BooleanTree, WithDefaultMaterialOnlyFillsMissing) {
  auto red = std::make_shared<Material>();
  red->color = dvec3(1, 0, 0);
  auto grey = std::make_shared<Material>();
  grey->color = dvec3(0.5);
  SolidPtr sphere = Primitive::create<Sphere>(1.0)->withMaterial(red);
  SolidPtr tree = differenceOf({unionOf({Primitive::create<Box>(dvec3(1.0)), sphere}),
                                Primitive::create<Cylinder>(0.2, 0.2, 3.0)});
  SolidPtr painted = tree->withDefaultMaterial(grey);
  std::vector<const Primitive*> before, after;
  collectPrimitives(tree, before);
  collectPrimitives(painted, after);
  ASSERT_EQ(after.size(), 3u);
  EXPECT_EQ(after[0]->kind(), "box");
  EXPECT_EQ(after[0]->material(), grey);
  EXPECT_EQ(after[1]->kind(), "sphere");
  EXPECT_EQ(after[1]->material(), red);
  EXPECT_EQ(after[2]->material(), grey);
  EXPECT_EQ(before[0]->material(), nullptr);
  EXPECT_EQ(before[2]->material(), nullptr);
  EXPECT_EQ(kindsInOrder(painted), kindsInOrder(tree));
  // A second default does not override the first.
  auto blue = std::make_shared<Material>();
  std::vector<const Primitive*> again;
  collectPrimitives(painted->withDefaultMaterial(blue), again);
  for (size_t k = 0; k < again.size(); ++k) EXPECT_EQ(again[k]->material(), after[k]->material());
}

// mapPrimitives visits each primitive once, keeps the tree's shape, and
// the result is the tree of the mapped leaves.
TEST(BooleanTree, MapPrimitivesRebuildsTree) {
  SolidPtr tree =
      unionOf({differenceOf({boxFromTo(dvec3(0.0), dvec3(2.0)), sphereAt(0.5, dvec3(1.0))}),
               sphereAt(1.0, dvec3(5, 0, 0))});
  int calls = 0;
  SolidPtr moved = tree->mapPrimitives([&](const Primitive& p) {
    ++calls;
    return p.withFrame(p.frame().then(Affine::translation(dvec3(0, 0, 10))));
  });
  EXPECT_EQ(calls, 3);
  EXPECT_EQ(kindsInOrder(moved), kindsInOrder(tree));
  for (dvec3 p : {dvec3(0.2, 0.2, 0.2), dvec3(1.0), dvec3(5, 0, 0.5), dvec3(1.9, 1.9, 1.9)}) {
    EXPECT_EQ(moved->contains(p + dvec3(0, 0, 10)), tree->contains(p));
  }
  EXPECT_FALSE(moved->contains(dvec3(1.0, 1.0, 11.0)));  // the hole moved too
  EXPECT_TRUE(moved->contains(dvec3(0.2, 0.2, 10.2)));
}

TEST(BooleanTree, TreeStatsCountsNodes) {
  TreeStats leaf = treeStats(*Primitive::create<Sphere>(1.0));
  EXPECT_EQ(leaf.primitives, 1);
  EXPECT_EQ(leaf.booleans, 0);
  SolidPtr tree =
      unionOf({differenceOf({boxFromTo(dvec3(0.0), dvec3(2.0)), sphereAt(0.5, dvec3(1.0)),
                             cylinderAt(0.2, 3, dvec3(1, 1, -0.5))}),
               intersectionOf({sphereAt(1.0, dvec3(5, 0, 0)), sphereAt(1.0, dvec3(5.5, 0, 0))}),
               Primitive::create<Sphere>(2.0)});
  TreeStats stats = treeStats(*tree);
  EXPECT_EQ(stats.primitives, 6);
  EXPECT_EQ(stats.booleans, 3);
}

TEST(BooleanTree, TreeStatsCountsASharedSubtreeOnceAsStored) {
  // Moving a boolean makes an instance that shares its tree: three uses of
  // a union of two primitives are six primitives in use, two stored.
  SolidPtr pair = unionOf({sphereAt(1.0, dvec3(0.0)), sphereAt(1.0, dvec3(1.5, 0, 0))});
  SolidPtr three = unionOf({pair, pair->transformed(Affine::translation({0, 5, 0})),
                            pair->transformed(Affine::translation({0, 10, 0}))});
  TreeStats stats = treeStats(*three);
  EXPECT_EQ(stats.primitives, 6u);
  EXPECT_EQ(stats.storedPrimitives, 2u);
  EXPECT_EQ(treeStats(*pair).storedPrimitives, treeStats(*pair).primitives);
}

TEST(BooleanTree, KindsAndOperands) {
  SolidPtr a = Primitive::create<Sphere>(1.0), b = Primitive::create<Box>(dvec3(1.0));
  EXPECT_EQ(unionOf({a, b})->kind(), "union");
  EXPECT_EQ(intersectionOf({a, b})->kind(), "intersection");
  EXPECT_EQ(differenceOf({a, b})->kind(), "difference");
  SolidPtr u = unionOf({a, b});
  ASSERT_EQ(u->children().size(), 2u);
  EXPECT_EQ(u->children()[0], a);
  EXPECT_EQ(u->children()[1], b);
}

// s = s - hole in a loop: each node extends the last one's operand list
// (engine/operand_list.h). Every node answers as the node made at once
// from its list would: its operands, counts, depth and box; the chain's
// lists share storage, copied only as it fills (so O(n), not n²/2
// operands written); a branch off a node of the chain leaves that node,
// and the branch taken before it, as they were.
TEST(BooleanTree, AChainBuiltOneOperandAtATimeSharesItsList) {
  const SolidPtr plate = boxFromTo(dvec3(0.0), dvec3(100, 100, 1));
  std::vector<SolidPtr> holes;
  for (int i = 0; i < 1000; ++i)
    holes.push_back(cylinderAt(0.2, 1.0, dvec3(1 + i % 40 * 2.4, 1 + i / 40 * 3.6, 0)));
  std::vector<SolidPtr> chain{plate};
  for (const SolidPtr& hole : holes) chain.push_back(differenceOf({chain.back(), hole}));
  std::vector<SolidPtr> list{plate};
  std::set<const SolidPtr*> storages;
  for (std::size_t k = 1; k < chain.size(); k += 37) {
    const Solid& node = *chain[k];
    list.assign(chain.begin(), chain.begin() + 1);
    list.insert(list.end(), holes.begin(), holes.begin() + k);
    const SolidPtr atOnce = differenceOf(list);
    ASSERT_EQ(node.children().size(), k + 1);
    EXPECT_TRUE(
        std::equal(node.children().begin(), node.children().end(), atOnce->children().begin()));
    EXPECT_EQ(node.primitiveCount(), atOnce->primitiveCount());
    EXPECT_EQ(node.booleanCount(), atOnce->booleanCount());
    EXPECT_EQ(node.depth(), atOnce->depth());
    EXPECT_EQ(node.bounds().lo, atOnce->bounds().lo);
    EXPECT_EQ(node.bounds().hi, atOnce->bounds().hi);
    EXPECT_EQ(node.firstBoundaryCutsShort(), atOnce->firstBoundaryCutsShort());
    EXPECT_EQ(node.insideBeyondWindow(), atOnce->insideBeyondWindow());
    EXPECT_EQ(node.hasInstances(), atOnce->hasInstances());
  }
  for (const SolidPtr& node : chain) storages.insert(node->children().data());
  // The plate's (none), the first node's, then each with room for twice
  // the operands of the last: 2, 8, 18, 38, ..., 1278.
  EXPECT_LE(storages.size(), 10u);
  // A branch off the middle: the chain's nodes keep their operands.
  const SolidPtr middle = chain[500], extra = sphereAt(1.0, dvec3(50, 50, 0.5));
  const SolidPtr branch = differenceOf({middle, extra});
  EXPECT_EQ(branch->children().back(), extra);
  EXPECT_EQ(branch->children().size(), 502u);
  EXPECT_EQ(chain[501]->children()[501], holes[500]);
  EXPECT_EQ(middle->children().size(), 501u);
  EXPECT_FALSE(branch->contains(dvec3(50, 50, 0.5)));
  EXPECT_TRUE(chain[501]->contains(dvec3(50, 50, 0.5)));
  // Unions and intersections chain as well; a union of a difference (whose
  // first boundary cuts short) and balls answers as the union made at once.
  std::vector<SolidPtr> parts{chain[3]};
  SolidPtr row = chain[3];
  for (int i = 1; i < 100; ++i) {
    parts.push_back(sphereAt(0.5, dvec3(i, 0, 5)));
    row = unionOf({row, parts.back()});
  }
  const SolidPtr rowAtOnce = unionOf(parts);
  EXPECT_EQ(row->children().size(), 100u);
  EXPECT_EQ(row->bounds().hi.x, 100.0);
  EXPECT_EQ(row->bounds().hi.z, 5.5);
  EXPECT_TRUE(row->contains(dvec3(42, 0, 5.4)));
  EXPECT_EQ(row->primitiveCount(), rowAtOnce->primitiveCount());
  EXPECT_EQ(row->booleanCount(), rowAtOnce->booleanCount());
  EXPECT_EQ(row->depth(), rowAtOnce->depth());
  EXPECT_EQ(row->firstBoundaryCutsShort(), rowAtOnce->firstBoundaryCutsShort());
  EXPECT_EQ(row->insideBeyondWindow(), rowAtOnce->insideBeyondWindow());
}

// Threads that extend the same node at once: one takes the room after its
// list, the others copy it; each gets its own operand, and the node keeps
// its list.
TEST(BooleanTree, NodesExtendingOneNodeOnManyThreadsKeepTheirOperands) {
  SolidPtr base = boxFromTo(dvec3(0.0), dvec3(10.0));
  for (int i = 0; i < 20; ++i) base = differenceOf({base, sphereAt(0.1, dvec3(i * 0.5, 0, 0))});
  constexpr int kThreads = 8, kRounds = 200;
  std::vector<std::vector<SolidPtr>> made(kThreads);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      for (int r = 0; r < kRounds; ++r) {
        const SolidPtr hole = sphereAt(0.1, dvec3(t, r * 0.01, 5));
        made[t].push_back(differenceOf({base, hole}));
        EXPECT_EQ(made[t].back()->children().back(), hole);
      }
    });
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(base->children().size(), 21u);
  for (int t = 0; t < kThreads; ++t)
    for (const SolidPtr& node : made[t]) {
      ASSERT_EQ(node->children().size(), 22u);
      EXPECT_TRUE(
          std::equal(base->children().begin(), base->children().end(), node->children().begin()));
    }
}

TEST(BooleanTree, RejectsEmptyOrNullOperands) {
  EXPECT_THROW(unionOf({}), std::invalid_argument);
  EXPECT_THROW(intersectionOf({}), std::invalid_argument);
  EXPECT_THROW(differenceOf({}), std::invalid_argument);
  SolidPtr a = Primitive::create<Sphere>(1.0);
  EXPECT_THROW(unionOf({a, nullptr}), std::invalid_argument);
  EXPECT_THROW(differenceOf({nullptr, a}), std::invalid_argument);
}

// Faces that coincide in the model must still coincide once rotated, when
// each primitive computes its t in its own frame and rounds differently.
TEST(BooleanSpans, CoincidentFacesStayRegularUnderRotation) {
  Affine turn = Affine::rotation(0.3, glm::normalize(dvec3(1, 1.3, 1.7)));
  auto a = Primitive::create<Box>(dvec3(0.3))->transformed(Affine::translation({0.1, 0.7, 0.2}));
  auto b = Primitive::create<Box>(dvec3(0.3))->transformed(Affine::translation({0.4, 0.7, 0.2}));
  SolidPtr touching = intersectionOf({a, b})->transformed(turn);
  // A notch flush with the top face: the top must have no sliver left.
  auto block = Primitive::create<Box>(dvec3(10));
  auto notch = Primitive::create<Box>(dvec3(5))->transformed(Affine::translation({0, 0, 5}));
  SolidPtr notched = differenceOf({block, notch})->transformed(turn);
  std::mt19937_64 rng(7);
  int slivers = 0;
  for (int i = 0; i < 20000; ++i) {
    // Lines through the shared face x = 0.4 of the touching boxes.
    dvec3 p =
        turn.pointToWorld(dvec3(0.4, 0.7 + 0.3 * (i % 97) / 97.0, 0.2 + 0.3 * (i % 89) / 89.0));
    dvec3 dir = test::randomDirection(rng);
    slivers += !spansOf(*touching, Ray(p - 5.0 * dir, dir, -kInfinity, kInfinity)).empty();
    // Lines through the plane of the notch's side walls, x = 5 above z = 5.
    dvec3 q =
        turn.pointToWorld(dvec3(5.0, 0.5 + 9.0 * (i % 83) / 83.0, 5.0 + 5.0 * (i % 79) / 79.0));
    dvec3 d = test::randomDirection(rng);
    SpanList spans = spansOf(*notched, Ray(q - 20.0 * d, d, -kInfinity, kInfinity));
    for (const Span& s : spans) slivers += s.length() < 1e-9;
  }
  EXPECT_EQ(slivers, 0);
}

}  // namespace
}  // namespace csgray::detail

namespace csgray::detail {
namespace {

// A plate drilled in a loop, s = s - hole, 400 times in a row: a ray along
// the row meets every hole (the first ones are subtracted one by one, the
// rest united and subtracted at once). Its spans are the 401 pieces of
// plate between the holes, exactly; spans agree with contains() on random
// lines, and the volume is the plate's less the holes'.
TEST(BooleanSpans, AHoleDrilledRowLeavesThePiecesBetween) {
  const int n = 400;
  SolidPtr plate = Primitive::create<Box>(dvec3(n, 1.0, 1.0));
  for (int i = 0; i < n; ++i)
    plate = std::make_shared<Boolean>(
        Boolean::Op::Difference,
        std::vector<SolidPtr>{plate, Primitive::create<Cylinder>(0.25, 0.25, 3.0)
                                         ->transformed(Affine::translation({i + 0.5, 0.5, -1.0}))});
  SpanList along = spansOf(*plate, Ray(dvec3(-1.0, 0.5, 0.5), dvec3(1, 0, 0)));
  ASSERT_EQ(along.size(), std::uint32_t(n + 1));
  for (int i = 0; i <= n; ++i) {
    EXPECT_NEAR(along[i].in.t, i == 0 ? 1.0 : i + 0.75, 1e-12) << i;
    EXPECT_NEAR(along[i].out.t, i == n ? n + 1.0 : i + 1.25, 1e-12) << i;
  }
  expectSpansAgreeWithContainsOnRandomLines(*plate, 1000, 3);
  const double pi = std::acos(-1.0);
  // (997 columns: not on the holes' rims, where the grid's rays would graze.)
  EXPECT_NEAR(test::gridVolume(*plate, plate->bounds(), 997), n * (1.0 - pi * 0.0625), 0.02 * n);
}

}  // namespace
}  // namespace csgray::detail
