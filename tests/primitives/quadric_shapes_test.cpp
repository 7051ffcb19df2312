// The named quadrics of the classic table (docs/theory.md) and clip, through the script
// API: each function builds the table's matrix (up to a positive factor),
// its solid is the documented side, rays meet it where the equations say,
// spans agree with contains, and clipped pieces have their analytic volumes.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/mat4x4.hpp>
#include <iomanip>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "engine/boolean.h"
#include "engine/primitive.h"
#include "primitives/quadric.h"
#include "script/script.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

using test::scriptError;
using test::solidOf;

constexpr double kPi = std::numbers::pi;

std::shared_ptr<const Quadric> quadricOf(const std::string& source) {
  auto q = std::dynamic_pointer_cast<const Quadric>(solidOf(source));
  EXPECT_TRUE(q) << source << " is not a quadric primitive";
  return q;
}

// ---- Matrices -----------------------------------------------------------------

glm::dmat4 symmetric(std::initializer_list<std::initializer_list<double>> rows) {
  glm::dmat4 m(0.0);
  int r = 0;
  for (const auto& row : rows) {
    int c = 0;
    for (double v : row) m[c++][r] = v;
    ++r;
  }
  return m;
}

std::string number(double v) {
  std::ostringstream s;
  s << std::setprecision(17) << v;
  return s.str();
}

// Table 17.1 of Winkler, "Raytracing", transcribed as printed (rows).
struct TableEntry {
  std::string source;
  glm::dmat4 matrix;
  double sign;  // of the factor between the script's matrix and the table's
};

std::vector<TableEntry> tableEntries(double a, double b, double c, double p) {
  double a2 = a * a, b2 = b * b, c2 = c * c;
  auto call = [&](const char* f, bool withC) {
    return std::string("return ") + f + "{a=" + number(a) + ", b=" + number(b) +
           (withC ? ", c=" + number(c) : "") + "}";
  };
  return {
      {call("hyperboloid1", true),
       symmetric(
           {{b2 * c2, 0, 0, 0}, {0, a2 * c2, 0, 0}, {0, 0, -a2 * b2, 0}, {0, 0, 0, -a2 * b2 * c2}}),
       1.0},
      {call("hyperboloid2", true),
       symmetric(
           {{b2 * c2, 0, 0, 0}, {0, a2 * c2, 0, 0}, {0, 0, -a2 * b2, 0}, {0, 0, 0, a2 * b2 * c2}}),
       1.0},
      {call("elliptic_cone", true),
       symmetric({{b2 * c2, 0, 0, 0}, {0, a2 * c2, 0, 0}, {0, 0, -a2 * b2, 0}, {0, 0, 0, 0}}), 1.0},
      {call("elliptic_paraboloid", false),
       symmetric({{b2, 0, 0, 0}, {0, a2, 0, 0}, {0, 0, 0, -a2 * b2 / 2}, {0, 0, -a2 * b2 / 2, 0}}),
       1.0},
      {call("hyperbolic_paraboloid", false),
       symmetric({{b2, 0, 0, 0}, {0, -a2, 0, 0}, {0, 0, 0, -a2 * b2 / 2}, {0, 0, -a2 * b2 / 2, 0}}),
       1.0},
      {call("elliptic_cylinder", false),
       symmetric({{b2, 0, 0, 0}, {0, a2, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, -a2 * b2}}), 1.0},
      // The solid is the inside of the sheets, x²/a² − y²/b² >= 1: the
      // table's matrix negated (docs/script.md, "Named quadrics").
      {call("hyperbolic_cylinder", false),
       symmetric({{b2, 0, 0, 0}, {0, -a2, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, -a2 * b2}}), -1.0},
      {"return parabolic_cylinder{p=" + number(p) + "}",
       symmetric({{0, 0, 0, -p}, {0, 1, 0, 0}, {0, 0, 0, 0}, {-p, 0, 0, 0}}), 1.0},
  };
}

