// The ground shadow's grid (raytrace/ground_shadow_grid.h): corners traced
// once each, smoothed over their neighbours and interpolated bilinearly;
// nothing outside the grid or across a sharp step; no grid past its size
// limit.
#include "raytrace/ground_shadow_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

namespace csgray::detail {
namespace {

TEST(GroundShadowGrid, SmoothsAndInterpolatesCornersTracedOnce) {
  // Cells of 0.5 over [0, 4] × [0, 2]: 9 × 5 corners.
  const GroundShadowGrid grid({0.0, 0.0}, {4.0, 2.0}, 0.5, 100);
  ASSERT_TRUE(grid.made());
  std::map<std::pair<double, double>, int> traced;
  // A slope gentle enough to interpolate: the mean over a symmetric
  // neighbourhood and bilinear interpolation both keep a bilinear function.
  auto share = [](const dvec3& p) { return 0.02 * p.x + 0.01 * p.y + 0.005 * p.x * p.y; };
  auto trace = [&](const dvec3& p) {
    EXPECT_EQ(p.z, -1.0);
    ++traced[{p.x, p.y}];
    return share(p);
  };
  // Both in the cell from (1, 0.5) to (1.5, 1), whose smoothed corners
  // have all their neighbours in the grid.
  for (const dvec3& p : {dvec3(1.2, 0.7, -1.0), dvec3(1.3, 0.9, -1.0)}) {
    EXPECT_TRUE(grid.holds(p));
    const std::optional<double> hidden = grid.at(p, -1.0, trace);
    ASSERT_TRUE(hidden);
    EXPECT_NEAR(*hidden, share(p), 1e-6);
  }
  // The 4 × 4 corners about the cell, each once.
  EXPECT_EQ(traced.size(), 16u);
  for (const auto& [corner, times] : traced) EXPECT_EQ(times, 1);
  EXPECT_EQ(traced.count({0.5, 0.0}), 1u);
  EXPECT_EQ(traced.count({2.0, 1.5}), 1u);
  // At the grid's edge the neighbourhood is cut short, and the share stays
  // within the corners' range.
  const std::optional<double> edge = grid.at({3.99, 1.99, -1.0}, -1.0, trace);
  ASSERT_TRUE(edge);
  EXPECT_GE(*edge, share({3.0, 1.0, 0.0}));
  EXPECT_LE(*edge, share({4.0, 2.0, 0.0}));
  EXPECT_FALSE(grid.holds({-0.1, 1.0, -1.0}));
  EXPECT_FALSE(grid.at({-0.1, 1.0, -1.0}, -1.0, trace));
  EXPECT_FALSE(grid.at({1.0, 2.5, -1.0}, -1.0, trace));
}

// The mean over 3 × 3 corners takes most of the grain out of traced shares
// that scatter about the true one (each a sum over a few sky points).
TEST(GroundShadowGrid, SmoothingTakesTheGrainOut) {
  const GroundShadowGrid grid({0.0, 0.0}, {10.0, 10.0}, 0.25, 10'000);
  auto truth = [](const dvec3& p) { return 0.3 + 0.02 * p.x; };
  // Grain of ±0.05, the same at a corner whenever it is asked.
  auto trace = [&](const dvec3& p) {
    return truth(p) + 0.05 * std::sin(12.9898 * p.x + 78.233 * p.y * p.y + 4.1 * p.x * p.y);
  };
  double squares = 0.0;
  int n = 0;
  for (double x = 1.0; x < 9.0; x += 0.37)
    for (double y = 1.0; y < 9.0; y += 0.41) {
      const dvec3 p(x, y, 0.0);
      const std::optional<double> hidden = grid.at(p, 0.0, trace);
      ASSERT_TRUE(hidden) << x << " " << y;
      squares += (*hidden - truth(p)) * (*hidden - truth(p));
      ++n;
    }
  // A corner's own grain has an RMS of 0.035; the smoothed share's is far less.
  EXPECT_LT(std::sqrt(squares / n), 0.015);
}

TEST(GroundShadowGrid, ASharpStepIsLeftToTheCaller) {
  const GroundShadowGrid grid({0.0, 0.0}, {4.0, 4.0}, 1.0, 100);
  // A step of 0.4 between two columns of corners, the cell's own right
  // side and the column beyond: smoothing moves the corners next to it by
  // 0.4 / 3.
  auto step = [](const dvec3& p) { return p.x < 2.5 ? 0.5 : 0.9; };
  // A steep slope, 0.3 a cell, is interpolated: the mean keeps it.
  auto steep = [](const dvec3& p) { return 0.3 * p.x - 0.1; };
  const GroundShadowGrid sloped({0.0, 0.0}, {4.0, 4.0}, 1.0, 100);
  EXPECT_NEAR(*sloped.at({1.5, 1.5, 0.0}, 0.0, steep), 0.35, 1e-7);
  EXPECT_FALSE(grid.at({1.5, 1.5, 0.0}, 0.0, step));
  EXPECT_TRUE(grid.holds({1.5, 1.5, 0.0}));
  auto gentle = [](const dvec3& p) { return 0.05 * p.x; };
  const GroundShadowGrid other({0.0, 0.0}, {4.0, 4.0}, 1.0, 100);
  EXPECT_NEAR(*other.at({1.5, 1.5, 0.0}, 0.0, gentle), 0.075, 1e-7);
}

TEST(GroundShadowGrid, NoneWhenItWouldBeTooLarge) {
  EXPECT_FALSE(GroundShadowGrid({0.0, 0.0}, {100.0, 100.0}, 0.01, 1'000'000).made());
  EXPECT_TRUE(GroundShadowGrid({0.0, 0.0}, {100.0, 100.0}, 0.1, 1'100'000).made());
}

}  // namespace
}  // namespace csgray::detail
