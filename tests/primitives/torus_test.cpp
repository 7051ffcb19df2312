// The torus and its quartic solver: roots of known polynomials, analytic
// hits, boundaries on the surface, agreement with contains(), volumes,
// grazing and near-tangent rays (no lost or invented spans), far-away tori,
// horn and spindle tori, the script function, and an edge-on rendering whose
// every pixel is checked against the silhouette computed independently.
#include "primitives/torus.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/boolean.h"
#include "engine/solvers/quartic.h"
#include "primitives/sphere.h"
#include "raytrace/renderer.h"
#include "scene/camera.h"
#include "script/script.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

using test::expectSpansAgreeWithContains;
using test::expectSpansAgreeWithContainsOnRandomLines;
using test::randomDirection;
using test::scriptError;
using test::spansOf;

constexpr double kPi = std::numbers::pi;

std::shared_ptr<Torus> torus(double R, double r) { return Primitive::create<Torus>(R, r); }

// Distance of an object-space point from the torus surface, along the
// meridian: |distance from the core circle − r|.
double surfaceDistance(const dvec3& p, double R, double r) {
  return std::abs(std::hypot(std::hypot(p.x, p.y) - R, p.z) - r);
}

// ------------------------------------------------------------------ solver

std::vector<double> sublevelBoundaries(const std::vector<double>& c, double lo, double hi) {
  double roots[4];
  int n = polynomialSublevelBoundaries(c.data(), int(c.size()) - 1, lo, hi, roots);
  return std::vector<double>(roots, roots + n);
}

// (t − 1)(t − 2)(t − 3)(t − 4) = t⁴ − 10t³ + 35t² − 50t + 24.
TEST(QuarticSolver, FourSimpleRoots) {
  double roots[4];
  ASSERT_EQ(quarticRoots(-10, 35, -50, 24, -100, 100, roots), 4);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(roots[i], i + 1.0, 1e-13);
  // Only the ones inside the interval.
  ASSERT_EQ(quarticRoots(-10, 35, -50, 24, 1.5, 3.5, roots), 2);
  EXPECT_NEAR(roots[0], 2.0, 1e-13);
  EXPECT_NEAR(roots[1], 3.0, 1e-13);
}