// M = k · table for one factor k of the expected sign.
void expectMultipleOf(const glm::dmat4& m, const glm::dmat4& table, double sign,
                      const std::string& what) {
  int c0 = 0, r0 = 0;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (std::abs(table[c][r]) > std::abs(table[c0][r0])) c0 = c, r0 = r;
  double k = m[c0][r0] / table[c0][r0];
  EXPECT_GT(k * sign, 0.0) << what;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      EXPECT_NEAR(m[c][r], k * table[c][r], 1e-12 * std::abs(m[c0][r0]))
          << what << " entry row " << r << " column " << c;
}

TEST(NamedQuadrics, MatricesAreThoseOfTable17_1) {
  for (double s : {1.0, 0.01, 250.0}) {
    for (const TableEntry& e : tableEntries(2.0 * s, 3.0 * s, 1.5 * s, 0.7 * s)) {
      auto q = quadricOf(e.source);
      ASSERT_TRUE(q) << e.source;
      expectMultipleOf(q->matrix(), e.matrix, e.sign, e.source);
    }
  }
  // p < 0: the table's matrix with its own sign of p.
  auto q = quadricOf("return parabolic_cylinder{p=-0.5}");
  expectMultipleOf(q->matrix(),
                   symmetric({{0, 0, 0, 0.5}, {0, 1, 0, 0}, {0, 0, 0, 0}, {0.5, 0, 0, 0}}), 1.0,
                   "p=-0.5");
}

// ---- Rays along known lines ---------------------------------------------------------

// The spans of the whole line through origin along dir (a unit axis).
SpanList lineSpans(const SolidPtr& s, const dvec3& origin, const dvec3& dir) {
  return test::spansOf(*s, Ray(origin, dir, -kInfinity, kInfinity));
}

void expectT(double actual, double expected, const std::string& what) {
  if (std::isinf(expected))
    EXPECT_EQ(actual, expected) << what;
  else
    EXPECT_NEAR(actual, expected, 1e-9 * (1.0 + std::abs(expected))) << what;
}

// The line's spans are exactly the given intervals (±inf for unbounded ends).
void expectSpans(const SolidPtr& s, const dvec3& origin, const dvec3& dir,
                 std::vector<std::pair<double, double>> expected) {
  SpanList spans = lineSpans(s, origin, dir);
  std::string where = "line through (" + std::to_string(origin.x) + ", " +
                      std::to_string(origin.y) + ", " + std::to_string(origin.z) + ")";
  ASSERT_TRUE(spans.valid()) << where;
  ASSERT_EQ(spans.size(), expected.size()) << where;
  for (std::uint32_t i = 0; i < spans.size(); ++i) {
    expectT(spans[i].in.t, expected[i].first, where + " in");
    expectT(spans[i].out.t, expected[i].second, where + " out");
  }
}

const dvec3 kX(1, 0, 0), kY(0, 1, 0), kZ(0, 0, 1);
constexpr double kInf = kInfinity;

// x²/a² + y²/b² − z²/c² <= 1 with a = 2, b = 3, c = 1.5: the waist at z = 0
// has semi-axes a and b; at z = ±c they are a√2 and b√2.
TEST(NamedQuadrics, HyperboloidOfOneSheet) {
  SolidPtr s = solidOf("return hyperboloid1{a=2, b=3, c=1.5}");
  double r2 = std::sqrt(2.0);
  expectSpans(s, dvec3(0), kX, {{-2, 2}});
  expectSpans(s, dvec3(0), kY, {{-3, 3}});
  expectSpans(s, dvec3(0, 0, 1.5), kX, {{-2 * r2, 2 * r2}});
  expectSpans(s, dvec3(0, 0, -1.5), kY, {{-3 * r2, 3 * r2}});
  expectSpans(s, dvec3(0), kZ, {{-kInf, kInf}});  // the axis lies inside
  // A line outside the waist, parallel to the axis, is inside for |z| >= c·√3
  // (at x = 4: 16/4 − z²/2.25 <= 1).
  expectSpans(s, dvec3(4, 0, 0), kZ,
              {{-kInf, -1.5 * std::sqrt(3.0)}, {1.5 * std::sqrt(3.0), kInf}});
  EXPECT_TRUE(s->contains(dvec3(2 * r2 - 1e-6, 0, 1.5)));
  EXPECT_FALSE(s->contains(dvec3(2 * r2 + 1e-6, 0, 1.5)));
  EXPECT_TRUE(s->contains(dvec3(0, 0, 1e6)));
}

