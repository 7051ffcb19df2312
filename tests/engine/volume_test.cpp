// Volumes from span lengths: integrating the spans of a grid of parallel
// rays (the midpoint rule across, exact along the rays) must give the
// analytic volume of primitives and booleans to within 0.5%. A wrong span
// anywhere on the grid (a lost, doubled or misplaced span) shows up here.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/mat4x4.hpp>
#include <numbers>

#include "engine/boolean.h"
#include "primitives/box.h"
#include "primitives/cylinder.h"
#include "primitives/half_space.h"
#include "primitives/quadric.h"
#include "primitives/sphere.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kGrid = 400;
constexpr double kTolerance = 0.005;  // relative

// Rays along z over the solid's bounds.
double volumeAlongZ(const SolidPtr& s) { return test::gridVolume(*s, s->bounds(), kGrid); }

// Rays along the solid's own x (y) axis: turn the solid so that axis maps to
// z, then use the z grid. A quarter turn about y sends x to -z; one about x
// sends y to z.
double volumeAlongX(const SolidPtr& s) {
  SolidPtr turned = s->transformed(Affine::rotation(kPi / 2, dvec3(0, 1, 0)));
  return test::gridVolume(*turned, turned->bounds(), kGrid);
}
double volumeAlongY(const SolidPtr& s) {
  SolidPtr turned = s->transformed(Affine::rotation(kPi / 2, dvec3(1, 0, 0)));
  return test::gridVolume(*turned, turned->bounds(), kGrid);
}

void expectVolume(const SolidPtr& s, double exact) {
  EXPECT_NEAR(volumeAlongZ(s), exact, kTolerance * exact) << "rays along z";
  EXPECT_NEAR(volumeAlongX(s), exact, kTolerance * exact) << "rays along x";
  EXPECT_NEAR(volumeAlongY(s), exact, kTolerance * exact) << "rays along y";
}

double ballVolume(double r) { return 4.0 / 3.0 * kPi * r * r * r; }

// A spherical cap of height h cut from a ball of radius r: πh²(3r - h)/3.
double capVolume(double r, double h) { return kPi * h * h * (3 * r - h) / 3.0; }

// The lens shared by balls of radii R and r whose centres are d apart
// (R - r < d < R + r):
// V = π (R + r - d)² (d² + 2dr - 3r² + 2dR + 6rR - 3R²) / (12 d).
double lensVolume(double R, double r, double d) {
  return kPi * (R + r - d) * (R + r - d) *
         (d * d + 2 * d * r - 3 * r * r + 2 * d * R + 6 * r * R - 3 * R * R) / (12 * d);
}

SolidPtr sphereAt(double r, const dvec3& c) {
  return Primitive::create<Sphere>(r)->transformed(Affine::translation(c));
}

// The formulas themselves: the lens of equal balls is two caps of height
// (2r - d)/2, and a lens with d → R + r vanishes.
TEST(Volume, FormulasAreConsistent) {
  EXPECT_NEAR(lensVolume(1, 1, 1), 2 * capVolume(1, 0.5), 1e-12);
  // Radii 1.2 and 0.8, d = 1: the circle's plane is at x = (d² + R² - r²)/(2d)
  // = 0.9, so the caps have heights 1.2 - 0.9 and 0.8 - 0.1.
  EXPECT_NEAR(lensVolume(1.2, 0.8, 1.0), capVolume(1.2, 0.3) + capVolume(0.8, 0.7), 1e-12);
  EXPECT_NEAR(lensVolume(1, 1, 2), 0.0, 1e-12);
  EXPECT_NEAR(capVolume(1, 2), ballVolume(1), 1e-12);
}

// 4/3 π r³.
TEST(Volume, Sphere) { expectVolume(sphereAt(1.5, dvec3(0.3, -0.2, 0.1)), ballVolume(1.5)); }

// 1·2·3, also turned about a skew axis.
TEST(Volume, Box) {
  SolidPtr box = Primitive::create<Box>(dvec3(1, 2, 3))
                     ->transformed(Affine::translation(dvec3(-0.5, 0.25, 1)));
  expectVolume(box, 6.0);
  expectVolume(box->transformed(Affine::rotation(0.5, dvec3(1, 1, 1))), 6.0);
}

// π r² h.
TEST(Volume, Cylinder) {
  expectVolume(Primitive::create<Cylinder>(1.0, 1.0, 2.0), kPi * 2.0);
  expectVolume(Primitive::create<Cylinder>(0.7, 0.7, 0.5)
                   ->transformed(Affine::rotation(0.9, dvec3(1, -2, 0.5))),
               kPi * 0.49 * 0.5);
}

// Frustum: π h/3 (r1² + r1 r2 + r2²); r1 = 2, r2 = 1, h = 4 gives 28π/3.
TEST(Volume, ConeFrustum) {
  expectVolume(Primitive::create<Cylinder>(2.0, 1.0, 4.0), 28.0 * kPi / 3.0);
  expectVolume(Primitive::create<Cylinder>(0.5, 1.5, 1.0), kPi / 3.0 * (0.25 + 0.75 + 2.25));
  // Pointed cones: π r² h / 3.
  expectVolume(Primitive::create<Cylinder>(1.5, 0.0, 2.0), kPi * 2.25 * 2.0 / 3.0);
  expectVolume(Primitive::create<Cylinder>(0.0, 1.0, 3.0), kPi * 3.0 / 3.0);
}

