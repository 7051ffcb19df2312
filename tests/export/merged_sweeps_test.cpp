// Sweeps side by side in a union are merged into one sweep of their
// regions' union, and only those: straight extrusions of one height on
// one plane, turns of one angle about one axis; one material, boxes that
// meet, no point where the union touches itself.
#include "export/merged_sweeps.h"

#include <gtest/gtest.h>

#include <array>
#include <string>

#include "engine/boolean.h"
#include "engine/instance.h"
#include "primitives/linear_extrusion.h"
#include "primitives/revolution.h"
#include "profile/region_evaluation.h"
#include "script/script.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

using test::primitivesOf;

SolidPtr mergedOf(const std::string& source) {
  return sweepsMerged(flattened(test::solidOf(source)));
}

TEST(MergedSweeps, SquaresSideBySideAreOneExtrusionOfTheirUnion) {
  const SolidPtr part = mergedOf(
      "local s = {}\n"
      "for i = 0, 3 do s[#s + 1] = linear_extrude{square(2), height = 3}:translate(2 * i, 0, 1) "
      "end\n"
      "return union(table.unpack(s))");
  auto* prism = dynamic_cast<const LinearExtrusion*>(part.get());
  ASSERT_NE(prism, nullptr) << part->kind();
  EXPECT_DOUBLE_EQ(area(evaluate(*prism->region(), 1e-4)), 16.0);
  EXPECT_DOUBLE_EQ(prism->height(), 3.0);
  EXPECT_TRUE(part->contains({7.5, 1.0, 2.0}));
  EXPECT_FALSE(part->contains({8.5, 1.0, 2.0}));
  EXPECT_FALSE(part->contains({1.0, 1.0, 0.5}));  // below: the bottom stays at z = 1
}

TEST(MergedSweeps, CellsGivenTheSameLookEachMerge) {
  // Each cell given its material on its own: equal materials, not one.
  const SolidPtr part = mergedOf(
      "local s = {}\n"
      "for i = 0, 2 do s[#s + 1] = linear_extrude{square(2), height = 3}:translate(2 * i, 0, 0)"
      ":material{color = {1, 0.5, 0}} end\n"
      "return union(table.unpack(s))");
  EXPECT_EQ(primitivesOf(*part), 1);
}

TEST(MergedSweeps, CellsOfAPartTurnedAsAWholeMerge) {
  // The frames are turned by 17° after the move: the moves between them,
  // taken back into the first's plane, are the moves within it to rounding.
  const SolidPtr part = mergedOf(
      "local s = {}\n"
      "for i = 0, 2 do s[#s + 1] = linear_extrude{square(2), height = 3}:translate(2 * i, 0, 0) "
      "end\n"
      "return union(table.unpack(s)):rotate(0, 0, 17):translate(5, 1, 0)");
  EXPECT_EQ(primitivesOf(*part), 1);
}

TEST(MergedSweeps, OnlyLikeExtrusionsThatMeetMerge) {
  // Another height, another material, another plane, a twist, boxes apart:
  // each stays a solid of its own.
  for (const char* other :
       {"linear_extrude{square(2), height = 4}:translate(2, 0, 0)",
        "linear_extrude{square(2), height = 3}:translate(2, 0, 0):material{color = {1, 0, 0}}",
        "linear_extrude{square(2), height = 3}:translate(2, 0, 0.5)",
        "linear_extrude{square(2), height = 3, twist = 10}:translate(2, 0, 0)",
        "linear_extrude{square(2), height = 3}:translate(2.5, 0, 0)",
        "linear_extrude{square(2), height = 3}:rotate(0, 90, 0):translate(4, 0, 0)"}) {
    SCOPED_TRACE(other);
    const SolidPtr part =
        mergedOf(std::string("return linear_extrude{square(2), height = 3} + ") + other);
    EXPECT_EQ(primitivesOf(*part), 2);
  }
}

TEST(MergedSweeps, PrismsWhoseRegionsWouldTouchAtAPointStayApart) {
  // Squares corner to corner, discs side by side: the union's boundary
  // would pass through the point of contact twice, and its sweep be
  // pinched along a line there. Apart, they are solids that touch, which
  // the booleans resolve.
  for (const char* part : {"return linear_extrude{square(2), height = 3} + "
                           "linear_extrude{square(2), height = 3}:translate(2, 2, 0)",
                           "return linear_extrude{circle(1), height = 3} + "
                           "linear_extrude{circle(1), height = 3}:translate(2, 0, 0)"}) {
    SCOPED_TRACE(part);
    EXPECT_EQ(primitivesOf(*mergedOf(part)), 2);
  }
}