// x²/a² + y²/b² − z²/c² <= −1 with a = 2, b = 3, c = 1.5: the vertices are
// at z = ±c; at z = ±c√2 the sheets have semi-axes a and b.
TEST(NamedQuadrics, HyperboloidOfTwoSheets) {
  SolidPtr s = solidOf("return hyperboloid2{a=2, b=3, c=1.5}");
  expectSpans(s, dvec3(0), kZ, {{-kInf, -1.5}, {1.5, kInf}});
  expectSpans(s, dvec3(0), kX, {});
  expectSpans(s, dvec3(0), kY, {});
  double z = 1.5 * std::sqrt(2.0);
  expectSpans(s, dvec3(0, 0, z), kX, {{-2, 2}});
  expectSpans(s, dvec3(0, 0, -z), kY, {{-3, 3}});
  EXPECT_TRUE(s->contains(dvec3(0, 0, 1.5)));  // a vertex
  EXPECT_FALSE(s->contains(dvec3(0, 0, 1.49)));
  EXPECT_FALSE(s->contains(dvec3(0)));
}

// x²/a² + y²/b² <= z²/c² with a = 2, b = 3, c = 1.5: apex at the origin,
// semi-axes a and b at z = ±c.
TEST(NamedQuadrics, EllipticCone) {
  SolidPtr s = solidOf("return elliptic_cone{a=2, b=3, c=1.5}");
  expectSpans(s, dvec3(0), kZ, {{-kInf, kInf}});
  expectSpans(s, dvec3(0, 0, 1.5), kX, {{-2, 2}});
  expectSpans(s, dvec3(0, 0, -3), kY, {{-6, 6}});
  expectSpans(s, dvec3(0), kX, {});    // through the apex only: no volume
  EXPECT_TRUE(s->contains(dvec3(0)));  // the apex
  EXPECT_FALSE(s->contains(dvec3(1e-3, 0, 0)));
  // A line through the apex inside the cone is inside all along.
  SpanList through = lineSpans(s, dvec3(0), glm::normalize(dvec3(1, 0, 1.5)));
  ASSERT_TRUE(through.valid());
  EXPECT_NEAR(through.lengthWithin(-10, 10), 20.0, 1e-9);
}

// x²/a² + y²/b² <= z with a = 2, b = 3: vertex at the origin, semi-axes
// a√z and b√z.
TEST(NamedQuadrics, EllipticParaboloid) {
  SolidPtr s = solidOf("return elliptic_paraboloid{a=2, b=3}");
  expectSpans(s, dvec3(0, 0, -5), kZ, {{5, kInf}});  // the vertex is at z = 0
  expectSpans(s, dvec3(0, 0, 1), kX, {{-2, 2}});
  expectSpans(s, dvec3(0, 0, 4), kY, {{-6, 6}});
  expectSpans(s, dvec3(0, 0, -0.1), kX, {});
  EXPECT_TRUE(s->contains(dvec3(0)));
  EXPECT_FALSE(s->contains(dvec3(0, 0, -1e-9)));
}

// z >= x²/a² − y²/b² with a = 2, b = 3: the side above the saddle.
TEST(NamedQuadrics, HyperbolicParaboloid) {
  SolidPtr s = solidOf("return hyperbolic_paraboloid{a=2, b=3}");
  expectSpans(s, dvec3(0, 0, -5), kZ, {{5, kInf}});
  expectSpans(s, dvec3(4, 0, 0), kZ, {{4, kInf}});      // z >= 16/4
  expectSpans(s, dvec3(0, 6, 0), kZ, {{-4, kInf}});     // z >= −36/9
  expectSpans(s, dvec3(0, 0, 1), kX, {{-2, 2}});        // x² <= a²·z
  expectSpans(s, dvec3(0, 0, 0), kY, {{-kInf, kInf}});  // z = 0 >= −y²/b²
  expectSpans(s, dvec3(0, 0, -1), kY, {{-kInf, -3}, {3, kInf}});
  EXPECT_TRUE(s->contains(dvec3(0, 0, 1)));
  EXPECT_FALSE(s->contains(dvec3(0, 0, -1)));
}

