// A ball turned or mirrored is placed unturned for its mesh: the same
// ball, on the points of the ball placed by its move alone.
#include "export/turned_balls.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <string>
#include <vector>

#include "engine/bounds.h"
#include "tessellation/triangle_mesh.h"

namespace csgray::detail {
namespace {

constexpr double kPi = std::numbers::pi;

std::shared_ptr<const Sphere> ball(double r, const Affine& frame) {
  return std::static_pointer_cast<const Sphere>(Primitive::create<Sphere>(r)->withFrame(frame));
}

std::vector<dvec3> pointsOf(const Primitive& primitive) {
  std::vector<dvec3> points = primitive.tessellate(0.01, Bounds::everything()).points;
  std::sort(points.begin(), points.end(), [](const dvec3& a, const dvec3& b) {
    return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
  });
  return points;
}

TEST(TurnedBalls, ATurnedOrMirroredBallIsCutOnTheUnturnedBallsPoints) {
  const Affine move = Affine::translation(dvec3(1, -2, 3));
  struct Case {
    const char* what;
    Affine turn;
    double scale;
  };
  for (const Case& c :
       {Case{"turned over", Affine::rotation(kPi, dvec3(1, 0, 0)), 1.0},
        Case{"turned 37° about z", Affine::rotation(37 * kPi / 180, dvec3(0, 0, 1)), 1.0},
        Case{"turned about a slanted axis", Affine::rotation(1.0, dvec3(1, 2, 3)), 1.0},
        Case{"mirrored", Affine::mirror(dvec3(1, 0, 0)), 1.0},
        Case{"scaled by 2 and turned a quarter",
             Affine::scaling(dvec3(2.0)).then(Affine::rotation(kPi / 2, dvec3(0, 1, 0))), 2.0}}) {
    SCOPED_TRACE(c.what);
    const auto turned = ball(3.0, c.turn.then(move));
    const auto unturned = unturnedBall(*turned, turned->frame());
    ASSERT_NE(unturned, nullptr);
    EXPECT_EQ(pointsOf(*unturned),
              pointsOf(*ball(3.0, Affine::scaling(dvec3(c.scale)).then(move))));
  }
}

TEST(TurnedBalls, AMovedBallOrAnEllipsoidIsLeftAsItIs) {
  const auto moved = ball(3.0, Affine::translation(dvec3(1, 2, 3)));
  EXPECT_EQ(unturnedBall(*moved, moved->frame()), nullptr);
  const auto ellipsoid = ball(3.0, Affine::scaling(dvec3(1, 1, 2)));
  EXPECT_EQ(unturnedBall(*ellipsoid, ellipsoid->frame()), nullptr);
  const auto turnedEllipsoid =
      ball(3.0, Affine::scaling(dvec3(1, 1, 2)).then(Affine::rotation(0.5, dvec3(1, 0, 0))));
  EXPECT_EQ(unturnedBall(*turnedEllipsoid, turnedEllipsoid->frame()), nullptr);
}

}  // namespace
}  // namespace csgray::detail
