// loopsMeet: loops that cross, touch or fold back meet; simple loops apart,
// or one inside another, do not.
#include "tessellation/loop_crossings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

namespace csgray::detail {
namespace {

using Loops = std::vector<std::vector<dvec2>>;

std::vector<dvec2> square(double x, double y, double side, bool clockwise = false) {
  std::vector<dvec2> loop = {{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}};
  if (clockwise) std::swap(loop[1], loop[3]);
  return loop;
}

TEST(LoopsMeet, SimpleLoopsApartOrNestedDoNot) {
  EXPECT_FALSE(loopsMeet({square(0, 0, 1)}));
  EXPECT_FALSE(loopsMeet({square(0, 0, 1), square(2, 0, 1)}));
  EXPECT_FALSE(loopsMeet({square(0, 0, 4), square(1, 1, 2, true)}));
  // A polygon of many points, a regular 1000-gon, with a hole.
  std::vector<dvec2> many, hole;
  for (int k = 0; k < 1000; ++k) {
    const double a = 2.0 * 3.141592653589793 * k / 1000;
    many.emplace_back(std::cos(a), std::sin(a));
    // Clockwise, its points half a step from the outline's.
    const double b = -2.0 * 3.141592653589793 * (k + 0.5) / 1000;
    hole.emplace_back(0.999 * std::cos(b), 0.999 * std::sin(b));
  }
  EXPECT_FALSE(loopsMeet({many, hole}));
  // The hole grown to 0.999999: its points stand out of the outline's
  // edges, whose middles lie at cos(π/1000) = 0.999995.
  for (dvec2& p : hole) p *= 0.999999 / 0.999;
  EXPECT_TRUE(loopsMeet({many, hole}));
}

TEST(LoopsMeet, CrossingTouchingAndFoldingBackDo) {
  // A bow tie crosses itself.
  EXPECT_TRUE(loopsMeet({{{0, 0}, {1, 1}, {1, 0}, {0, 1}}}));
  // Squares corner to corner, and side against side.
  EXPECT_TRUE(loopsMeet({square(0, 0, 1), square(1, 1, 1)}));
  EXPECT_TRUE(loopsMeet({square(0, 0, 1), square(1, 0.5, 1)}));
  // A hole whose corner is on the outline.
  EXPECT_TRUE(loopsMeet({square(0, 0, 4), {{0, 2}, {2, 3}, {2, 1}}}));
  // A spike: the loop runs out along a line and back over it.
  EXPECT_TRUE(loopsMeet({{{0, 0}, {3, 0}, {2, 0}, {2, 1}, {0, 1}}}));
  // A loop through one point twice.
  EXPECT_TRUE(loopsMeet({{{0, 0}, {2, 0}, {1, 1}, {2, 2}, {0, 2}, {1, 1}}}));
}

}  // namespace
}  // namespace csgray::detail