// x²/a² + y²/b² <= 1 along z with a = 2, b = 3.
TEST(NamedQuadrics, EllipticCylinder) {
  SolidPtr s = solidOf("return elliptic_cylinder{a=2, b=3}");
  expectSpans(s, dvec3(0, 0, 100), kX, {{-2, 2}});
  expectSpans(s, dvec3(0, 0, -7), kY, {{-3, 3}});
  expectSpans(s, dvec3(1, 1, 0), kZ, {{-kInf, kInf}});
  expectSpans(s, dvec3(2.01, 0, 0), kZ, {});
}

// x²/a² − y²/b² >= 1 along z with a = 2, b = 3: the two regions about the
// x axis, vertices at x = ±a; at y = ±b they begin at |x| = a√2.
TEST(NamedQuadrics, HyperbolicCylinder) {
  SolidPtr s = solidOf("return hyperbolic_cylinder{a=2, b=3}");
  double r2 = std::sqrt(2.0);
  expectSpans(s, dvec3(0), kX, {{-kInf, -2}, {2, kInf}});
  expectSpans(s, dvec3(0, 3, 5), kX, {{-kInf, -2 * r2}, {2 * r2, kInf}});
  expectSpans(s, dvec3(0), kY, {});
  expectSpans(s, dvec3(3, 0, 0), kZ, {{-kInf, kInf}});
  EXPECT_TRUE(s->contains(dvec3(-2, 0, 9)));
  EXPECT_FALSE(s->contains(dvec3(0)));
}

// y² <= 2px along z: p = 0.7 opens towards +x, p = −0.7 towards −x.
TEST(NamedQuadrics, ParabolicCylinder) {
  SolidPtr s = solidOf("return parabolic_cylinder{p=0.7}");
  expectSpans(s, dvec3(0), kX, {{0, kInf}});
  expectSpans(s, dvec3(0, 1, 3), kX, {{1 / 1.4, kInf}});
  expectSpans(s, dvec3(2, 0, 0), kY, {{-std::sqrt(2.8), std::sqrt(2.8)}});
  EXPECT_TRUE(s->contains(dvec3(0, 0, -50)));
  EXPECT_FALSE(s->contains(dvec3(-0.01, 0, 0)));
  SolidPtr left = solidOf("return parabolic_cylinder{p=-0.7}");
  expectSpans(left, dvec3(0), kX, {{-kInf, 0}});
  expectSpans(left, dvec3(-2, 0, 0), kY, {{-std::sqrt(2.8), std::sqrt(2.8)}});
}

// ---- Invariants on random lines -----------------------------------------------------

const char* const kShapes[] = {
    "return hyperboloid1{a=2, b=3, c=1.5}",
    "return hyperboloid2{a=2, b=3, c=1.5}",
    "return elliptic_cone{a=2, b=3, c=1.5}",
    "return elliptic_paraboloid{a=2, b=3}",
    "return hyperbolic_paraboloid{a=2, b=3}",
    "return elliptic_cylinder{a=2, b=3}",
    "return hyperbolic_cylinder{a=2, b=3}",
    "return parabolic_cylinder{p=0.7}",
    "return parabolic_cylinder{p=-2}",
    "return clip(hyperboloid1{a=1, b=1.5, c=2}, {lo={-3, -3, -2}, hi={3, 3, 2}})",
    "return clip(hyperbolic_paraboloid{a=2, b=1}, {lo={-2, -1, -1.5}, hi={2, 1, 2}})",
    "return clip(hyperboloid2{a=1, b=1, c=1}, {half_space{normal={0, 0, 1}, offset=3}, "
    "half_space{normal={1, 1, 0}, offset=1}})",
};

TEST(NamedQuadrics, SpansAgreeWithContainsOnRandomLines) {
  for (const char* source : kShapes) {
    SCOPED_TRACE(source);
    test::expectSpansAgreeWithContainsOnRandomLines(*solidOf(source), 2000, 7);
  }
}

