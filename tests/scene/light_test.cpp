// Lights against their formulas: 1/d² falloff, the Warn spot light's cone
// and cosⁿ falloff, and area lights whose samples cover the light evenly.
#include "scene/light.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

namespace csgray::detail {
namespace {

TEST(Light, PointLightIsConstantWithoutFalloffAndInverseSquareWithIt) {
  Light light;
  light.position = dvec3(0, 0, 10);
  light.color = dvec3(1, 0.5, 0.25);
  light.intensity = 2.0;
  EXPECT_EQ(light.sampleCount(), 1);
  EXPECT_EQ(light.samplePoint(0, 0.3, 0.7, dvec3(0)), light.position);
  EXPECT_EQ(light.radianceAt(dvec3(0), light.position), dvec3(2, 1, 0.5));
  EXPECT_EQ(light.radianceAt(dvec3(5, 5, 0), light.position), dvec3(2, 1, 0.5));
  light.inverseSquare = true;
  // d = 10 and d = 20: a quarter of the light at twice the distance.
  dvec3 near = light.radianceAt(dvec3(0, 0, 0), light.position);
  dvec3 far = light.radianceAt(dvec3(0, 0, -10), light.position);
  EXPECT_DOUBLE_EQ(near.x, 2.0 / 100.0);
  EXPECT_DOUBLE_EQ(far.x, near.x / 4.0);
}

TEST(Light, SpotConeEdgeAndCosineFalloff) {
  Light spot;
  spot.kind = Light::Kind::Spot;
  spot.position = dvec3(0, 0, 10);
  spot.direction = dvec3(0, 0, -2);  // any length
  spot.coneDegrees = 30.0;
  spot.exponent = 3.0;
  const double pi = std::numbers::pi;
  // On the floor z = 0 the cone's edge is a circle of radius 10·tan 30°.
  double edge = 10.0 * std::tan(pi / 6.0);
  EXPECT_GT(spot.radianceAt(dvec3(edge * 0.999, 0, 0), spot.position).x, 0.0);
  EXPECT_EQ(spot.radianceAt(dvec3(edge * 1.001, 0, 0), spot.position).x, 0.0);
  EXPECT_EQ(spot.radianceAt(dvec3(0, 0, 20), spot.position).x, 0.0);  // behind
  // cos³ of the angle off the axis (Warn's model).
  dvec3 p(0, 4, 0);
  double cosine = 10.0 / glm::length(p - spot.position);
  EXPECT_NEAR(spot.radianceAt(p, spot.position).x, std::pow(cosine, 3.0), 1e-12);
  EXPECT_DOUBLE_EQ(spot.radianceAt(dvec3(0), spot.position).x, 1.0);
}

// A soft edge (POV-Ray's radius and falloff): full light within inner,
// none at the cone's edge, smoothstep of the cosine between.
TEST(Light, SpotSoftEdgeFadesBySmoothstep) {
  LightParams p;
  p.kind = Light::Kind::Spot;
  p.position = dvec3(0, 0, 10);
  p.angle = 30.0;
  p.inner = 20.0;
  p.exponent = 0.0;
  const Light spot = makeLight(p);
  const double pi = std::numbers::pi;
  auto at = [&](double degrees) {
    return spot.radianceAt(dvec3(10.0 * std::tan(degrees * pi / 180.0), 0, 0), spot.position).x;
  };
  EXPECT_DOUBLE_EQ(at(0.0), 1.0);
  EXPECT_DOUBLE_EQ(at(19.9), 1.0);
  EXPECT_EQ(at(30.1), 0.0);
  const double c20 = std::cos(20.0 * pi / 180.0), c30 = std::cos(30.0 * pi / 180.0);
  for (double degrees : {21.0, 25.0, 29.0}) {
    const double t = (std::cos(degrees * pi / 180.0) - c30) / (c20 - c30);
    EXPECT_NEAR(at(degrees), t * t * (3.0 - 2.0 * t), 1e-12) << degrees;
  }
  EXPECT_GT(at(21.0), at(25.0));
  EXPECT_GT(at(25.0), at(29.0));
  // Without inner, the edge is hard, as before.
  p.inner.reset();
  EXPECT_DOUBLE_EQ(
      makeLight(p).radianceAt(dvec3(10.0 * std::tan(29.9 * pi / 180.0), 0, 0), spot.position).x,
      1.0);
  p.inner = 40.0;
  EXPECT_THROW(makeLight(p), std::invalid_argument);
}

TEST(Light, RectangleSamplesAreStratifiedOverTheRectangle) {
  Light area;
  area.kind = Light::Kind::Rectangle;
  area.position = dvec3(1, 2, 3);
  area.edgeU = dvec3(4, 0, 0);
  area.edgeV = dvec3(0, 2, 0);
  area.samples = 10;  // rounded to 3 × 3
  ASSERT_EQ(area.sampleCount(), 9);
  int hits[3][3] = {};
  dvec3 mean(0.0);
  for (int i = 0; i < 9; ++i) {
    dvec3 s = area.samplePoint(i, 0.5, 0.5, dvec3(0));
    mean += s / 9.0;
    EXPECT_DOUBLE_EQ(s.z, 3.0);
    int cx = int((s.x - (1 - 2)) / 4 * 3), cy = int((s.y - (2 - 1)) / 2 * 3);
    ASSERT_TRUE(cx >= 0 && cx < 3 && cy >= 0 && cy < 3) << s.x << " " << s.y;
    ++hits[cx][cy];
  }
  for (auto& row : hits)
    for (int h : row) EXPECT_EQ(h, 1);  // one sample in each stratum
  EXPECT_NEAR(glm::length(mean - area.position), 0.0, 1e-12);
  // Corners: jitter (0, 0) and (1, 1) reach the rectangle's corners.
  EXPECT_EQ(area.samplePoint(0, 0.0, 0.0, dvec3(0)), dvec3(-1, 1, 3));
  // The samples share the intensity.
  EXPECT_DOUBLE_EQ(area.radianceAt(dvec3(0), dvec3(1, 2, 3)).x, 1.0 / 9.0);
}

TEST(Light, SphereSamplesLieOnTheDiscFacingThePoint) {
  Light ball;
  ball.kind = Light::Kind::Sphere;
  ball.position = dvec3(0, 0, 10);
  ball.radius = 2.0;
  ball.samples = 16;
  dvec3 p(3, 0, 0);
  dvec3 axis = glm::normalize(p - ball.position);
  double farthest = 0.0;
  for (int i = 0; i < ball.sampleCount(); ++i) {
    dvec3 s = ball.samplePoint(i, 0.999, 0.999, p);
    EXPECT_NEAR(glm::dot(s - ball.position, axis), 0.0, 1e-12);
    EXPECT_LE(glm::length(s - ball.position), 2.0 + 1e-12);
    farthest = std::max(farthest, glm::length(s - ball.position));
  }
  EXPECT_GT(farthest, 1.9);  // the outer strata reach the rim
}

}  // namespace
}  // namespace csgray::detail