// Roots 1e-6 apart next to others: t⁴ − 2t² + ... built from its roots.
TEST(QuarticSolver, ClusteredRoots) {
  std::vector<double> want = {-2.0, 1.0, 1.0 + 1e-6, 5.0};
  // Expand (t − a)(t − b)(t − c)(t − d).
  std::vector<double> c = {1.0};
  for (double root : want) {
    std::vector<double> next(c.size() + 1, 0.0);
    for (size_t i = 0; i < c.size(); ++i) {
      next[i + 1] += c[i];
      next[i] -= root * c[i];
    }
    c = next;
  }
  std::vector<double> got = sublevelBoundaries(c, -10, 10);
  ASSERT_EQ(got.size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(got[i], want[i], 1e-9) << i;
  EXPECT_GT(got[2], got[1]);
}

// Lower degrees and the boundaries of {p <= 0}: a cubic, a quadratic that
// never reaches zero, and a double root touched from above.
TEST(QuarticSolver, CubicQuadraticAndTangency) {
  // (t + 1)(t − 0.5)(t − 3) = t³ − 2.5t² − 2t + 1.5
  std::vector<double> got = sublevelBoundaries({1.5, -2.0, -2.5, 1.0}, -5, 5);
  ASSERT_EQ(got.size(), 3u);
  EXPECT_NEAR(got[0], -1.0, 1e-14);
  EXPECT_NEAR(got[1], 0.5, 1e-14);
  EXPECT_NEAR(got[2], 3.0, 1e-14);
  EXPECT_TRUE(sublevelBoundaries({1.0, 0.0, 1.0}, -5, 5).empty());  // t² + 1
  // (t − 1)²(t² + 1) touches 0 at t = 1: nothing, or a point (two roots at 1).
  got = sublevelBoundaries({1.0, -2.0, 2.0, -2.0, 1.0}, -5, 5);
  ASSERT_TRUE(got.empty() || got.size() == 2u);
  for (double t : got) EXPECT_NEAR(t, 1.0, 1e-7);
  // (t − 1)²(t² + 1) − 1e-12 dips below: two roots 1e-6 from 1.
  got = sublevelBoundaries({1.0 - 1e-12, -2.0, 2.0, -2.0, 1.0}, -5, 5);
  ASSERT_EQ(got.size(), 2u);
  EXPECT_NEAR(got[0], 1.0 - std::sqrt(0.5e-12), 1e-9);
  EXPECT_NEAR(got[1], 1.0 + std::sqrt(0.5e-12), 1e-9);
}

// ------------------------------------------------------------ analytic hits

// Along x through the centre: in the tube for R − r <= |x| <= R + r.
TEST(TorusPrimitive, RayAlongXThroughCentre) {
  auto t = torus(3.0, 1.0);
  SpanList spans = spansOf(*t, Ray(dvec3(-10, 0, 0), dvec3(1, 0, 0)));
  ASSERT_EQ(spans.size(), 2u);
  EXPECT_NEAR(spans[0].in.t, 10 - 4, 1e-12);
  EXPECT_NEAR(spans[0].out.t, 10 - 2, 1e-12);
  EXPECT_NEAR(spans[1].in.t, 10 + 2, 1e-12);
  EXPECT_NEAR(spans[1].out.t, 10 + 4, 1e-12);
  EXPECT_EQ(spans[0].in.primitive, t.get());
  // A direction of length 2 halves t; along y the same.
  spans = spansOf(*t, Ray(dvec3(0, 10, 0), dvec3(0, -2, 0)));
  ASSERT_EQ(spans.size(), 2u);
  EXPECT_NEAR(spans[0].in.t, 3.0, 1e-12);
  EXPECT_NEAR(spans[0].out.t, 4.0, 1e-12);
  EXPECT_NEAR(spans[1].in.t, 6.0, 1e-12);
  EXPECT_NEAR(spans[1].out.t, 7.0, 1e-12);
}

// Along z through the core circle: in the tube for |z| <= r.
TEST(TorusPrimitive, RayAlongZThroughCoreCircle) {
  auto t = torus(3.0, 1.0);
  SpanList spans = spansOf(*t, Ray(dvec3(3, 0, -10), dvec3(0, 0, 1)));
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_NEAR(spans[0].in.t, 9.0, 1e-12);
  EXPECT_NEAR(spans[0].out.t, 11.0, 1e-12);
  // Down the axis: through the hole, nothing.
  EXPECT_TRUE(spansOf(*t, Ray(dvec3(0, 0, -10), dvec3(0, 0, 1))).empty());
  // Diagonally through the core circle at (0, 3, 0), in the meridian
  // plane x = 0: a chord of the tube's circle, length 2r.
  spans = spansOf(*t, Ray(dvec3(0, 3, 0) - 10.0 * glm::normalize(dvec3(0, 1, 1)),
                          glm::normalize(dvec3(0, 1, 1))));
  ASSERT_GE(spans.size(), 1u);
  EXPECT_NEAR(spans[0].in.t, 9.0, 1e-12);
  EXPECT_NEAR(spans[0].out.t, 11.0, 1e-12);
}

// A line through the centre in a meridian plane at angle β to the xy
// plane: s² − 2R·cos β·s + R² − r² = 0 on each side.
TEST(TorusPrimitive, RayThroughCentreAtAnAngle) {
  double R = 3.0, r = 2.0;
  auto t = torus(R, r);
  dvec3 dir = glm::normalize(dvec3(1, 1, 1));
  double sinB = 1.0 / std::sqrt(3.0), cosB = std::sqrt(2.0 / 3.0);
  double mid = R * cosB, half = std::sqrt(r * r - R * R * sinB * sinB);
  SpanList spans = spansOf(*t, Ray(-20.0 * dir, dir));
  ASSERT_EQ(spans.size(), 2u);
  EXPECT_NEAR(spans[0].in.t, 20 - mid - half, 1e-12);
  EXPECT_NEAR(spans[0].out.t, 20 - mid + half, 1e-12);
  EXPECT_NEAR(spans[1].in.t, 20 + mid - half, 1e-12);
  EXPECT_NEAR(spans[1].out.t, 20 + mid + half, 1e-12);
}

// Lines along y at x = δ in the plane z = z0: the tube's section there is
// the annulus R − q <= ρ <= R + q, q = √(r² − z0²), which the line crosses
// at y = ±√(ρ² − δ²). Near the axis the tube's factor (ρ − R)² + z² − r²
// is concave along the line (for ρ³ < R·δ²), so these take both kinds of
// piece the solver splits lines into; the spindle's inner boundaries (at
// ρ = R − q = 0.05) lie in the concave piece when δ = 0.03.
TEST(TorusPrimitive, LinesPassingNearTheAxis) {
  struct Line {
    double R, r, z0, delta;
  };
  const double nearPole = std::sqrt(1.0 - 0.45 * 0.45);
  for (Line c :
       {Line{3, 1, 0, 0.3}, Line{3, 1, 0, 1e-3}, Line{3, 1, 0.5, 1e-6}, Line{3, 1, 0, 1e-9},
        Line{3, 1, 0.9, 1e-12}, Line{0.5, 1, nearPole, 0.03}, Line{0.5, 1, nearPole, 1e-7}}) {
    SCOPED_TRACE(testing::Message() << "R " << c.R << ", z0 " << c.z0 << ", delta " << c.delta);
    auto t = torus(c.R, c.r);
    const double q = std::sqrt(c.r * c.r - c.z0 * c.z0);
    const double inner = std::sqrt((c.R - q) * (c.R - q) - c.delta * c.delta);
    const double outer = std::sqrt((c.R + q) * (c.R + q) - c.delta * c.delta);
    SpanList spans = spansOf(*t, Ray(dvec3(c.delta, -10, c.z0), dvec3(0, 1, 0)));
    ASSERT_EQ(spans.size(), 2u);
    EXPECT_NEAR(spans[0].in.t, 10 - outer, 1e-12);
    EXPECT_NEAR(spans[0].out.t, 10 - inner, 1e-12);
    EXPECT_NEAR(spans[1].in.t, 10 + inner, 1e-12);
    EXPECT_NEAR(spans[1].out.t, 10 + outer, 1e-12);
  }
}

TEST(TorusPrimitive, ContainsBoundsAndNormals) {
  auto t = torus(3.0, 1.0);
  EXPECT_TRUE(t->contains(dvec3(3, 0, 0)));
  EXPECT_TRUE(t->contains(dvec3(0, -3.9, 0)));
  EXPECT_TRUE(t->contains(dvec3(2, 0, 0)));  // on the inner equator
  EXPECT_FALSE(t->contains(dvec3(0, 0, 0)));
  EXPECT_FALSE(t->contains(dvec3(1.9, 0, 0)));
  EXPECT_FALSE(t->contains(dvec3(3, 0, 1.01)));
  test::expectVecNear(t->bounds().lo, dvec3(-4, -4, -1), 0.0);
  test::expectVecNear(t->bounds().hi, dvec3(4, 4, 1), 0.0);
  test::expectVecNear(t->normal(dvec3(4, 0, 0), 0), dvec3(1, 0, 0), 1e-15);
  test::expectVecNear(t->normal(dvec3(0, 2, 0), 0), dvec3(0, -1, 0), 1e-15);
  test::expectVecNear(t->normal(dvec3(0, 3, 1), 0), dvec3(0, 0, 1), 1e-15);
  dvec3 p(3 + std::sqrt(0.5), 0, -std::sqrt(0.5));
  test::expectVecNear(t->normal(p, 0), glm::normalize(dvec3(1, 0, -1)), 1e-15);
  EXPECT_EQ(t->kind(), "torus");
}

TEST(TorusPrimitive, RefusesBadParameters) {
  EXPECT_THROW(torus(3.0, 0.0), std::invalid_argument);
  EXPECT_THROW(torus(3.0, -1.0), std::invalid_argument);
  EXPECT_THROW(torus(-1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(torus(std::nan(""), 1.0), std::invalid_argument);
  EXPECT_THROW(torus(kInfinity, 1.0), std::invalid_argument);
  EXPECT_NO_THROW(torus(0.0, 1.0));  // a ball
}

// ------------------------------------------------------- random lines

// Tori of every kind, as they are and moved.
std::vector<std::pair<std::string, SolidPtr>> assortedTori() {
  Affine skew = Affine::rotation(0.7, glm::normalize(dvec3(1, 2, 3)))
                    .then(Affine::translation(dvec3(0.5, -2, 1)));
  return {
      {"ring", torus(3.0, 1.0)},
      {"thin ring", torus(10.0, 0.1)},
      {"fat ring", torus(1.0, 0.9)},
      {"horn", torus(1.0, 1.0)},
      {"spindle", torus(0.5, 1.0)},
      {"nearly a ball", torus(1e-4, 1.0)},
      {"ball", torus(0.0, 1.0)},
      {"moved ring", torus(3.0, 1.0)->transformed(skew)},
      {"squashed spindle", torus(0.6, 1.0)->transformed(Affine::scaling(dvec3(1, 2, 0.5)))},
  };
}

// Every boundary is on the surface: the meridian distance there is within
// 1e-9 of the torus's size (rounding, and the sqrt(ε) of a near-tangency).
TEST(TorusPrimitive, BoundariesLieOnTheSurface) {
  struct Case {
    double R, r;
  };
  std::mt19937_64 rng(11);
  for (Case c : {Case{3, 1}, Case{10, 0.1}, Case{1, 0.9}, Case{1, 1}, Case{0.5, 1}, Case{0, 1}}) {
    auto t = torus(c.R, c.r);
    Bounds box = t->bounds();
    double size = c.R + c.r;
    int boundaries = 0;
    for (int i = 0; i < 4000; ++i) {
      dvec3 dir = randomDirection(rng) * (i % 3 == 0 ? 0.25 : 1.0);
      Ray line(test::randomPoint(rng, box), dir, -kInfinity, kInfinity);
      SpanList spans = spansOf(*t, line);
      ASSERT_TRUE(spans.valid());
      for (const Span& s : spans) {
        EXPECT_GT(s.out.t, s.in.t);
        for (double tt : {s.in.t, s.out.t}) {
          ++boundaries;
          ASSERT_LE(surfaceDistance(line.at(tt), c.R, c.r), 1e-9 * size)
              << "R=" << c.R << " r=" << c.r << " t=" << tt;
        }
      }
    }
    EXPECT_GT(boundaries, 500);
  }
}

TEST(TorusPrimitive, SpansAgreeWithContainsOnRandomLines) {
  for (const auto& [name, solid] : assortedTori()) {
    SCOPED_TRACE(name);
    expectSpansAgreeWithContainsOnRandomLines(*solid, 5000, 5);
  }
}

// Very thin and very fat rings (R/r = 1e6 and 1 + 1e-6): lines through
// random points of the tube find the span holding the point, with ends on
// the surface to 1e-12 of the torus's size.
TEST(TorusPrimitive, ExtremeProportions) {
  struct Case {
    double R, r;
  };
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (Case c : {Case{1000.0, 1e-3}, Case{1.0 + 1e-6, 1.0}, Case{1.0, 1.0 + 1e-6}}) {
    auto t = torus(c.R, c.r);
    for (int i = 0; i < 2000; ++i) {
      // A point in the tube: core circle angle, then a point of the disc.
      double theta = 2 * kPi * unit(rng), phi = 2 * kPi * unit(rng), rho = c.r * unit(rng);
      dvec3 radial(std::cos(theta), std::sin(theta), 0.0);
      dvec3 p = (c.R + rho * std::cos(phi)) * radial + dvec3(0, 0, rho * std::sin(phi));
      dvec3 u = randomDirection(rng);
      Ray line(p - 3 * (c.R + c.r) * u, u, -kInfinity, kInfinity);
      SpanList spans = spansOf(*t, line);
      ASSERT_TRUE(spans.valid());
      double at = 3 * (c.R + c.r);
      bool held = false;
      for (const Span& s : spans) {
        held = held || (s.in.t <= at + 1e-12 * at && at - 1e-12 * at <= s.out.t);
        for (double tt : {s.in.t, s.out.t})
          EXPECT_LE(surfaceDistance(line.at(tt), c.R, c.r), 1e-12 * (c.R + c.r))
              << "R=" << c.R << " r=" << c.r;
      }
      EXPECT_TRUE(held || surfaceDistance(p, c.R, c.r) < 1e-12 * (c.R + c.r))
          << "R=" << c.R << " r=" << c.r << " i=" << i;
      if (::testing::Test::HasFailure()) return;
    }
  }
}

// A camera or shadow ray asks for the first boundary only, and the torus
// then stops at the first entry: that boundary is the one of the whole
// spans, bit for bit.
TEST(TorusPrimitive, FirstBoundaryAgreesWithTheWholeSpans) {
  for (const auto& [name, solid] : assortedTori()) {
    SCOPED_TRACE(name);
    const auto [hits, entries] = test::expectFirstBoundaryAgreesWithTheWholeSpans(*solid, 3000, 5);
    // Many rays meet the torus, both entering and leaving first.
    EXPECT_GT(hits, 500);
    EXPECT_GT(entries, 300);
    EXPECT_LT(entries, hits - 25);
  }
}

// A shadow ray asks only whether the torus meets its window, which the
// torus answers without finding its boundaries exactly where it can
// (Torus::objectMeetsWindow): the answer is the one of the first
// boundary's spans, on rays from around it and from within its box, over
// windows that start and end anywhere.
TEST(TorusPrimitive, MeetsAWindowWhereItsFirstBoundaryLies) {
  for (const auto& [name, solid] : assortedTori()) {
    SCOPED_TRACE(name);
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const Bounds box = solid->bounds();
    const dvec3 pad = 0.5 * box.size();
    const double reach = glm::length(box.size());
    int met = 0, missed = 0;
    SpanList first, scratch;
    for (int i = 0; i < 4000; ++i) {
      const dvec3 from = test::randomPoint(rng, Bounds{box.lo - pad, box.hi + pad});
      Ray ray(from, test::randomPoint(rng, box) - from);
      if (i % 2) ray = Ray(test::randomPoint(rng, box), reach * randomDirection(rng));
      ray.tMin = i % 3 == 1 ? u(rng) : 0.0;
      ray.tMax = i % 5 == 2 ? ray.tMin + u(rng) : kInfinity;
      if (i % 7 == 4) {
        // A window that starts or ends on the surface, where the answer
        // cannot be had without the boundaries.
        solid->spans(ray, first);
        if (!first.empty()) (i % 2 ? ray.tMin : ray.tMax) = first.front().in.t;
      }
      solid->spansToFirstBoundary(ray, first);
      const bool expected = first.meetsOpenWindow(ray.tMin, ray.tMax);
      EXPECT_EQ(solid->meetsWindow(ray, scratch), expected) << "ray " << i;
      (expected ? met : missed)++;
    }
    EXPECT_GT(met, 800);
    EXPECT_GT(missed, 800);
  }
  // Lines that graze the top of the tube or run along the axis.
  auto ring = torus(3.0, 1.0), spindle = torus(0.5, 1.0);
  SpanList first, scratch;
  for (double z : {1.0 - 1e-12, 1.0, 1.0 + 1e-14}) {
    for (const auto& solid : {ring, spindle}) {
      for (Ray ray : {Ray(dvec3(-10, 0, z), dvec3(1, 0, 0)), Ray(dvec3(0, 0, -5), dvec3(0, 0, 1)),
                      Ray(dvec3(0, 1e-300, -5), dvec3(0, 0, 1), 4.0, 7.0)}) {
        solid->spansToFirstBoundary(ray, first);
        EXPECT_EQ(solid->meetsWindow(ray, scratch), first.meetsOpenWindow(ray.tMin, ray.tMax))
            << "z " << z << " dir " << ray.dir.x;
      }
    }
  }
}

// Shadow rays as the renderer casts them: from a point of the surface,
// moved off it along the normal by a little (as little as 1e-9 of the
// size), towards a light on the outer side, some of them grazing. Many
// leave the torus for good, many cross the hole and meet the tube again,
// and rays that start inside (moved the other way) meet it at once. The
// answer is the one of the first boundary's spans.
TEST(TorusPrimitive, ShadowRaysFromTheSurfaceMeetItWhereItsSpansSay) {
  std::mt19937_64 rng(37);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (auto [R, r] :
       {std::pair{3.0, 1.0}, std::pair{1.0, 0.9}, std::pair{10.0, 0.1}, std::pair{2.0, 0.5}}) {
    auto t = torus(R, r);
    const double size = R + r;
    int met = 0, missed = 0;
    SpanList first, scratch;
    for (int i = 0; i < 4000; ++i) {
      const double theta = 2 * kPi * u(rng), phi = 2 * kPi * u(rng);
      const dvec3 radial(std::cos(theta), std::sin(theta), 0.0);
      const dvec3 n = std::cos(phi) * radial + dvec3(0, 0, std::sin(phi));
      const dvec3 p = R * radial + r * n;
      dvec3 dir = randomDirection(rng);
      if (glm::dot(dir, n) < 0.0) dir = -dir;
      if (i % 4 == 1) dir = glm::normalize(dir - glm::dot(dir, n) * n + 1e-6 * n);  // grazing
      const double off = std::pow(10.0, -9.0 + 4.0 * u(rng)) * size;
      const dvec3 from = p + (i % 7 == 3 ? -off : off) * n;
      Ray ray(from, (0.5 + 3.0 * u(rng)) * size * dir, 0.0, 1.0);
      t->spansToFirstBoundary(ray, first);
      const bool expected = first.meetsOpenWindow(ray.tMin, ray.tMax);
      EXPECT_EQ(t->meetsWindow(ray, scratch), expected) << "R=" << R << " r=" << r << " ray " << i;
      (expected ? met : missed)++;
    }
    EXPECT_GT(met, 600) << "R=" << R << " r=" << r;
    EXPECT_GT(missed, 1500) << "R=" << R << " r=" << r;
  }
}

// Unit outward normals: against the ray where it enters, along it where it
// leaves.
TEST(TorusPrimitive, NormalsFaceOutward) {
  std::mt19937_64 rng(9);
  for (auto [R, r] : {std::pair{3.0, 1.0}, std::pair{0.5, 1.0}, std::pair{0.0, 1.0}}) {
    auto t = torus(R, r);
    for (int i = 0; i < 2000; ++i) {
      Ray line(test::randomPoint(rng, t->bounds()), randomDirection(rng), -kInfinity, kInfinity);
      for (const Span& s : spansOf(*t, line)) {
        if (s.length() < 1e-6) continue;  // nearly tangent: the normal is nearly perpendicular
        dvec3 in = t->normal(line.at(s.in.t), 0), out = t->normal(line.at(s.out.t), 0);
        EXPECT_NEAR(glm::length(in), 1.0, 1e-12);
        EXPECT_LE(glm::dot(in, line.dir), 1e-9);
        EXPECT_GE(glm::dot(out, line.dir), -1e-9);
      }
    }
  }
}

// tMin/tMax: spans wholly outside the window may be left out, the others
// are whole.
TEST(TorusPrimitive, WindowCulling) {
  auto t = torus(3.0, 1.0);
  SpanList spans = spansOf(*t, Ray(dvec3(-10, 0, 0), dvec3(1, 0, 0), 7.0, 12.5));
  ASSERT_EQ(spans.size(), 2u);
  EXPECT_NEAR(spans[0].in.t, 6.0, 1e-12);
  EXPECT_NEAR(spans[1].out.t, 14.0, 1e-12);
  EXPECT_TRUE(spansOf(*t, Ray(dvec3(-10, 0, 0), dvec3(1, 0, 0), 15.0, 20.0)).empty());
  EXPECT_TRUE(spansOf(*t, Ray(dvec3(-10, 0, 0), dvec3(1, 0, 0), 0.0, 5.0)).empty());
}

// ------------------------------------------------------------- volumes

constexpr int kGrid = 400;
constexpr double kTolerance = 0.005;

void expectVolume(const SolidPtr& s, double exact) {
  auto along = [&](const Affine& turn) {
    SolidPtr turned = s->transformed(turn);
    return test::gridVolume(*turned, turned->bounds(), kGrid);
  };
  EXPECT_NEAR(along(Affine()), exact, kTolerance * exact) << "rays along z";
  EXPECT_NEAR(along(Affine::rotation(kPi / 2, dvec3(0, 1, 0))), exact, kTolerance * exact)
      << "rays along x";
  EXPECT_NEAR(along(Affine::rotation(kPi / 2, dvec3(1, 0, 0))), exact, kTolerance * exact)
      << "rays along y";
}

// Pappus: 2πR · πr².
TEST(TorusVolume, RingTorus) {
  expectVolume(torus(3.0, 1.0), 2 * kPi * kPi * 3.0 * 1.0);
  expectVolume(torus(2.0, 0.5)->transformed(Affine::rotation(0.4, glm::normalize(dvec3(1, 1, 0)))),
               2 * kPi * kPi * 2.0 * 0.25);
  expectVolume(torus(1.0, 1.0), 2 * kPi * kPi);  // horn: Pappus still holds
}

// A spindle torus (R < r): the meridian disc crosses the axis, and the part
// of it beyond the axis is covered twice, so it counts once:
// V = 2π(πr²R + (2/3)h³ − R·r²·acos(R/r) + R²h), h = √(r² − R²).
double spindleVolume(double R, double r) {
  double h = std::sqrt(r * r - R * R);
  return 2 * kPi *
         (kPi * r * r * R + 2.0 / 3.0 * h * h * h - R * r * r * std::acos(R / r) + R * R * h);
}

TEST(TorusVolume, SpindleTorus) {
  // The formula at its ends: a ball at R = 0, Pappus at R = r.
  EXPECT_NEAR(spindleVolume(0.0, 1.5), 4.0 / 3.0 * kPi * std::pow(1.5, 3), 1e-12);
  EXPECT_NEAR(spindleVolume(2.0, 2.0), 2 * kPi * kPi * 2.0 * 4.0, 1e-12);
  expectVolume(torus(0.5, 1.0), spindleVolume(0.5, 1.0));
  expectVolume(torus(0.0, 1.0), 4.0 / 3.0 * kPi);
}

// ---------------------------------------------------------- grazing rays

// Rays along x over the top of the tube at height z: the tube is cut where
// (|x| − R)² <= r² − z², two spans of half-length √(r² − z²) around x = ±R.
TEST(TorusGrazing, OverTheTopOfTheTube) {
  double R = 3.0, r = 1.0;
  auto t = torus(R, r);
  for (double sign : {1.0, -1.0}) {
    // Just inside: two spans of the predicted length.
    for (double below : {1e-3, 1e-6, 1e-9, 1e-12}) {
      double z = sign * r * (1 - below);
      double half = std::sqrt((r - std::abs(z)) * (r + std::abs(z)));
      SpanList spans = spansOf(*t, Ray(dvec3(-10, 0, z), dvec3(1, 0, 0)));
      ASSERT_TRUE(spans.valid());
      ASSERT_EQ(spans.size(), 2u) << "z = r(1 - " << below << ")";
      for (int i = 0; i < 2; ++i) {
        double centre = 10 + (i == 0 ? -R : R);
        EXPECT_NEAR(spans[i].in.t, centre - half, 1e-9 + 1e-4 * half) << below;
        EXPECT_NEAR(spans[i].out.t, centre + half, 1e-9 + 1e-4 * half) << below;
      }
      if (below >= 1e-9) {
        EXPECT_NEAR(spans[0].length(), 2 * half, 1e-6 * half) << below;
      }
    }
    // Exactly tangent: nothing, or tiny spans at x = ±R.
    SpanList spans = spansOf(*t, Ray(dvec3(-10, 0, sign * r), dvec3(1, 0, 0)));
    ASSERT_TRUE(spans.valid());
    for (const Span& s : spans) {
      EXPECT_LT(s.length(), 1e-6);
      EXPECT_NEAR(std::abs(s.in.t - 10), R, 1e-6);
    }
    // Just outside: nothing.
    for (double above : {1e-9, 1e-12, 1e-14}) {
      spans = spansOf(*t, Ray(dvec3(-10, 0, sign * r * (1 + above)), dvec3(1, 0, 0)));
      EXPECT_TRUE(spans.empty()) << "z = r(1 + " << above << ")";
    }
  }
}

// Lines tangent to the outer (convex) part of the surface at random points,
// moved off it by ±δ along the normal: inward, a short span around the
// tangent point of length 2√(2δ/κ) (κ the normal curvature along the line,
// by Euler's formula); outward, nothing near the tangent point.
TEST(TorusGrazing, TangentLinesOnTheOuterSurface) {
  double R = 3.0, r = 1.0;
  auto t = torus(R, r);
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 300; ++i) {
    double theta = 2 * kPi * u(rng), phi = (u(rng) - 0.5) * (kPi - 0.4), alpha = 2 * kPi * u(rng);
    dvec3 radial(std::cos(theta), std::sin(theta), 0.0),
        around(-std::sin(theta), std::cos(theta), 0.0);
    dvec3 n = std::cos(phi) * radial + dvec3(0, 0, std::sin(phi));
    dvec3 meridian = -std::sin(phi) * radial + dvec3(0, 0, std::cos(phi));
    dvec3 p = R * radial + r * n;
    dvec3 dir = std::cos(alpha) * meridian + std::sin(alpha) * around;
    double kMeridian = 1.0 / r, kParallel = std::cos(phi) / (R + r * std::cos(phi));
    double kappa = kMeridian * std::cos(alpha) * std::cos(alpha) +
                   kParallel * std::sin(alpha) * std::sin(alpha);
    for (double delta : {1e-6, 1e-9, 1e-12}) {
      Ray inward(p - delta * n - 10.0 * dir, dir, -kInfinity, kInfinity);
      SpanList spans = spansOf(*t, inward);
      ASSERT_TRUE(spans.valid());
      double expected = 2 * std::sqrt(2 * delta / kappa);
      bool found = false;
      for (const Span& s : spans) {
        if (s.in.t > 10.0 || s.out.t < 10.0) continue;
        found = true;
        EXPECT_NEAR(s.length(), expected, 0.01 * expected)
            << "delta " << delta << " theta " << theta << " phi " << phi << " alpha " << alpha;
      }
      EXPECT_TRUE(found) << "inward by " << delta << " theta " << theta << " phi " << phi;
      Ray outward(p + delta * n - 10.0 * dir, dir, -kInfinity, kInfinity);
      spans = spansOf(*t, outward);
      ASSERT_TRUE(spans.valid());
      for (const Span& s : spans)
        EXPECT_TRUE(s.out.t < 10.0 - 0.01 || s.in.t > 10.0 + 0.01)
            << "outward by " << delta << ": span [" << s.in.t << ", " << s.out.t << "]";
    }
  }
}

// Near the hole. Lines along y in the plane z = 0 at x = R − r ∓ δ: in the
// hole they pass between two spans with a gap of 2√((R − r)² − x²); just
// outside it they go through the tube in one span. Lines along z at
// x = R − r ± δ graze the inner equator from inside (a span 2√(2rδ − δ²)
// long) or miss it.
TEST(TorusGrazing, NearTheHole) {
  double R = 3.0, r = 1.0;
  auto t = torus(R, r);
  double inner = R - r, outerY = 10.0;
  for (double delta : {1e-3, 1e-6, 1e-9, 1e-12}) {
    double x = inner - delta;
    SpanList spans = spansOf(*t, Ray(dvec3(x, -outerY, 0), dvec3(0, 1, 0)));
    ASSERT_TRUE(spans.valid());
    double gap = 2 * std::sqrt((inner - x) * (inner + x));
    if (gap > 1e-5) {
      ASSERT_EQ(spans.size(), 2u) << delta;
      EXPECT_NEAR(spans[1].in.t - spans[0].out.t, gap, 1e-4 * gap) << delta;
    } else {
      // The gap may close in rounding, never anything else.
      ASSERT_GE(spans.size(), 1u);
      ASSERT_LE(spans.size(), 2u);
      if (spans.size() == 2) {
        EXPECT_LT(spans[1].in.t - spans[0].out.t, 1e-4);
      }
    }
    double far = std::sqrt((R + r) * (R + r) - x * x);
    EXPECT_NEAR(spans[0].in.t, outerY - far, 1e-9);
    EXPECT_NEAR(spans[spans.size() - 1].out.t, outerY + far, 1e-9);

    spans = spansOf(*t, Ray(dvec3(inner + delta, -outerY, 0), dvec3(0, 1, 0)));
    ASSERT_EQ(spans.size(), 1u) << delta;
    EXPECT_NEAR(spans[0].in.t,
                outerY - std::sqrt((R + r) * (R + r) - (inner + delta) * (inner + delta)), 1e-9);

    spans = spansOf(*t, Ray(dvec3(inner + delta, 0, -5), dvec3(0, 0, 1)));
    ASSERT_EQ(spans.size(), 1u) << delta;
    double half = std::sqrt(2 * r * delta - delta * delta);
    EXPECT_NEAR(spans[0].in.t, 5 - half, 1e-9 + 1e-4 * half) << delta;
    EXPECT_NEAR(spans[0].out.t, 5 + half, 1e-9 + 1e-4 * half) << delta;
    EXPECT_TRUE(spansOf(*t, Ray(dvec3(inner - delta, 0, -5), dvec3(0, 0, 1))).empty()) << delta;
  }
  // Exactly tangent to the inner equator, from inside the hole: one span or
  // two that nearly touch, valid either way.
  SpanList spans = spansOf(*t, Ray(dvec3(inner, -outerY, 0), dvec3(0, 1, 0)));
  ASSERT_TRUE(spans.valid());
  ASSERT_GE(spans.size(), 1u);
  EXPECT_NEAR(spans.lengthWithin(-kInfinity, kInfinity), 2 * std::sqrt(16.0 - 4.0), 1e-6);
}

// ---------------------------------------------------------- far away

// A torus a million units away: the same hits as at the origin, to the
// precision the ray's position has there (~1e-10).
TEST(TorusFarAway, HitsAtAMillion) {
  double R = 3.0, r = 2.0;
  dvec3 centre(1e6, 1e6, 1e6);
  SolidPtr t = torus(R, r)->transformed(Affine::translation(centre));
  // Along x through the centre, from 1e6 away.
  SpanList spans = spansOf(*t, Ray(dvec3(0, 1e6, 1e6), dvec3(1, 0, 0)));
  ASSERT_EQ(spans.size(), 2u);
  EXPECT_NEAR(spans[0].in.t, 1e6 - 5, 1e-8);
  EXPECT_NEAR(spans[0].out.t, 1e6 - 1, 1e-8);
  EXPECT_NEAR(spans[1].in.t, 1e6 + 1, 1e-8);
  EXPECT_NEAR(spans[1].out.t, 1e6 + 5, 1e-8);
  // From the world origin through the centre, at the angle β with sin β = 1/√3.
  dvec3 dir = glm::normalize(centre);
  double d = glm::length(centre);
  double mid = R * std::sqrt(2.0 / 3.0), half = std::sqrt(r * r - R * R / 3.0);
  spans = spansOf(*t, Ray(dvec3(0), dir));
  ASSERT_EQ(spans.size(), 2u);
  EXPECT_NEAR(spans[0].in.t, d - mid - half, 1e-7);
  EXPECT_NEAR(spans[0].out.t, d - mid + half, 1e-7);
  EXPECT_NEAR(spans[1].in.t, d + mid - half, 1e-7);
  EXPECT_NEAR(spans[1].out.t, d + mid + half, 1e-7);
  // Random lines through points inside the tube, seen from 2e6 away: the
  // span holding the point is where the same line near the origin has it.
  auto near = torus(R, r);
  std::mt19937_64 rng(17);
  for (int i = 0; i < 500; ++i) {
    dvec3 p;
    do p = test::randomPoint(rng, near->bounds());
    while (!near->contains(p) || surfaceDistance(p, R, r) < 0.05);
    dvec3 u = randomDirection(rng);
    SpanList local = spansOf(*near, Ray(p, u, -kInfinity, kInfinity));
    SpanList far = spansOf(*t, Ray(centre + p - 2e6 * u, u));
    auto holding = [](const SpanList& s, double at) -> const Span* {
      for (const Span& x : s)
        if (x.in.t <= at && at <= x.out.t) return &x;
      return nullptr;
    };
    const Span* a = holding(local, 0.0);
    const Span* b = holding(far, 2e6);
    ASSERT_TRUE(a && b) << i;
    // The ends may be grazing exits, where 1e-10 in position is ~1e-5 in t.
    EXPECT_NEAR(b->in.t - 2e6, a->in.t, 1e-4) << i;
    EXPECT_NEAR(b->out.t - 2e6, a->out.t, 1e-4) << i;
    for (double tt : {b->in.t, b->out.t})
      EXPECT_LE(surfaceDistance(centre + p - 2e6 * u + tt * u - centre, R, r), 1e-8);
  }
}

// ------------------------------------------------ horn, spindle, ball

TEST(TorusSelfIntersecting, HornAndSpindleAlongAxes) {
  // Horn (R = r = 1): along x through the centre, one span |x| <= 2 (the
  // tube closes at the centre, which belongs to the solid).
  auto horn = torus(1.0, 1.0);
  SpanList spans = spansOf(*horn, Ray(dvec3(-10, 0, 0), dvec3(1, 0, 0)));
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_NEAR(spans[0].in.t, 8.0, 1e-12);
  EXPECT_NEAR(spans[0].out.t, 12.0, 1e-12);
  // Spindle (R = 0.5, r = 1): along x, |x| <= 1.5; along the axis, the
  // cusps at z = ±√(r² − R²); the inner lemon is solid, no boundary.
  auto spindle = torus(0.5, 1.0);
  spans = spansOf(*spindle, Ray(dvec3(-10, 0, 0), dvec3(1, 0, 0)));
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_NEAR(spans[0].in.t, 8.5, 1e-12);
  EXPECT_NEAR(spans[0].out.t, 11.5, 1e-12);
  spans = spansOf(*spindle, Ray(dvec3(0, 0, -10), dvec3(0, 0, 1)));
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_NEAR(spans[0].in.t, 10 - std::sqrt(0.75), 1e-9);
  EXPECT_NEAR(spans[0].out.t, 10 + std::sqrt(0.75), 1e-9);
  // Parallel to the axis through the dimple: (ρ − R)² + z² <= r².
  spans = spansOf(*spindle, Ray(dvec3(0.2, 0, -10), dvec3(0, 0, 1)));
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_NEAR(spans[0].out.t - 10, std::sqrt(1 - 0.09), 1e-12);
}

// R = 0 is a ball: the same spans as the sphere.
TEST(TorusSelfIntersecting, ZeroMajorRadiusIsABall) {
  auto ball = torus(0.0, 2.0);
  auto sphere = Primitive::create<Sphere>(2.0);
  std::mt19937_64 rng(4);
  for (int i = 0; i < 2000; ++i) {
    Ray line(test::randomPoint(rng, Bounds{dvec3(-3), dvec3(3)}), randomDirection(rng), -kInfinity,
             kInfinity);
    SpanList a = spansOf(*ball, line), b = spansOf(*sphere, line);
    ASSERT_TRUE(a.valid());
    if (!b.empty() && b[0].length() > 1e-6) {
      ASSERT_EQ(a.size(), 1u) << i;
      EXPECT_NEAR(a[0].in.t, b[0].in.t, 1e-9);
      EXPECT_NEAR(a[0].out.t, b[0].out.t, 1e-9);
    }
  }
}

// -------------------------------------------------------------- script

Scene sceneOf(const std::string& source) { return runScript(source, "part.lua"); }

TEST(TorusScript, MakesATorus) {
  Scene scene = sceneOf("return torus{R=3, r=1}");
  ASSERT_EQ(scene.objects.size(), 1u);
  auto t = std::dynamic_pointer_cast<const Torus>(scene.objects[0]);
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->majorRadius(), 3.0);
  EXPECT_EQ(t->minorRadius(), 1.0);
  EXPECT_NO_THROW(sceneOf("return torus{R=0, r=1}"));
  EXPECT_NO_THROW(sceneOf("return torus{R=0.5, r=1}"));
}

TEST(TorusScript, ErrorsNameTheParameter) {
  auto expectError = [](const std::string& source, const std::string& expected) {
    std::string e = scriptError(source);
    EXPECT_NE(e.find(expected), std::string::npos) << source << "\n  gave: " << e;
    EXPECT_NE(e.find("part.lua:1"), std::string::npos) << e;
  };
  expectError("return torus{R=3, r=-1}", "torus: r must be > 0 (got -1)");
  expectError("return torus{R=3, r=0}", "torus: r must be > 0 (got 0)");
  expectError("return torus{R=-1, r=1}", "torus: R must be >= 0 (got -1)");
  expectError("return torus{R=3}", "torus: needs R");
  expectError("return torus{r=1}", "torus: needs R");
  expectError("return torus{R=3, r=1, d=2}", "torus");
  expectError("return torus{R=3, r=0/0}", "torus: r");
}

// ------------------------------------------------------------- rendering

// Is the line through the ray within r of the core circle (R, θ) in the
// plane through centre spanned by e1, e2? Independent of the solver: the
// squared distance from the circle point at θ to the line is a
// trigonometric polynomial; a fine scan finds its minima, golden-section
// search refines each. Returns the minimum distance, or the scan's when
// that already decides on which side of r it is (the scan's minimum is an
// upper bound, and the true one is at most R·step/2 less).
// samples: the circle's points at angles 2πi/n, computed once per circle.
double distanceToCoreCircle(const Ray& ray, const dvec3& centre, const dvec3& e1, const dvec3& e2,
                            double R, double r, const std::vector<dvec3>& samples) {
  dvec3 d = glm::normalize(ray.dir);
  auto dist2 = [&](double theta) {
    dvec3 c = centre + R * (std::cos(theta) * e1 + std::sin(theta) * e2) - ray.origin;
    dvec3 off = c - glm::dot(c, d) * d;
    return glm::dot(off, off);
  };
  const int kSamples = int(samples.size());
  double step = 2 * kPi / kSamples;
  std::vector<double> values(kSamples);
  for (int i = 0; i < kSamples; ++i) {
    dvec3 c = samples[i] - ray.origin;
    dvec3 off = c - glm::dot(c, d) * d;
    values[i] = glm::dot(off, off);
  }
  double scanned = std::sqrt(*std::min_element(values.begin(), values.end()));
  if (scanned < 0.999 * r || scanned - R * step > 1.001 * r) return scanned;
  double best = kInfinity;
  for (int i = 0; i < kSamples; ++i) {
    double here = values[i];
    if (here > values[(i + kSamples - 1) % kSamples] || here > values[(i + 1) % kSamples]) continue;
    double a = (i - 1) * step, b = (i + 1) * step;
    const double g = (std::sqrt(5.0) - 1) / 2;
    double x1 = b - g * (b - a), x2 = a + g * (b - a);
    double f1 = dist2(x1), f2 = dist2(x2);
    for (int k = 0; k < 80; ++k) {
      if (f1 < f2) {
        b = x2, x2 = x1, f2 = f1;
        x1 = b - g * (b - a), f1 = dist2(x1);
      } else {
        a = x1, x1 = x2, f1 = f2;
        x2 = a + g * (b - a), f2 = dist2(x2);
      }
    }
    best = std::min({best, here, f1, f2});
  }
  return std::sqrt(best);
}

struct SilhouetteCheck {
  int hits = 0, misses = 0, skipped = 0, wrong = 0;
};

// Renders the scene and compares every pixel with the analytic answer for
// the ray through the pixel's centre (the renderer's own camera rays).
SilhouetteCheck checkSilhouette(const Scene& scene, int w, int h, const dvec3& centre,
                                const dvec3& e1, const dvec3& e2, double R, double r, double band,
                                bool exactOrtho) {
  Image image = Renderer(scene, {w, h, 0}).render();
  Camera camera(*scene.camera, w, h);
  SilhouetteCheck check;
  std::vector<dvec3> samples(720);
  for (size_t i = 0; i < samples.size(); ++i) {
    double theta = 2 * kPi * double(i) / double(samples.size());
    samples[i] = centre + R * (std::cos(theta) * e1 + std::sin(theta) * e2);
  }
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      Ray ray = camera.ray(x + 0.5, y + 0.5);
      double dist;
      if (exactOrtho) {
        // Rays along y in the torus's plane: the line (u, ·, v) is
        // max(|u| − R, 0) in the plane and v out of it from the circle.
        double u = ray.origin.x - centre.x, v = ray.origin.z - centre.z;
        dist = std::hypot(std::max(std::abs(u) - R, 0.0), v);
      } else {
        dist = distanceToCoreCircle(ray, centre, e1, e2, R, r, samples);
      }
      if (std::abs(dist - r) <= band) {
        ++check.skipped;
        continue;
      }
      bool hit = dist < r;
      bool shown = image.at(x, y) != dvec3(0.0);
      check.hits += hit;
      check.misses += !hit;
      if (hit != shown) {
        if (++check.wrong <= 10)
          ADD_FAILURE() << "pixel (" << x << ", " << y << "): silhouette says "
                        << (hit ? "hit" : "miss") << ", distance − r = " << dist - r;
      }
    }
  }
  return check;
}