// The side each function calls the solid is the side the normals point away
// from: along a line, a span is entered against the normal and left along it.
TEST(NamedQuadrics, NormalsPointOutOfTheSolid) {
  std::mt19937_64 rng(11);
  Bounds around{dvec3(-5), dvec3(5)};
  for (const char* source : kShapes) {
    SCOPED_TRACE(source);
    SolidPtr s = solidOf(source);
    for (int i = 0; i < 1000; ++i) {
      Ray line(test::randomPoint(rng, around), test::randomDirection(rng), -kInfinity, kInfinity);
      SpanList spans = test::spansOf(*s, line);
      for (const Span& span : spans) {
        for (const Boundary* b : {&span.in, &span.out}) {
          if (!b->primitive) continue;  // at infinity
          dvec3 n = b->primitive->normal(line.at(b->t), b->face);
          if (!std::isfinite(glm::length(n))) continue;  // the cone's apex
          double along = glm::dot(n, line.dir) * (b->flip ? -1.0 : 1.0);
          if (b == &span.in)
            EXPECT_LE(along, 1e-6) << "entering at t=" << b->t;
          else
            EXPECT_GE(along, -1e-6) << "leaving at t=" << b->t;
        }
      }
    }
  }
}

// ---- Volumes of clipped pieces ---------------------------------------------------------

constexpr int kGrid = 400;
constexpr double kTolerance = 0.005;  // relative

// Rays along z, x and y over the solid's bounds (as in volume_test.cpp: a
// quarter turn about y sends x to −z, one about x sends y to z).
void expectVolume(const std::string& source, double exact) {
  SCOPED_TRACE(source);
  SolidPtr s = solidOf(source);
  ASSERT_TRUE(s->bounds().finite());
  SolidPtr alongX = s->transformed(Affine::rotation(kPi / 2, dvec3(0, 1, 0)));
  SolidPtr alongY = s->transformed(Affine::rotation(kPi / 2, dvec3(1, 0, 0)));
  EXPECT_NEAR(test::gridVolume(*s, s->bounds(), kGrid), exact, kTolerance * exact) << "along z";
  EXPECT_NEAR(test::gridVolume(*alongX, alongX->bounds(), kGrid), exact, kTolerance * exact)
      << "along x";
  EXPECT_NEAR(test::gridVolume(*alongY, alongY->bounds(), kGrid), exact, kTolerance * exact)
      << "along y";
}

// x²/a² + y²/b² <= z <= h: the ellipse at height z has area π a b z, so
// V = ∫₀ʰ π a b z dz = π a b h²/2.
TEST(ClippedVolume, EllipticParaboloid) {
  double a = 2, b = 1.5, h = 3;
  expectVolume("return clip(elliptic_paraboloid{a=2, b=1.5}, {lo={-4, -3, -1}, hi={4, 3, 3}})",
               kPi * a * b * h * h / 2);
}

// π a b h.
TEST(ClippedVolume, EllipticCylinder) {
  expectVolume("return clip(elliptic_cylinder{a=2, b=1}, {lo={-3, -2, 0}, hi={3, 2, 3}})",
               kPi * 2 * 1 * 3);
}

// Both nappes for |z| <= h: the section at z has area π a b z²/c², so
// V = 2 ∫₀ʰ π a b z²/c² dz = 2 π a b h³/(3c²).
TEST(ClippedVolume, EllipticCone) {
  double a = 2, b = 1, c = 1.5, h = 2;
  expectVolume("return clip(elliptic_cone{a=2, b=1, c=1.5}, {lo={-3, -1.5, -2}, hi={3, 1.5, 2}})",
               2 * kPi * a * b * h * h * h / (3 * c * c));
}

// |z| <= h: the section has area π a b (1 + z²/c²), so
// V = π a b (2h + 2h³/(3c²)).
TEST(ClippedVolume, HyperboloidOfOneSheet) {
  double a = 1, b = 1.5, c = 2, h = 1.5;
  expectVolume(
      "return clip(hyperboloid1{a=1, b=1.5, c=2}, {lo={-1.5, -2, -1.5}, hi={1.5, 2, 1.5}})",
      kPi * a * b * (2 * h + 2 * h * h * h / (3 * c * c)));
}

