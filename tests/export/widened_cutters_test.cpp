// Cylinders of one radius cut away across each other, made a hair wider:
// which of them, by how much, and nothing else.
#include "export/widened_cutters.h"

#include <gtest/gtest.h>

#include "engine/boolean.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

// The i-th cutter of a difference: part's children after the first.
const Solid& cutter(const SolidPtr& part, std::size_t i) {
  return *part->asBoolean()->children()[i + 1];
}

TEST(WidenedCutters, EachCylinderThatCrossesAnUnwidenedOneOfItsRadiusIsWider) {
  // Three bores r = 1 through a block, in one difference: along x, along
  // y (meeting the first's axis at (10, 10, 10)) and along z through
  // (10, 10, 10) too. The second meets the first: wider by `by`. The
  // third meets the first (not widened): wider by twice `by`, so that it
  // differs from the second too.
  const SolidPtr part = test::solidOf(
      "local bore = cylinder{r=1, h=30, center=true}\n"
      "return difference(box(20), {bore:rotate(0, 90, 0):translate(10, 10, 10),"
      " bore:rotate(90, 0, 0):translate(10, 10, 10), bore:translate(10, 10, 10)})");
  const double by = 0.01;
  const SolidPtr wider = crossingCuttersWidened(part, by);
  ASSERT_NE(wider, part);
  // Points at a radius between the old and the new, beside each axis.
  EXPECT_TRUE(cutter(wider, 0).contains({0.0, 10.0, 11.0 - 0.5 * by}));  // the first as it was
  EXPECT_FALSE(cutter(wider, 0).contains({0.0, 10.0, 11.0 + 0.5 * by}));
  EXPECT_TRUE(cutter(wider, 1).contains({10.0, 0.0, 11.0 + 0.5 * by}));
  EXPECT_FALSE(cutter(wider, 1).contains({10.0, 0.0, 11.0 + 1.5 * by}));
  EXPECT_TRUE(cutter(wider, 2).contains({11.0 + 1.5 * by, 10.0, 0.0}));
  EXPECT_FALSE(cutter(wider, 2).contains({11.0 + 2.5 * by, 10.0, 0.0}));
  // The part given is as it was.
  EXPECT_FALSE(cutter(part, 1).contains({10.0, 0.0, 11.0 + 0.5 * by}));
}

TEST(WidenedCutters, OtherCuttersAndUnionsStayAsTheyAre) {
  // Parallel bores of one radius; crossing bores of two radii; axes that
  // cross at a distance; axes that meet beyond both bores (an angle
  // bracket's two holes); crossing cylinders united, not cut away.
  for (const char* source :
       {"local bore = cylinder{r=1, h=30, center=true}\n"
        "return box(20) - bore:translate(5, 5, 10) - bore:translate(15, 5, 10)",
        "return box(20) - cylinder{r=1, h=30, center=true}:rotate(0, 90, 0):translate(10, 10, 10)"
        " - cylinder{r=1.5, h=30, center=true}:rotate(90, 0, 0):translate(10, 10, 10)",
        "local bore = cylinder{r=1, h=30, center=true}\n"
        "return box(20) - bore:rotate(0, 90, 0):translate(10, 10, 5)"
        " - bore:rotate(90, 0, 0):translate(10, 10, 15)",
        "return box(30) - cylinder{r=1, h=10}:translate(18, 10, 0)"
        " - cylinder{r=1, h=10}:rotate(0, 90, 0):translate(0, 10, 18)",
        "local rod = cylinder{r=1, h=30, center=true}\n"
        "return rod:rotate(0, 90, 0) + rod:rotate(90, 0, 0)"}) {
    const SolidPtr part = test::solidOf(source);
    EXPECT_EQ(crossingCuttersWidened(part, 0.01), part) << source;
  }
}

}  // namespace
}  // namespace csgray::detail
