// The box of a solid's own points (engine/tight_bounds.h) against the
// analytic boxes: a turned ball's and torus's, a cube less part of it, a
// lens of two balls; empty and unbounded solids.
#include "engine/tight_bounds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine/boolean.h"
#include "primitives/box.h"
#include "primitives/cylinder.h"
#include "primitives/half_space.h"
#include "primitives/sphere.h"
#include "primitives/torus.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

constexpr double kPi = std::numbers::pi;

void expectBox(const Bounds& b, const dvec3& lo, const dvec3& hi, double tolerance = 1e-9) {
  test::expectVecNear(b.lo, lo, tolerance);
  test::expectVecNear(b.hi, hi, tolerance);
}

TEST(TightBounds, ATurnedBallIsItsRadiusEachWay) {
  // Its bounds() are the turned cube's about it: ±5√2 across.
  const SolidPtr ball = Primitive::create<Sphere>(5.0)
                            ->transformed(Affine::rotation(kPi / 4, dvec3(0, 0, 1)))
                            ->transformed(Affine::translation(dvec3(1, 2, 3)));
  expectBox(tightBounds(*ball), dvec3(-4, -3, -2), dvec3(6, 7, 8));
}

TEST(TightBounds, ASmallBallKeepsItsDigits) {
  const SolidPtr ball = Primitive::create<Sphere>(1e-6)
                            ->transformed(Affine::rotation(kPi / 4, dvec3(0, 0, 1)))
                            ->transformed(Affine::translation(dvec3(3e-6, 0, 0)));
  expectBox(tightBounds(*ball), dvec3(2e-6, -1e-6, -1e-6), dvec3(4e-6, 1e-6, 1e-6), 1e-15);
}

TEST(TightBounds, ATurnedTorusReachesRTimesTheSineOfItsTiltPlusr) {
  // A torus (R = 10, r = 2) about z, turned 45° about y: along an axis at
  // angle φ to its own, it reaches R·sin φ + r (the circle of centres
  // grown by the tube).
  const SolidPtr ring =
      Primitive::create<Torus>(10.0, 2.0)->transformed(Affine::rotation(kPi / 4, dvec3(0, 1, 0)));
  const double slanted = 10.0 * std::sqrt(0.5) + 2.0;
  expectBox(tightBounds(*ring), dvec3(-slanted, -12, -slanted), dvec3(slanted, 12, slanted));
}

TEST(TightBounds, ACubeLessHalfOfItIsTheHalfLeft) {
  // OpenSCAD's resize of difference(){cube(20); translate([10,-1,-1]) cube(22);}
  // measures 10 wide; bounds() keep the whole cube.
  const SolidPtr cube = Primitive::create<Box>(dvec3(20.0));
  const SolidPtr cutter =
      Primitive::create<Box>(dvec3(22.0))->transformed(Affine::translation(dvec3(10, -1, -1)));
  const SolidPtr half = differenceOf({cube, cutter});
  EXPECT_EQ(half->bounds().hi.x, 20.0);
  expectBox(tightBounds(*half), dvec3(0.0), dvec3(10, 20, 20));
}

TEST(TightBounds, ALensIsWhereItsBallsOverlap) {
  // Two unit balls 1 apart: the lens is 1 across along x, and √3/2 in
  // radius about it, reached where the spheres meet.
  const SolidPtr a = Primitive::create<Sphere>(1.0);
  const SolidPtr b = Primitive::create<Sphere>(1.0)->transformed(Affine::translation({1, 0, 0}));
  const double r = std::sqrt(3.0) / 2.0;
  expectBox(tightBounds(*intersectionOf({a, b})), dvec3(0, -r, -r), dvec3(1, r, r));
}

TEST(TightBounds, AGearTurnedAtEachToothKeepsItsSize) {
  // gear = (gear + tooth):rotate(0, 0, 10), 36 times: the rays find the
  // gear's 24 across (had its bounds() grown with each turn, to some
  // 4 000 across, a grid of rays over them would have passed it by).
  const SolidPtr tooth =
      Primitive::create<Box>(dvec3(2.5, 1, 2))->transformed(Affine::translation({9.5, -0.5, 0}));
  SolidPtr gear = Primitive::create<Cylinder>(10.0, 10.0, 2.0);
  for (int i = 0; i < 36; ++i)
    gear = unionOf({gear, tooth})->transformed(Affine::rotation(kPi / 18, dvec3(0, 0, 1)));
  expectBox(tightBounds(*gear), dvec3(-12, -12, 0), dvec3(12, 12, 2), 1e-9);
}

TEST(TightBounds, EmptyAndUnboundedSolids) {
  const SolidPtr a = Primitive::create<Sphere>(1.0);
  const SolidPtr far =
      Primitive::create<Sphere>(1.0)->transformed(Affine::translation({1.5, 1.5, 0}));
  // The balls' boxes overlap, the balls (2.1 apart) do not: nothing is
  // met, and the box is bounds() as it is.
  const SolidPtr none = intersectionOf({a, far});
  const Bounds b = tightBounds(*none);
  EXPECT_EQ(b.lo, none->bounds().lo);
  EXPECT_EQ(b.hi, none->bounds().hi);
  // So is a ball whose arithmetic overflows, and one too small for rays
  // across its box to be told apart.
  const SolidPtr huge = Primitive::create<Sphere>(1e300);
  EXPECT_EQ(tightBounds(*huge).hi, huge->bounds().hi);
  const SolidPtr speck = Primitive::create<Sphere>(4.9e-324);
  EXPECT_EQ(tightBounds(*speck).hi, speck->bounds().hi);
  const SolidPtr half = Primitive::create<HalfSpace>(dvec3(0, 0, 1), 0.0);
  EXPECT_FALSE(tightBounds(*half).finite());
}

}  // namespace
}  // namespace csgray::detail