// |z| <= h: sections π a b (z²/c² − 1) for c <= |z| <= h, so
// V = 2 π a b ((h³ − c³)/(3c²) − (h − c)).
TEST(ClippedVolume, HyperboloidOfTwoSheets) {
  double a = 1, b = 1.5, c = 1, h = 2;
  expectVolume("return clip(hyperboloid2{a=1, b=1.5, c=1}, {lo={-2, -3, -2}, hi={2, 3, 2}})",
               2 * kPi * a * b * ((h * h * h - c * c * c) / (3 * c * c) - (h - c)));
}

// Over |x| <= X, |y| <= Y, from the saddle (which stays above the box's
// floor) up to z = h: V = 4XYh − ∫∫ (x²/a² − y²/b²)
//                       = 4XYh − 4X³Y/(3a²) + 4XY³/(3b²).
TEST(ClippedVolume, HyperbolicParaboloid) {
  double a = 2, b = 1.5, X = 2, Y = 1, h = 2;
  expectVolume("return clip(hyperbolic_paraboloid{a=2, b=1.5}, {lo={-2, -1, -2}, hi={2, 1, 2}})",
               4 * X * Y * h - 4 * X * X * X * Y / (3 * a * a) + 4 * X * Y * Y * Y / (3 * b * b));
}

// |x| <= X, |y| <= Y, 0 <= z <= L: each branch covers
// ∫ (X − a√(1 + y²/b²)) dy = 2XY − a b (U√(1 + U²) + asinh U), U = Y/b.
TEST(ClippedVolume, HyperbolicCylinder) {
  double a = 1, b = 1.5, X = 3, Y = 2, L = 2, U = Y / b;
  expectVolume("return clip(hyperbolic_cylinder{a=1, b=1.5}, {lo={-3, -2, 0}, hi={3, 2, 2}})",
               2 * L * (2 * X * Y - a * b * (U * std::sqrt(1 + U * U) + std::asinh(U))));
}

// y² <= 2px, x <= X, 0 <= z <= L: the parabolic segment of width
// 2s = 2√(2pX) and depth X has area (4/3)·X·s.
TEST(ClippedVolume, ParabolicCylinder) {
  double p = 0.7, X = 2, L = 3, s = std::sqrt(2 * p * X);
  expectVolume("return clip(parabolic_cylinder{p=0.7}, {lo={-1, -2, 0}, hi={2, 2, 3}})",
               4.0 / 3.0 * X * s * L);
  expectVolume("return clip(parabolic_cylinder{p=-0.7}, {lo={-2, -2, 0}, hi={1, 2, 3}})",
               4.0 / 3.0 * X * s * L);
}

// ---- clip ---------------------------------------------------------------------------------

TEST(Clip, BoundsAreFiniteAndWithinTheBox) {
  Bounds box{dvec3(-1.5, -2, -1), dvec3(2, 2.5, 3)};
  for (const char* f : {"hyperboloid1{a=1, b=1, c=1}", "hyperboloid2{a=1, b=1, c=1}",
                        "elliptic_cone{a=1, b=1, c=1}", "elliptic_paraboloid{a=1, b=1}",
                        "hyperbolic_paraboloid{a=1, b=1}", "elliptic_cylinder{a=1, b=1}",
                        "hyperbolic_cylinder{a=1, b=1}", "parabolic_cylinder{p=1}", "sphere(10)"}) {
    std::string source = std::string("return clip(") + f + ", {lo={-1.5, -2, -1}, hi={2, 2.5, 3}})";
    SolidPtr s = solidOf(source);
    Bounds b = s->bounds();
    ASSERT_TRUE(b.finite()) << source;
    for (int i = 0; i < 3; ++i) {
      EXPECT_GE(b.lo[i], box.lo[i] - 1e-12) << source;
      EXPECT_LE(b.hi[i], box.hi[i] + 1e-12) << source;
    }
    EXPECT_FALSE(s->contains(dvec3(0, 0, 3.01))) << source;
  }
}

