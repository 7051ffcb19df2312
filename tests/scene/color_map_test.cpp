// Colour maps: linear between stops, constant past the ends, a sharp edge
// where two stops share a place, and the checks of what a user gives.
#include "scene/color_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "test_support.h"

namespace csgray::detail {
namespace {

using test::expectVecNear;

const dvec3 kRed(1, 0, 0), kGreen(0, 1, 0), kBlue(0, 0, 1);

TEST(ColorMap, TwoColoursBlendFromZeroToOne) {
  const ColorMap map(kRed, kBlue);
  expectVecNear(map.at(0.0), kRed, 0.0);
  expectVecNear(map.at(0.25), dvec3(0.75, 0, 0.25), 1e-15);
  expectVecNear(map.at(1.0), kBlue, 0.0);
  expectVecNear(map.at(-3.0), kRed, 0.0);
  expectVecNear(map.at(7.0), kBlue, 0.0);
  expectVecNear(map.at(std::numeric_limits<double>::quiet_NaN()), kRed, 0.0);
}

TEST(ColorMap, StopsBlendPiecewiseAndTwoAtOnePlaceMakeAnEdge) {
  const ColorMap map({{0.2, kRed}, {0.6, kGreen}, {0.6, kBlue}, {0.8, dvec3(1.0)}}, "gradient");
  expectVecNear(map.at(0.1), kRed, 0.0);  // before the first stop
  expectVecNear(map.at(0.3), dvec3(0.75, 0.25, 0), 1e-15);
  expectVecNear(map.at(0.6 - 1e-12), kGreen, 1e-9);
  expectVecNear(map.at(0.6), kBlue, 0.0);  // the edge: the later stop's colour
  expectVecNear(map.at(0.7), dvec3(0.5, 0.5, 1), 1e-15);
  expectVecNear(map.at(0.95), dvec3(1.0), 0.0);  // after the last
  const ColorMap even = ColorMap::evenly({kRed, kGreen, kBlue}, "perlin");
  expectVecNear(even.at(0.5), kGreen, 0.0);
  expectVecNear(even.at(0.75), dvec3(0, 0.5, 0.5), 1e-15);
}

std::string refusal(std::vector<ColorStop> stops) {
  try {
    ColorMap(std::move(stops), "marble");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(ColorMap, StopsAreChecked) {
  EXPECT_EQ(refusal({{0.0, kRed}}), "marble: colors must be from 2 to 256 colours, not 1");
  EXPECT_EQ(refusal({{0.0, kRed}, {1.5, kBlue}}),
            "marble: colors[2]: a stop's place must be in [0, 1]");
  EXPECT_EQ(refusal({{0.5, kRed}, {0.2, kBlue}}),
            "marble: colors[2]: stops must be in order of their places");
  EXPECT_EQ(refusal({{0.0, kRed}, {1.0, dvec3(-1, 0, 0)}}),
            "marble: colors components must be >= 0");
  EXPECT_EQ(refusal({{0.0, kRed}, {std::nan(""), kBlue}}),
            "marble: colors[2]: a stop's place must be in [0, 1]");
  EXPECT_EQ(refusal(std::vector<ColorStop>(257, {0.5, kRed})),
            "marble: colors must be from 2 to 256 colours, not 257");
}

}  // namespace
}  // namespace csgray::detail
