// sineCosine: the sine and cosine of one angle within one unit in the last
// place, held against the long double functions, over the angles a
// twisted extrusion turns through.
#include "engine/solvers/sine_cosine.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

namespace csgray::detail {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// The error in units of the reference's last place (of the smallest
// normal double's, for a reference of 0).
double ulps(double value, long double reference) {
  const double magnitude =
      std::max(std::abs(double(reference)), std::numeric_limits<double>::min());
  return double(std::abs(value - reference)) / (kEpsilon * magnitude);
}

void expectWithinOneUlp(double x) {
  const SineCosine sc = sineCosine(x);
  const long double lx = x;
  EXPECT_LE(ulps(sc.sin, std::sin(lx)), 1.0) << "sin of " << x;
  EXPECT_LE(ulps(sc.cos, std::cos(lx)), 1.0) << "cos of " << x;
}

TEST(SineCosine, ExactAtZero) {
  EXPECT_EQ(sineCosine(0.0).sin, 0.0);
  EXPECT_EQ(sineCosine(0.0).cos, 1.0);
}

TEST(SineCosine, WithinOneUlpOverATwistsAngles) {
  // Up to the largest twist, 1 000 turns; small angles down to 1e-12.
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> angle(-6300.0, 6300.0), unit(-1.0, 1.0);
  for (int i = 0; i < 200000; ++i) {
    expectWithinOneUlp(angle(random));
    expectWithinOneUlp(unit(random));
    expectWithinOneUlp(1e-12 * unit(random));
  }
}

TEST(SineCosine, WithinOneUlpNearTheQuadrantsEnds) {
  // Where the reduction cancels most: near multiples of π/2, where one of
  // the two is near 0 and is held to its own last place.
  for (int k = -4000; k <= 4000; ++k) {
    const double x = k * (std::numbers::pi / 2);
    expectWithinOneUlp(x);
    expectWithinOneUlp(std::nextafter(x, std::numeric_limits<double>::infinity()));
    expectWithinOneUlp(k * (std::numbers::pi / 4));
  }
}

// sineCosineBeside: the angle sum from a's sine and cosine (each within an
// ulp) and e's (Taylor series to 1e-19 for |e| <= 1/8, sineCosine beyond):
// two products and a sum, each rounded, so within 2.5 units of 2⁻⁵³
// of the exact value (1.25 ε) plus the inputs' own errors (ε/2 each):
// 2.25 ε in all, absolute, since the values are at most 1.
TEST(SineCosine, BesideAnAngleWithinAFewUnitsOfRounding) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> angle(-6300.0, 6300.0), unit(-1.0, 1.0);
  double worst = 0.0;
  for (int i = 0; i < 200000; ++i) {
    const double a = angle(random);
    // Steps within the series' reach, at its edge, and beyond it.
    for (double e : {0.125 * unit(random), std::copysign(0.125, unit(random)), 3.0 * unit(random),
                     1e-9 * unit(random), 0.0}) {
      const SineCosine sc = sineCosineBeside(sineCosine(a), e);
      const long double exact = (long double)a + (long double)e;
      worst = std::max({worst, std::abs(double(sc.sin - std::sin(exact))),
                        std::abs(double(sc.cos - std::cos(exact)))});
    }
  }
  EXPECT_LE(worst, 2.25 * kEpsilon);
  // a + 0 is a itself, bit for bit.
  EXPECT_EQ(sineCosineBeside(sineCosine(0.7), 0.0).sin, sineCosine(0.7).sin);
  EXPECT_EQ(sineCosineBeside(sineCosine(0.7), 0.0).cos, sineCosine(0.7).cos);
}

TEST(SineCosine, LargeAnglesFallBackToTheLibrary) {
  for (double x : {1e6, -3.5e7, 1e300}) {
    EXPECT_EQ(sineCosine(x).sin, std::sin(x)) << x;
    EXPECT_EQ(sineCosine(x).cos, std::cos(x)) << x;
  }
  EXPECT_TRUE(std::isnan(sineCosine(std::numeric_limits<double>::quiet_NaN()).sin));
}

}  // namespace
}  // namespace csgray::detail
