// unitCircleDegrees: the corners of polygons that stand in for circles lie
// exactly on the axes and mirror each other bit for bit.
#include "engine/degrees.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace csgray::detail {
namespace {

TEST(UnitCircleDegrees, ExactOnTheAxes) {
  EXPECT_EQ(unitCircleDegrees(0.0), dvec2(1.0, 0.0));
  EXPECT_EQ(unitCircleDegrees(90.0), dvec2(0.0, 1.0));
  EXPECT_EQ(unitCircleDegrees(180.0), dvec2(-1.0, 0.0));
  EXPECT_EQ(unitCircleDegrees(270.0), dvec2(0.0, -1.0));
  EXPECT_EQ(unitCircleDegrees(360.0), dvec2(1.0, 0.0));
  EXPECT_EQ(unitCircleDegrees(-90.0), dvec2(0.0, -1.0));
  EXPECT_EQ(unitCircleDegrees(720.0 + 90.0), dvec2(0.0, 1.0));
  EXPECT_EQ(unitCircleDegrees(30.0).y, 0.5);
  EXPECT_EQ(unitCircleDegrees(60.0).x, 0.5);
}

TEST(UnitCircleDegrees, MirrorImagesAreExact) {
  // The corners of a 16-gon: a corner at a and its images at 180° − a,
  // 180° + a and −a differ only in sign.
  for (int j = 0; j < 16; ++j) {
    const double a = 360.0 * j / 16;
    const dvec2 p = unitCircleDegrees(a);
    EXPECT_EQ(unitCircleDegrees(180.0 - a), dvec2(-p.x, p.y)) << a;
    EXPECT_EQ(unitCircleDegrees(180.0 + a), dvec2(-p.x, -p.y)) << a;
    EXPECT_EQ(unitCircleDegrees(-a), dvec2(p.x, -p.y)) << a;
    EXPECT_EQ(unitCircleDegrees(90.0 - a), dvec2(p.y, p.x)) << a;
  }
}

TEST(UnitCircleDegrees, AgreesWithCosAndSin) {
  for (double a = -400.0; a <= 400.0; a += 0.37) {
    const double r = a * std::numbers::pi / 180.0;
    const dvec2 p = unitCircleDegrees(a);
    // (Past a turn std::sin of the radians is the less accurate one: its
    // argument carries the rounding of a·π/180.)
    EXPECT_NEAR(p.x, std::cos(r), 4e-15) << a;
    EXPECT_NEAR(p.y, std::sin(r), 4e-15) << a;
  }
}

}  // namespace
}  // namespace csgray::detail
