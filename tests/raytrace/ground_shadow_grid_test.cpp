// The ground shadow's grid (raytrace/ground_shadow_grid.h): bilinear
// between corners traced once each, nothing outside the grid or across a
// sharp step, and no grid past its size limit.
#include "raytrace/ground_shadow_grid.h"

#include <gtest/gtest.h>

#include <map>
#include <utility>

namespace csgray::detail {
namespace {

TEST(GroundShadowGrid, InterpolatesCornersTracedOnce) {
  // Cells of 0.5 over [0, 4] × [0, 2]: 9 × 5 corners.
  const GroundShadowGrid grid({0.0, 0.0}, {4.0, 2.0}, 0.5, 100);
  ASSERT_TRUE(grid.made());
  std::map<std::pair<double, double>, int> traced;
  // A slope gentle enough to interpolate: bilinear interpolation of a
  // bilinear function is exact.
  auto trace = [&](const dvec3& p) {
    EXPECT_EQ(p.z, -1.0);
    ++traced[{p.x, p.y}];
    return 0.05 * p.x + 0.02 * p.y + 0.01 * p.x * p.y;
  };
  for (const dvec3& p : {dvec3(1.2, 0.7, -1.0), dvec3(1.3, 0.9, -1.0), dvec3(3.99, 1.99, -1.0)}) {
    const std::optional<double> hidden = grid.at(p, -1.0, trace);
    ASSERT_TRUE(hidden);
    EXPECT_NEAR(*hidden, 0.05 * p.x + 0.02 * p.y + 0.01 * p.x * p.y, 1e-6);
  }
  // (1.2, 0.7) and (1.3, 0.9) share their cell: 4 + 4 corners in all.
  EXPECT_EQ(traced.size(), 8u);
  for (const auto& [corner, times] : traced) EXPECT_EQ(times, 1);
  EXPECT_EQ(traced.count({1.0, 0.5}), 1u);
  EXPECT_FALSE(grid.at({-0.1, 1.0, -1.0}, -1.0, trace));
  EXPECT_FALSE(grid.at({1.0, 2.5, -1.0}, -1.0, trace));
}

TEST(GroundShadowGrid, ASharpStepIsLeftToTheCaller) {
  const GroundShadowGrid grid({0.0, 0.0}, {1.0, 1.0}, 1.0, 100);
  auto step = [](const dvec3& p) { return p.x < 0.5 ? 0.0 : 1.0; };
  EXPECT_FALSE(grid.at({0.5, 0.5, 0.0}, 0.0, step));
  auto gentle = [](const dvec3& p) { return 0.1 * p.x; };
  const GroundShadowGrid other({0.0, 0.0}, {1.0, 1.0}, 1.0, 100);
  EXPECT_NEAR(*other.at({0.5, 0.5, 0.0}, 0.0, gentle), 0.05, 1e-7);
}

TEST(GroundShadowGrid, NoneWhenItWouldBeTooLarge) {
  EXPECT_FALSE(GroundShadowGrid({0.0, 0.0}, {100.0, 100.0}, 0.01, 1'000'000).made());
  EXPECT_TRUE(GroundShadowGrid({0.0, 0.0}, {100.0, 100.0}, 0.1, 1'100'000).made());
}

}  // namespace
}  // namespace csgray::detail
