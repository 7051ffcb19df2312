// A cylinder or cone turned upside down or mirrored is the same solid
// placed upright and unmirrored, and it is cut on the points of one placed
// so from the start: an axle turned the other way meets its bore's points.
#include "export/upright_cylinders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <vector>

#include "engine/bounds.h"
#include "tessellation/triangle_mesh.h"

namespace csgray::detail {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTolerance = 0.01;

std::shared_ptr<const Cylinder> frustum(double r1, double r2, double h, const Affine& frame) {
  return std::static_pointer_cast<const Cylinder>(
      Primitive::create<Cylinder>(r1, r2, h)->withFrame(frame));
}

// The points of the primitive's mesh, sorted.
std::vector<dvec3> pointsOf(const Primitive& primitive) {
  std::vector<dvec3> points = primitive.tessellate(kTolerance, Bounds::everything()).points;
  std::sort(points.begin(), points.end(), [](const dvec3& a, const dvec3& b) {
    return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
  });
  return points;
}

struct Turned {
  const char* what;
  Affine frame;    // places the frustum from z = 0 to 10 upside down or mirrored
  Affine upright;  // places it upright over the same place
  bool swapped;    // its radii swapped
};

TEST(UprightCylinders, TurnedOrMirroredFrustumsAreCutOnTheUprightOnesPoints) {
  const Affine down = Affine::translation(dvec3(0, 0, -10));
  const std::vector<Turned> cases = {
      {"half a turn about x", Affine::rotation(kPi, dvec3(1, 0, 0)), down, true},
      {"half a turn about y", Affine::rotation(kPi, dvec3(0, 1, 0)), down, true},
      {"half a turn about z", Affine::rotation(kPi, dvec3(0, 0, 1)), Affine(), false},
      {"mirrored in y", Affine::mirror(dvec3(0, 1, 0)), Affine(), false},
      {"mirrored in z", Affine::mirror(dvec3(0, 0, 1)), down, true},
      // Then turned about its axis: placed there upright and unturned.
      {"half a turn about x, then 60° about z",
       Affine::rotation(kPi, dvec3(1, 0, 0)).then(Affine::rotation(kPi / 3, dvec3(0, 0, 1))), down,
       true},
      {"mirrored in x, then turned 60° about z",
       Affine::mirror(dvec3(1, 0, 0)).then(Affine::rotation(kPi / 3, dvec3(0, 0, 1))), Affine(),
       false},
      {"turned 33.3° about z", Affine::rotation(33.3 * kPi / 180, dvec3(0, 0, 1)), Affine(), false},
      {"mirrored across the diagonal x = y", Affine::mirror(dvec3(1, 1, 0)), Affine(), false},
  };
  for (const Turned& c : cases)
    for (const auto& [r1, r2] : {std::pair(2.0, 2.0), std::pair(2.0, 4.5)}) {
      SCOPED_TRACE(std::string(c.what) + (r1 == r2 ? ", a cylinder" : ", a cone"));
      const auto turned = frustum(r1, r2, 10.0, c.frame);
      const auto upright = uprightCylinder(*turned, turned->frame());
      ASSERT_NE(upright, nullptr);
      // The same solid.
      for (const dvec3& p : {dvec3(0, 0, 0.5), dvec3(1.9, 0, 5), dvec3(0, 1.95, 9.5),
                             dvec3(2.1, 0, 1), dvec3(0, 0, 10.5), dvec3(4.4, 0, 9.9)}) {
        const dvec3 q = c.frame.pointToWorld(p);
        EXPECT_EQ(upright->contains(q), turned->contains(q)) << q.x << " " << q.y << " " << q.z;
      }
      // Cut on the points of the frustum placed upright there.
      const auto expected =
          c.swapped ? frustum(r2, r1, 10.0, c.upright) : frustum(r1, r2, 10.0, c.upright);
      EXPECT_EQ(pointsOf(*upright), pointsOf(*expected));
    }
}

TEST(UprightCylinders, FrustumsTurnedOppositeWaysAreCutOnTheSamePoints) {
  // Along +x from x = 0 to 10: a quarter turn about y one way, and a
  // quarter turn the other way from x = 10 back to 0. Neither is upright;
  // both are placed in the one frame whose axes point along +z, +y, +x.
  for (const auto& [r1, r2] : {std::pair(2.0, 2.0), std::pair(2.0, 4.5)}) {
    SCOPED_TRACE(r1 == r2 ? "a cylinder" : "a cone");
    const auto one = frustum(r1, r2, 10.0, Affine::rotation(kPi / 2, dvec3(0, 1, 0)));
    const auto other = frustum(
        r2, r1, 10.0,
        Affine::rotation(-kPi / 2, dvec3(0, 1, 0)).then(Affine::translation(dvec3(10, 0, 0))));
    const auto a = uprightCylinder(*one, one->frame()), b = uprightCylinder(*other, other->frame());
    ASSERT_NE(a, nullptr);
    ASSERT_NE(b, nullptr);
    EXPECT_EQ(pointsOf(*a), pointsOf(*b));
  }
}

TEST(UprightCylinders, ItsScaleStaysInItsFrame) {
  // r = 3 to 1.5, 4 high, scaled by 2 across and 3 along its axis, turned
  // over: the frustum r = 1.5 to 3 scaled so, standing where its top was
  // (a sweep scaled with it then takes its rim as the two are placed).
  const Affine scale = Affine::scaling(dvec3(2, 2, 3));
  const auto turned = frustum(3.0, 1.5, 4.0, scale.then(Affine::rotation(kPi, dvec3(1, 0, 0))));
  const auto upright = uprightCylinder(*turned, turned->frame());
  ASSERT_NE(upright, nullptr);
  EXPECT_EQ(upright->r1(), 1.5);
  EXPECT_EQ(upright->r2(), 3.0);
  EXPECT_EQ(upright->height(), 4.0);
  EXPECT_EQ(pointsOf(*upright),
            pointsOf(*frustum(1.5, 3.0, 4.0, scale.then(Affine::translation(dvec3(0, 0, -12))))));
  // Scaled but upright: as it is; an elliptic cylinder too.
  const auto scaled = frustum(3.0, 3.0, 4.0, scale);
  EXPECT_EQ(uprightCylinder(*scaled, scaled->frame()), nullptr);
  const auto elliptic = frustum(3.0, 3.0, 4.0, Affine::scaling(dvec3(2, 1, 1)));
  EXPECT_EQ(uprightCylinder(*elliptic, elliptic->frame()), nullptr);
}

TEST(UprightCylinders, TurnedAboutItsAxisItKeepsItsScaleBitForBit) {
  // Scaled by 2.5 across, then turned about its axis by angles whose sines
  // and cosines round: unturned, its radius is 2.5 times its own exactly,
  // the radius of a hole scaled so and not turned.
  const Affine scale = Affine::scaling(dvec3(2.5, 2.5, 1));
  const auto hole = frustum(2.0, 2.0, 4.0, scale);
  for (double degrees : {1.0, 33.3, 95.0, 137.0, 200.0, 301.7}) {
    SCOPED_TRACE(degrees);
    const auto pin =
        frustum(2.0, 2.0, 4.0, scale.then(Affine::rotation(degrees * kPi / 180, dvec3(0, 0, 1))));
    const auto upright = uprightCylinder(*pin, pin->frame());
    ASSERT_NE(upright, nullptr);
    EXPECT_EQ(pointsOf(*upright), pointsOf(*hole));
  }
  // An elliptic cylinder turned about its axis stays turned.
  const auto elliptic =
      frustum(2.0, 2.0, 4.0,
              Affine::scaling(dvec3(2, 1, 1)).then(Affine::rotation(kPi / 5, dvec3(0, 0, 1))));
  EXPECT_EQ(uprightCylinder(*elliptic, elliptic->frame()), nullptr);
}

TEST(UprightCylinders, UprightTiltedOrRoundingFrustumsAreLeftAsTheyAre) {
  const auto none = [](const Affine& frame) {
    const auto c = frustum(2.0, 2.0, 0.7, frame);
    return uprightCylinder(*c, c->frame()) == nullptr;
  };
  EXPECT_TRUE(none(Affine()));
  EXPECT_TRUE(none(Affine::translation(dvec3(1, -2, 3))));
  EXPECT_TRUE(none(Affine::rotation(kPi / 4, dvec3(1, 0, 0))));  // tilted
  EXPECT_TRUE(none(Affine::rotation(1.0, dvec3(1, 2, 3))));      // tilted, none of its axes on one
  // Upside down from z = 0.1: its bottom rim would land at
  // (0.1 − 0.7) + 0.7 = 0.09999999999999998.
  const Affine flipped = Affine::rotation(kPi, dvec3(1, 0, 0));
  EXPECT_TRUE(none(flipped.then(Affine::translation(dvec3(0, 0, 0.1)))));
  EXPECT_FALSE(none(flipped.then(Affine::translation(dvec3(0, 0, 0.3)))));
}

}  // namespace
}  // namespace csgray::detail