// A list of solids: the intersection of all; a single solid: the same as '*'.
TEST(Clip, TakesSolidsAndListsOfSolids) {
  SolidPtr slab = solidOf(R"(
    return clip(elliptic_cylinder{a=1, b=1},
                {half_space{normal={0, 0, 1}, offset=2}, half_space{normal={0, 0, -1}, offset=0}}))");
  EXPECT_TRUE(slab->contains(dvec3(0, 0, 1)));
  EXPECT_FALSE(slab->contains(dvec3(0, 0, 2.5)));
  EXPECT_FALSE(slab->contains(dvec3(0, 0, -0.5)));
  EXPECT_FALSE(slab->contains(dvec3(1.1, 0, 1)));
  Bounds box{dvec3(-1.5, -1.5, -1), dvec3(1.5, 1.5, 3)};
  EXPECT_NEAR(test::gridVolume(*slab, box, kGrid), 2 * kPi, kTolerance * 2 * kPi);

  SolidPtr clipped = solidOf("return clip(hyperboloid1{a=1, b=1, c=1}, sphere(2))");
  SolidPtr product = solidOf("return hyperboloid1{a=1, b=1, c=1} * sphere(2)");
  std::mt19937_64 rng(3);
  for (int i = 0; i < 2000; ++i) {
    dvec3 p = test::randomPoint(rng, Bounds{dvec3(-2.5), dvec3(2.5)});
    EXPECT_EQ(clipped->contains(p), product->contains(p)) << p.x << ", " << p.y << ", " << p.z;
  }
  EXPECT_TRUE(clipped->bounds().finite());
}

const Primitive* primitiveChild(const SolidPtr& s, std::size_t i) {
  return dynamic_cast<const Primitive*>(s->children()[i].get());
}

// The box's faces take the clipped solid's material when all of it has one,
// and keep none otherwise (the script can material the result).
TEST(Clip, BoxTakesTheSolidsMaterial) {
  SolidPtr s = solidOf(R"(
    return clip(elliptic_cylinder{a=1, b=1}:material{color={1, 0, 0}}, {lo={-2, -2, 0}, hi={2, 2, 1}}))");
  ASSERT_EQ(s->children().size(), 2u);
  ASSERT_TRUE(primitiveChild(s, 0) && primitiveChild(s, 1));
  ASSERT_TRUE(primitiveChild(s, 0)->material());
  EXPECT_EQ(primitiveChild(s, 1)->material(), primitiveChild(s, 0)->material());

  SolidPtr mixed = solidOf(R"(
    local u = elliptic_cylinder{a=1, b=1}:material{color={1, 0, 0}}
              + elliptic_cylinder{a=1, b=1}:translate(3, 0, 0):material{color={0, 1, 0}}
    return clip(u, {lo={-2, -2, 0}, hi={5, 2, 1}}))");
  ASSERT_EQ(mixed->children().size(), 2u);
  ASSERT_TRUE(primitiveChild(mixed, 1));
  EXPECT_FALSE(primitiveChild(mixed, 1)->material());
}

// ---- Errors -------------------------------------------------------------------------------

TEST(NamedQuadrics, ErrorsNameFileLineFunctionAndParameter) {
  struct Case {
    const char* source;
    const char* expected;
  } cases[] = {
      {"return hyperboloid1{a=1, b=2}", "part.lua:1: hyperboloid1: needs c"},
      {"\nreturn elliptic_cone{a=1, b=-2, c=1}",
       "part.lua:2: elliptic_cone: b must be > 0 (got -2)"},
      {"return hyperboloid2{a=0, b=1, c=1}", "part.lua:1: hyperboloid2: a must be > 0 (got 0)"},
      {"return elliptic_paraboloid{a=1, b=0/0}",
       "part.lua:1: elliptic_paraboloid: b must be finite"},
      {"return hyperbolic_paraboloid{a=math.huge, b=1}",
       "part.lua:1: hyperbolic_paraboloid: a must be finite"},
      {"return elliptic_cylinder{a='2', b=1}",
       "part.lua:1: elliptic_cylinder: a must be a number, got string"},
      {"return hyperbolic_cylinder{a=1, b=1, c=1}",
       "part.lua:1: hyperbolic_cylinder: unknown parameter 'c'"},
      {"return hyperboloid1{a=1, b=2, cc=3}", "part.lua:1: hyperboloid1: unknown parameter 'cc'"},
      {"return hyperboloid2{1, 2, 3}", "part.lua:1: hyperboloid2: unexpected value without a name"},
      {"return hyperboloid1{a=1e-200, b=1, c=1}",
       "part.lua:1: hyperboloid1: a = 1e-200 is out of range"},
      {"return elliptic_cone{a=1, b=1, c=1e200}",
       "part.lua:1: elliptic_cone: c = 1e+200 is out of range"},
      {"return parabolic_cylinder{p=0}", "part.lua:1: parabolic_cylinder: p must not be 0"},
      {"return parabolic_cylinder{}", "part.lua:1: parabolic_cylinder: needs p"},
      {"return parabolic_cylinder{p=1/0}", "part.lua:1: parabolic_cylinder: p must be finite"},
  };
  for (const Case& c : cases)
    EXPECT_NE(scriptError(c.source).find(c.expected), std::string::npos)
        << c.source << "\n  gave: " << scriptError(c.source);
}

