// Geometric optics against the laws they implement: Snell's law in the
// plane of incidence, total internal reflection exactly past the critical
// angle, the law of reflection, and the Fresnel equations (normal
// incidence, Brewster's angle, grazing incidence, reciprocity), each
// checked with formulas written independently of raytrace/optics.cpp.
#include "raytrace/optics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <random>

#include "test_support.h"

namespace csgray::detail {
namespace {

constexpr double kPi = std::numbers::pi;

// A unit normal and a unit tangent perpendicular to it, spanning a plane of
// incidence; random so that no axis alignment hides an error.
struct Frame {
  dvec3 n, t;
};

Frame randomFrame(std::mt19937_64& rng) {
  dvec3 n = test::randomDirection(rng);
  dvec3 other = test::randomDirection(rng);
  dvec3 t = glm::normalize(other - glm::dot(other, n) * n);
  return {n, t};
}

// The unit direction that meets the surface (normal n facing against it)
// at angle alpha from the normal, in the plane of n and t.
dvec3 incident(const Frame& f, double alpha) {
  return std::sin(alpha) * f.t - std::cos(alpha) * f.n;
}

// The sine of the angle between a unit direction and the normal line.
double sineToNormal(const dvec3& d, const dvec3& n) { return glm::length(glm::cross(d, n)); }

const std::pair<double, double> kIndexPairs[] = {{1.0, 1.5}, {1.5, 1.0}, {1.0, 1.333}, {1.333, 1.5},
                                                 {2.4, 1.0}, {1.2, 2.4}, {1.0, 1.0}};

TEST(Optics, SnellsLawInThePlaneOfIncidence) {
  std::mt19937_64 rng(7);
  for (auto [n1, n2] : kIndexPairs) {
    for (int k = 0; k < 200; ++k) {
      Frame f = randomFrame(rng);
      double alpha = std::uniform_real_distribution<double>(0.0, 0.5 * kPi - 1e-6)(rng);
      dvec3 d = incident(f, alpha);
      std::optional<dvec3> t = refract(d, f.n, n1, n2);
      bool total = n1 * std::sin(alpha) > n2;
      ASSERT_EQ(t.has_value(), !total) << n1 << " -> " << n2 << " at " << alpha;
      if (!t) continue;
      EXPECT_NEAR(glm::length(*t), 1.0, 1e-12);
      // n1 sin α = n2 sin β.
      double sinBeta = sineToNormal(*t, f.n);
      EXPECT_NEAR(n1 * std::sin(alpha), n2 * sinBeta, 1e-12) << n1 << " -> " << n2 << " " << alpha;
      // The ray goes on through the surface, on the far side of the normal
      // line from where it came (not mirrored back)...
      EXPECT_LT(glm::dot(*t, f.n), 0.0);
      if (alpha > 1e-3) {
        EXPECT_GT(glm::dot(*t, f.t), 0.0);
      }
      // ... and stays in the plane of incidence.
      EXPECT_NEAR(glm::dot(*t, glm::cross(f.n, f.t)), 0.0, 1e-12);
    }
  }
}

TEST(Optics, NormalIncidencePassesStraightAndEqualIndicesDoNotBend) {
  std::mt19937_64 rng(11);
  for (int k = 0; k < 50; ++k) {
    Frame f = randomFrame(rng);
    std::optional<dvec3> t = refract(-f.n, f.n, 1.0, 1.7);
    ASSERT_TRUE(t);
    test::expectVecNear(*t, -f.n, 1e-12);
    dvec3 d = incident(f, 1.2);
    std::optional<dvec3> same = refract(d, f.n, 1.4, 1.4);
    ASSERT_TRUE(same);
    test::expectVecNear(*same, d, 1e-12);
  }
}

TEST(Optics, TotalInternalReflectionExactlyPastTheCriticalAngle) {
  std::mt19937_64 rng(3);
  const std::pair<double, double> denser[] = {{1.5, 1.0}, {1.333, 1.0}, {2.4, 1.5}, {1.5, 1.333}};
  for (auto [n1, n2] : denser) {
    double critical = std::asin(n2 / n1);
    for (int k = 0; k < 20; ++k) {
      Frame f = randomFrame(rng);
      std::optional<dvec3> below = refract(incident(f, critical - 1e-7), f.n, n1, n2);
      std::optional<dvec3> above = refract(incident(f, critical + 1e-7), f.n, n1, n2);
      ASSERT_TRUE(below) << n1 << " -> " << n2;
      EXPECT_FALSE(above) << n1 << " -> " << n2;
      // Just below the critical angle the ray leaves almost along the surface.
      EXPECT_NEAR(sineToNormal(*below, f.n), 1.0, 1e-6);
      // Far past it, and at grazing incidence, still none.
      EXPECT_FALSE(refract(incident(f, 0.5 * (critical + 0.5 * kPi)), f.n, n1, n2));
      EXPECT_FALSE(refract(incident(f, 0.5 * kPi), f.n, n1, n2));
    }
    // Into the denser medium there is no critical angle.
    Frame f = randomFrame(rng);
    EXPECT_TRUE(refract(incident(f, 0.5 * kPi - 1e-9), f.n, n2, n1));
  }
}

TEST(Optics, ReflectionPreservesTheAngle) {
  std::mt19937_64 rng(5);
  for (int k = 0; k < 500; ++k) {
    Frame f = randomFrame(rng);
    double alpha = std::uniform_real_distribution<double>(0.0, 0.5 * kPi)(rng);
    dvec3 d = incident(f, alpha);
    dvec3 r = reflect(d, f.n);
    EXPECT_NEAR(glm::length(r), 1.0, 1e-12);
    // Angle of reflection = angle of incidence, on the other side of the
    // normal line, in the plane of incidence; the tangential part is kept.
    EXPECT_NEAR(glm::dot(r, f.n), std::cos(alpha), 1e-12);
    EXPECT_NEAR(glm::dot(r, f.t), std::sin(alpha), 1e-12);
    EXPECT_NEAR(glm::dot(r, glm::cross(f.n, f.t)), 0.0, 1e-12);
    // Reflecting twice gives the direction back.
    test::expectVecNear(reflect(r, f.n), d, 1e-12);
  }
}

// The Fresnel amplitude coefficients in Fresnel's sine and tangent forms
// (Hecht 4.42, 4.43), independent of the cosine forms of optics.cpp.
double rsOf(double ti, double tt) { return -std::sin(ti - tt) / std::sin(ti + tt); }
double rpOf(double ti, double tt) { return std::tan(ti - tt) / std::tan(ti + tt); }
// The angle of transmission by Snell's law.
double transmitted(double ti, double n1, double n2) { return std::asin(n1 / n2 * std::sin(ti)); }

TEST(Optics, FresnelAtNormalIncidence) {
  for (auto [n1, n2] : kIndexPairs) {
    double expected = std::pow((n1 - n2) / (n1 + n2), 2.0);
    EXPECT_NEAR(fresnelReflectance(1.0, n1, n2), expected, 1e-15) << n1 << " -> " << n2;
    // The sign of the cosine (which side the normal faces) does not matter.
    EXPECT_NEAR(fresnelReflectance(-1.0, n1, n2), expected, 1e-15) << n1 << " -> " << n2;
  }
  EXPECT_NEAR(fresnelReflectance(1.0, 1.0, 1.5), 0.04, 1e-15);
}

TEST(Optics, FresnelMatchesSineAndTangentFormsAtAllAngles) {
  for (auto [n1, n2] : kIndexPairs) {
    if (n1 == n2) continue;
    double limit = n1 > n2 ? std::asin(n2 / n1) : 0.5 * kPi;
    for (int k = 1; k < 100; ++k) {
      double ti = limit * k / 100.0;
      double tt = transmitted(ti, n1, n2);
      double rs = rsOf(ti, tt), rp = rpOf(ti, tt);
      double r = fresnelReflectance(std::cos(ti), n1, n2);
      EXPECT_NEAR(r, 0.5 * (rs * rs + rp * rp), 1e-12) << n1 << " -> " << n2 << " at " << ti;
      EXPECT_GE(r, 0.0);
      EXPECT_LE(r, 1.0);
    }
  }
}

TEST(Optics, FresnelBrewsterAngleHasNoPPolarisedReflection) {
  for (auto [n1, n2] : kIndexPairs) {
    if (n1 == n2) continue;
    double brewster = std::atan(n2 / n1);
    double tt = transmitted(brewster, n1, n2);
    // At Brewster's angle the reflected and refracted rays are perpendicular.
    ASSERT_NEAR(brewster + tt, 0.5 * kPi, 1e-12);
    double rs = rsOf(brewster, tt);
    ASSERT_GT(rs * rs, 1e-3);  // s-polarised light is still reflected
    // The mean of rs² and rp² is rs²/2 only where rp vanishes.
    EXPECT_NEAR(fresnelReflectance(std::cos(brewster), n1, n2), 0.5 * rs * rs, 1e-14)
        << n1 << " -> " << n2;
    // Away from Brewster's angle the p part is not zero: R > rs²/2.
    for (double off : {-0.05, 0.05}) {
      double ti = brewster + off;
      double t2 = transmitted(ti, n1, n2);
      if (std::isnan(t2)) continue;  // past the critical angle
      double s = rsOf(ti, t2);
      EXPECT_GT(fresnelReflectance(std::cos(ti), n1, n2) - 0.5 * s * s, 1e-7);
    }
  }
}

TEST(Optics, FresnelIsOneAtGrazingIncidenceAndPastTheCriticalAngle) {
  for (auto [n1, n2] : kIndexPairs) {
    if (n1 == n2) continue;
    EXPECT_NEAR(fresnelReflectance(0.0, n1, n2), 1.0, 1e-15) << n1 << " -> " << n2;
    // Approaching grazing incidence R tends to 1 continuously.
    EXPECT_GT(fresnelReflectance(std::cos(0.5 * kPi - 1e-4), n1, n2), 0.99);
    if (n1 > n2) {
      double critical = std::asin(n2 / n1);
      for (double ti = critical + 1e-9; ti < 0.5 * kPi; ti += 0.05)
        EXPECT_EQ(fresnelReflectance(std::cos(ti), n1, n2), 1.0) << n1 << " -> " << n2 << " " << ti;
      // Just below the critical angle it is close to 1 but not 1.
      double r = fresnelReflectance(std::cos(critical - 1e-6), n1, n2);
      EXPECT_LT(r, 1.0);
      EXPECT_GT(r, 0.95);
    }
  }
}

// Stokes reciprocity: light going the reverse way, from n2 at the
// transmission angle into n1, is reflected by the same share.
TEST(Optics, FresnelIsReciprocal) {
  for (auto [n1, n2] : kIndexPairs) {
    double limit = n1 > n2 ? std::asin(n2 / n1) : 0.5 * kPi;
    for (int k = 0; k < 100; ++k) {
      double ti = limit * k / 100.0;
      double tt = transmitted(ti, n1, n2);
      EXPECT_NEAR(fresnelReflectance(std::cos(ti), n1, n2),
                  fresnelReflectance(std::cos(tt), n2, n1), 1e-12)
          << n1 << " -> " << n2 << " at " << ti;
    }
  }
}

}  // namespace
}  // namespace csgray::detail