TEST(MergedSweeps, ACornerOnAnotherLoopsEdgeIsAPointOfContactToo) {
  // A letter A of two slanted strokes and a bar: the strokes meet only at
  // the apex, where the hole under it touches the outline's top edge.
  const SolidPtr part = mergedOf(
      "local l = polygon({{0, 0}, {1, 0}, {2.5, 6}, {1.5, 6}})\n"
      "local r = polygon({{4, 0}, {5, 0}, {3.5, 6}, {2.5, 6}})\n"
      "local bar = square{size = {3, 0.8}}:translate(1, 2)\n"
      "return union(linear_extrude{l, height = 1}, linear_extrude{r, height = 1}, "
      "linear_extrude{bar, height = 1})");
  EXPECT_EQ(primitivesOf(*part), 3);
}

TEST(MergedSweeps, SweepsMeetThroughOthersInAnyOrder) {
  // A frame of a bottom bar, a top bar and two sides: the bars do not
  // meet each other, the sides join them. Whatever the order of the
  // union, the four are one (a square less a triangle, no point of
  // contact), not the first three, whose union would touch itself at
  // the sides' meeting point.
  const char* bottom = "linear_extrude{square{size = {4, 1}}, height = 1}";
  const char* top = "linear_extrude{square{size = {4, 1}}:translate(0, 3), height = 1}";
  const char* left = "linear_extrude{polygon({{0, 1}, {1, 1}, {2, 3}, {0, 3}}), height = 1}";
  const char* right = "linear_extrude{polygon({{3, 1}, {4, 1}, {4, 3}, {2, 3}}), height = 1}";
  for (const auto& order :
       {std::array{bottom, top, left, right}, std::array{left, right, bottom, top},
        std::array{top, left, bottom, right}}) {
    const std::string source = std::string("return union(") + order[0] + ", " + order[1] + ", " +
                               order[2] + ", " + order[3] + ")";
    SCOPED_TRACE(source);
    const SolidPtr part = mergedOf(source);
    ASSERT_EQ(primitivesOf(*part), 1);
    EXPECT_DOUBLE_EQ(area(evaluate(*dynamic_cast<const LinearExtrusion&>(*part).region(), 1e-4)),
                     14.0);
  }
}

TEST(MergedSweeps, TheStepsOfATurnedPartAreOneTurn) {
  // A stepped shaft: a disc, a collar on it, a shaft on that, each a
  // rotate_extrude of its own moved along the axis.
  const SolidPtr part = mergedOf(
      "return rotate_extrude{square{size = {20, 4}}} + "
      "rotate_extrude{square{size = {8, 6}}}:translate(0, 0, 4) + "
      "rotate_extrude{square{size = {3, 20}}}:translate(0, 0, 10)");
  auto* turn = dynamic_cast<const Revolution*>(part.get());
  ASSERT_NE(turn, nullptr) << part->kind();
  EXPECT_DOUBLE_EQ(area(evaluate(*turn->region(), 1e-4)), 80.0 + 48.0 + 60.0);
  EXPECT_TRUE(part->contains({0.0, 7.5, 9.5}));
  EXPECT_FALSE(part->contains({0.0, 8.5, 9.5}));
  EXPECT_TRUE(part->contains({0.0, 2.5, 29.5}));
}

TEST(MergedSweeps, TurnsOfOtherAnglesOrAxesStayApart) {
  for (const char* other : {"rotate_extrude{square{size = {8, 6}}, angle = 90}:translate(0, 0, 4)",
                            "rotate_extrude{square{size = {8, 6}}}:translate(1, 0, 4)",
                            "linear_extrude{square{size = {8, 6}}, height = 4}"}) {
    SCOPED_TRACE(other);
    EXPECT_EQ(primitivesOf(*mergedOf(
                  std::string("return rotate_extrude{square{size = {20, 4}}} + ") + other)),
              2);
  }
}

TEST(MergedSweeps, APartWithoutSuchPrismsIsLeftAsItIs) {
  const SolidPtr part = flattened(
      test::solidOf("return box(2) + cylinder{r = 1, h = 3} - sphere(1):translate(0, 0, 3)"));
  EXPECT_EQ(sweepsMerged(part), part);
}

TEST(MergedSweeps, PrismsUnderADifferenceMergeInTheirUnion) {
  // The merged union keeps its place: the cut still cuts it.
  const SolidPtr part = mergedOf(
      "return (linear_extrude{square(2), height = 3} + "
      "linear_extrude{square(2), height = 3}:translate(2, 0, 0)) - box(1)");
  EXPECT_EQ(primitivesOf(*part), 2);
  EXPECT_FALSE(part->contains({0.5, 0.5, 0.5}));
  EXPECT_TRUE(part->contains({3.5, 1.0, 2.0}));
}

}  // namespace
}  // namespace csgray::detail