// Sphere(1) scaled by (3, 2, 1): 4/3 π abc = 8π; the same ellipsoid as the
// quadric diag(1/9, 1/4, 1, -1).
TEST(Volume, Ellipsoid) {
  expectVolume(Primitive::create<Sphere>(1.0)->transformed(Affine::scaling(dvec3(3, 2, 1))),
               8.0 * kPi);
  glm::dmat4 m(0.0);
  m[0][0] = 1.0 / 9.0;
  m[1][1] = 0.25;
  m[2][2] = 1.0;
  m[3][3] = -1.0;
  expectVolume(Primitive::create<Quadric>(m), 8.0 * kPi);
}

// Box [0, 4]³ minus a ball of radius 1 wholly inside: 64 - 4/3 π.
TEST(Volume, BoxMinusInnerSphere) {
  SolidPtr box = Primitive::create<Box>(dvec3(4.0));
  expectVolume(differenceOf({box, sphereAt(1.0, dvec3(2.0))}), 64.0 - ballVolume(1.0));
}

// Box [0, 4]³ minus a ball of radius 1.5 centred 0.5 outside the face
// x = 4: only a cap of height 1.5 - 0.5 = 1 is removed (its base circle,
// radius sqrt(2), lies inside the face).
TEST(Volume, BoxMinusSphereOnFace) {
  SolidPtr box = Primitive::create<Box>(dvec3(4.0));
  expectVolume(differenceOf({box, sphereAt(1.5, dvec3(4.5, 2, 2))}), 64.0 - capVolume(1.5, 1.0));
  // And several at once (n-ary difference): the inner ball and the cap.
  expectVolume(differenceOf({box, sphereAt(1.0, dvec3(2.0)), sphereAt(1.5, dvec3(4.5, 2, 2))}),
               64.0 - ballVolume(1.0) - capVolume(1.5, 1.0));
}

// A 4 × 4 × 2 plate with a through hole of radius 1: 32 - 2π.
TEST(Volume, PlateWithHole) {
  SolidPtr plate = Primitive::create<Box>(dvec3(4, 4, 2));
  SolidPtr hole =
      Primitive::create<Cylinder>(1.0, 1.0, 4.0)->transformed(Affine::translation(dvec3(2, 2, -1)));
  expectVolume(differenceOf({plate, hole}), 32.0 - 2.0 * kPi);
}

// Two unit balls with centres 1 apart: union 2·4/3 π - lens, intersection
// the lens, lens = π(4r + d)(2r - d)²/12 = 5π/12.
TEST(Volume, UnionOfOverlappingSpheres) {
  SolidPtr a = sphereAt(1.0, dvec3(0.0)), b = sphereAt(1.0, dvec3(1.0, 0, 0));
  EXPECT_NEAR(lensVolume(1, 1, 1), 5.0 * kPi / 12.0, 1e-12);
  expectVolume(unionOf({a, b}), 2.0 * ballVolume(1.0) - lensVolume(1, 1, 1));
  // Disjoint balls: the sum.
  expectVolume(unionOf({a, sphereAt(0.5, dvec3(3, 1, 0))}), ballVolume(1.0) + ballVolume(0.5));
}

TEST(Volume, IntersectionOfSpheres) {
  dvec3 offset = glm::normalize(dvec3(1, 0.5, -0.3));
  expectVolume(intersectionOf({sphereAt(1.0, dvec3(0.0)), sphereAt(1.0, offset)}),
               lensVolume(1, 1, 1));
  expectVolume(intersectionOf({sphereAt(1.2, dvec3(0.0)), sphereAt(0.8, dvec3(1.0, 0, 0))}),
               lensVolume(1.2, 0.8, 1.0));
  // Ball minus ball is the ball minus the lens.
  expectVolume(differenceOf({sphereAt(1.2, dvec3(0.0)), sphereAt(0.8, dvec3(1.0, 0, 0))}),
               ballVolume(1.2) - lensVolume(1.2, 0.8, 1.0));
}

// Cutting with unbounded half-spaces: the cap z >= 0.5 of the unit ball is
// πh²(3r - h)/3 with h = 0.5; the ball minus z <= 0 is a hemisphere.
TEST(Volume, SphereCutByHalfSpace) {
  SolidPtr ball = Primitive::create<Sphere>(1.0);
  SolidPtr above = Primitive::create<HalfSpace>(dvec3(0, 0, -1), -0.5);  // z >= 0.5
  expectVolume(intersectionOf({ball, above}), capVolume(1.0, 0.5));
  expectVolume(differenceOf({ball, Primitive::create<HalfSpace>(dvec3(0, 0, 1), 0.0)}),
               ballVolume(1.0) / 2.0);
}

// Unbounded quadrics clipped by a box: the quadric cylinder x² + y² <= 1
// over z in [0, 3] is 3π; the upper sheet of x² + y² - z² + 1 <= 0 over
// z in [0, 2] is ∫₁² π(z² - 1) dz = 4π/3.
TEST(Volume, UnboundedQuadricsClippedByBox) {
  glm::dmat4 cyl(0.0);
  cyl[0][0] = cyl[1][1] = 1.0;
  cyl[3][3] = -1.0;
  SolidPtr box =
      Primitive::create<Box>(dvec3(4, 4, 3))->transformed(Affine::translation(dvec3(-2, -2, 0)));
  expectVolume(intersectionOf({Primitive::create<Quadric>(cyl), box}), 3.0 * kPi);
  glm::dmat4 two(0.0);
  two[0][0] = two[1][1] = two[3][3] = 1.0;
  two[2][2] = -1.0;
  SolidPtr slab =
      Primitive::create<Box>(dvec3(6, 6, 2))->transformed(Affine::translation(dvec3(-3, -3, 0)));
  expectVolume(intersectionOf({Primitive::create<Quadric>(two), slab}), 4.0 * kPi / 3.0);
}

}  // namespace
}  // namespace csgray::detail