TEST(Clip, ErrorsNameFileLineAndClip) {
  const std::string s = "local s = elliptic_cylinder{a=1, b=1}\n";
  struct Case {
    std::string source;
    const char* expected;
  } cases[] = {
      {s + "return clip()", "part.lua:2: clip: needs a solid"},
      {s + "return clip(s)", "part.lua:2: clip: needs a box {lo=, hi=}"},
      {s + "return clip(3, {lo={0, 0, 0}, hi={1, 1, 1}})",
       "part.lua:2: clip: the first argument must be a solid, got number"},
      {s + "return clip(s, {lo={0, 0, 0}, hi={1, 0, 1}})",
       "part.lua:2: clip: lo must be below hi on every axis (y: 0 >= 0)"},
      {s + "return clip(s, {lo={0, 0, 2}, hi={1, 1, 1}})",
       "part.lua:2: clip: lo must be below hi on every axis (z: 2 >= 1)"},
      {s + "return clip(s, {lo={0, 0, 0}})", "part.lua:2: clip: needs hi"},
      {s + "return clip(s, {hi={1, 1, 1}})", "part.lua:2: clip: needs lo"},
      {s + "return clip(s, {lo={0, 0}, hi={1, 1, 1}})",
       "part.lua:2: clip: lo must be a list of three numbers"},
      {s + "return clip(s, {lo={0, 0, 0}, hi={1, 1, 1}, size=3})",
       "part.lua:2: clip: unknown parameter 'size'"},
      {s + "return clip(s, {lo={-1e308, 0, 0}, hi={1e308, 1, 1}})",
       "part.lua:2: clip: the box is too large along x"},
      {s + "return clip(s, {sphere(1), 3})",
       "part.lua:2: clip: cutter 2 must be a solid, got number"},
      {s + "return clip(s, {})", "part.lua:2: clip: the second argument is empty"},
      {s + "return clip(s, 5)",
       "part.lua:2: clip: the second argument must be {lo=, hi=}, a solid or a list of solids, got "
       "number"},
      {s + "return clip(s, {lo={0, 0, 0}, hi={1, 1, 1}}, 3)",
       "part.lua:2: clip: takes two arguments"},
      {s + "return clip(s, plane{})",
       "part.lua:2: clip: the second argument must be a solid, but a"},
      {s + "return clip(s, {plane{}})", "part.lua:2: clip: cutter 1 must be a solid, but a"},
  };
  for (const Case& c : cases)
    EXPECT_NE(scriptError(c.source).find(c.expected), std::string::npos)
        << c.source << "\n  gave: " << scriptError(c.source);
}

// The example is a scene with its own camera, and every object in it is
// bounded by clip.
TEST(NamedQuadrics, ExampleIsASceneOfBoundedParts) {
  Scene scene = runScriptFile(CSGRAY_SOURCE_DIR "/examples/quadrics.lua");
  EXPECT_GE(scene.objects.size(), 8u);
  EXPECT_TRUE(scene.camera.has_value());
  for (const SolidPtr& s : scene.objects) EXPECT_TRUE(s->bounds().finite()) << s->kind();
}

}  // namespace
}  // namespace csgray::detail
