// Rotations in degrees: one turn written two ways is one matrix, bit for
// bit, so that solids turned so meet on the same points.
#include "scene/rotation.h"

#include <gtest/gtest.h>

#include <string>

namespace csgray::detail {
namespace {

void expectSameMatrix(const Affine& a, const Affine& b) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_EQ(a.worldFromObject()[c][r], b.worldFromObject()[c][r]);
}

TEST(Rotation, OneTurnWrittenTwoWaysIsOneMatrix) {
  for (double degrees : {10.0, -10.0, 33.25, 95.0, 179.5, -179.5, 180.0}) {
    SCOPED_TRACE(std::to_string(degrees));
    for (double turns : {-2.0, -1.0, 1.0, 3.0}) {
      expectSameMatrix(rotationDegrees(dvec3(0.0, 0.0, degrees + 360.0 * turns)),
                       rotationDegrees(dvec3(0.0, 0.0, degrees)));
      expectSameMatrix(rotationDegrees(degrees + 360.0 * turns, dvec3(1.0, 2.0, 3.0)),
                       rotationDegrees(degrees, dvec3(1.0, 2.0, 3.0)));
    }
  }
  // Half a turn either way.
  expectSameMatrix(rotationDegrees(dvec3(-180.0, 0.0, 0.0)),
                   rotationDegrees(dvec3(180.0, 0.0, 0.0)));
}

TEST(Rotation, OppositeTurnsAreMirrorImages) {
  // cos(−a) = cos(a) and sin(−a) = −sin(a), bit for bit, also written
  // past a whole turn (−30° as 330°).
  for (double degrees : {30.0, 72.0, 95.0, 123.4}) {
    SCOPED_TRACE(std::to_string(degrees));
    const glm::dmat4 a = rotationDegrees(dvec3(0.0, 0.0, degrees)).worldFromObject();
    const glm::dmat4 b = rotationDegrees(dvec3(0.0, 0.0, 360.0 - degrees)).worldFromObject();
    EXPECT_EQ(a[0][0], b[0][0]);
    EXPECT_EQ(a[0][1], -b[0][1]);
    EXPECT_EQ(a[1][0], -b[1][0]);
    EXPECT_EQ(a[1][1], b[1][1]);
  }
}

TEST(Rotation, TurnsMirroredAcrossAQuarterShareTheirSinesAndCosines) {
  // A turn by 180° − a is a turn by a mirrored in x: its cosine the other's
  // negated, its sine the same, bit for bit (a pin turned to 135° and
  // mirrored fills a hole turned to 45°); so are a and 90° − a, their sine
  // and cosine swapped. 30° and 60° have the exact half.
  for (double degrees : {10.0, 30.0, 33.0, 45.0, 60.0, 72.5, 89.0}) {
    SCOPED_TRACE(std::to_string(degrees));
    const glm::dmat4 a = rotationDegrees(dvec3(0.0, 0.0, degrees)).worldFromObject();
    const glm::dmat4 b = rotationDegrees(dvec3(0.0, 0.0, 180.0 - degrees)).worldFromObject();
    const glm::dmat4 c = rotationDegrees(dvec3(0.0, 0.0, 90.0 - degrees)).worldFromObject();
    EXPECT_EQ(a[0][0], -b[0][0]);
    EXPECT_EQ(a[0][1], b[0][1]);
    EXPECT_EQ(a[0][0], c[0][1]);
    EXPECT_EQ(a[0][1], c[0][0]);
  }
  EXPECT_EQ(rotationDegrees(dvec3(0.0, 0.0, 60.0)).worldFromObject()[0][0], 0.5);
  EXPECT_EQ(rotationDegrees(dvec3(30.0, 0.0, 0.0)).worldFromObject()[2][1], -0.5);
}

}  // namespace
}  // namespace csgray::detail