// Orthographic, edge-on, with r chosen so that a row of pixel centres lies
// 1e-9·r inside (then outside) the top and bottom of the tube: rays that
// skim the tube along its whole length.
TEST(TorusRender, EdgeOnOrthographicSkimmingRows) {
  const int w = 400, h = 200;
  CameraSpec camera{dvec3(0, -20, 0), dvec3(0), dvec3(0, 0, 1), 45.0, true, 10.0};
  Camera probe(camera, w, h);
  double row = probe.ray(0.5, 60.5).origin.z;  // pixel row 60's height
  ASSERT_GT(row, 0.5);
  for (double factor : {1 + 1e-9, 1 - 1e-9}) {
    double R = 3.0, r = row * factor;
    Scene scene;
    scene.objects.push_back(torus(R, r));
    scene.camera = camera;
    scene.background = dvec3(0.0);
    SilhouetteCheck c =
        checkSilhouette(scene, w, h, dvec3(0), dvec3(1, 0, 0), dvec3(0, 1, 0), R, r, 1e-12, true);
    EXPECT_EQ(c.wrong, 0) << "r = row·" << factor;
    EXPECT_GT(c.hits, 5000);
    EXPECT_GT(c.misses, 5000);
    // The skimming rows: hit along the whole top when inside, never when out.
    Image image = Renderer(scene, {w, h, 0}).render();
    int shown = 0;
    for (int x = 0; x < w; ++x) shown += image.at(x, 60) != dvec3(0.0);
    if (factor > 1) {
      EXPECT_GT(shown, 200);
    } else {
      EXPECT_EQ(shown, 0);
    }
  }
}

// Perspective, edge-on: the eye in the torus's plane looking at its
// centre; the silhouette is curved and rays cross the plane at an angle.
// Also a torus turned and moved, with the eye in its (turned) plane.
TEST(TorusRender, EdgeOnPerspective) {
  const int w = 400, h = 200;
  double R = 3.0, r = 1.0;
  {
    Scene scene;
    scene.objects.push_back(torus(R, r));
    scene.camera = CameraSpec{dvec3(0.3, -12, 0), dvec3(0), dvec3(0, 0, 1), 45.0};
    scene.background = dvec3(0.0);
    SilhouetteCheck c =
        checkSilhouette(scene, w, h, dvec3(0), dvec3(1, 0, 0), dvec3(0, 1, 0), R, r, 1e-6, false);
    EXPECT_EQ(c.wrong, 0);
    EXPECT_GT(c.hits, 5000);
    EXPECT_GT(c.misses, 5000);
    EXPECT_LT(c.skipped, 200);
  }
  {
    Affine turn = Affine::rotation(0.9, glm::normalize(dvec3(1, -2, 0.5)));
    dvec3 centre(5, -7, 2);
    Affine place = turn.then(Affine::translation(centre));
    dvec3 e1 = place.pointToWorld(dvec3(1, 0, 0)) - centre;
    dvec3 e2 = place.pointToWorld(dvec3(0, 1, 0)) - centre;
    dvec3 axis = glm::cross(e1, e2);
    Scene scene;
    scene.objects.push_back(torus(R, r)->transformed(place));
    // The eye 14 away along a direction in the torus's plane.
    dvec3 in = glm::normalize(0.6 * e1 - 0.8 * e2);
    scene.camera = CameraSpec{centre + 14.0 * in, centre, axis, 40.0};
    scene.background = dvec3(0.0);
    SilhouetteCheck c = checkSilhouette(scene, w, h, centre, e1, e2, R, r, 1e-6, false);
    EXPECT_EQ(c.wrong, 0);
    EXPECT_GT(c.hits, 5000);
    EXPECT_GT(c.misses, 5000);
  }
}

// The example script: several tori, cut and linked, fill the frame.
TEST(TorusRender, ExampleScriptRenders) {
  ScriptOptions options;
  Scene scene = runScriptFile(CSGRAY_SOURCE_DIR "/examples/torus.lua", options);
  ASSERT_FALSE(scene.objects.empty());
  Image image = Renderer(scene, {160, 120, 0}).render();
  int notBackground = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      notBackground += glm::any(glm::notEqual(image.at(x, y), dvec3(glm::vec3(scene.background))));
  EXPECT_GT(notBackground, image.width * image.height / 10);
}

}  // namespace
}  // namespace csgray::detail
