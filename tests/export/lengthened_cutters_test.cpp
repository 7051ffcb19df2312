// Cylinders, cones and turns cut away, made longer past each end: a cone
// goes on along its side, a tip stays where it is, a turn goes on past its
// end faces, and only the cutters that the choice takes change.
#include "export/lengthened_cutters.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "engine/boolean.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

// The cutter of a difference `part` (a solid less one cutter).
const Solid& cutterOf(const SolidPtr& part) { return *part->asBoolean()->children()[1]; }

TEST(LengthenedCutters, AConeGoesOnAlongItsSideAndATipStays) {
  // A cone r = 1 at z = 0 to r = 2 at z = 4, turned by 30° about x, cut
  // from a cylinder of its length (both ends flush); its side widens by
  // a quarter per unit along the axis.
  const SolidPtr part = test::solidOf(
      "return cylinder{r=5, h=4}:rotate(30, 0, 0) - cylinder{r1=1, r2=2, h=4}:rotate(30, 0, 0)");
  const SolidPtr longer = cuttersLengthened(part, 0.4, [](const Primitive&) { return true; });
  ASSERT_NE(longer, part);
  const glm::dmat4 turn = glm::rotate(glm::dmat4(1.0), glm::radians(30.0), glm::dvec3(1, 0, 0));
  auto at = [&](double radius, double z) { return dvec3(turn * glm::dvec4(radius, 0.0, z, 1.0)); };
  const Solid& cone = cutterOf(longer);
  EXPECT_TRUE(cone.contains(at(2.09, 4.38)));   // past the old top, within r = 2.1
  EXPECT_FALSE(cone.contains(at(2.12, 4.38)));  // outside the side going on
  EXPECT_FALSE(cone.contains(at(0.0, 4.42)));   // past the new top
  EXPECT_TRUE(cone.contains(at(0.89, -0.38)));  // below the old bottom, within r = 0.9
  EXPECT_FALSE(cone.contains(at(0.92, -0.38)));
  EXPECT_FALSE(cutterOf(part).contains(at(0.0, 4.2)));  // the part given is as it was

  // A cone to a tip at its top: the tip is not moved, the bottom is.
  const SolidPtr tip = test::solidOf(
      "return box{size=20, center=true}:translate(0, 0, 10) - cylinder{r1=1, r2=0, h=4}");
  const SolidPtr pointedPart = cuttersLengthened(tip, 0.4, [](const Primitive&) { return true; });
  const Solid& pointed = cutterOf(pointedPart);
  EXPECT_FALSE(pointed.contains({0.0, 0.0, 4.1}));
  EXPECT_TRUE(pointed.contains({0.0, 0.0, 3.9}));
  EXPECT_TRUE(pointed.contains({0.0, 0.0, -0.3}));
}

TEST(LengthenedCutters, ATurnGoesOnPastBothEndFaces) {
  // A bend of 60° of a circle r = 2 about ρ = 10, cut from a bend of a
  // circle r = 3 (its end faces flush): its farthest point, at ρ = 12,
  // moves by 0.6 past each end face (2.865°).
  const SolidPtr part = test::solidOf(
      "return rotate_extrude{circle{r=3}:translate(10, 0), angle=60} - "
      "rotate_extrude{circle{r=2}:translate(10, 0), angle=60}");
  const SolidPtr longer = cuttersLengthened(part, 0.6, [](const Primitive&) { return true; });
  const Solid& turn = cutterOf(longer);
  auto at = [](double degrees) {
    return dvec3(10.0 * std::cos(glm::radians(degrees)), 10.0 * std::sin(glm::radians(degrees)),
                 0.0);
  };
  EXPECT_FALSE(cutterOf(part).contains(at(61.0)));
  EXPECT_TRUE(turn.contains(at(61.0)));
  EXPECT_TRUE(turn.contains(at(-1.0)));
  EXPECT_FALSE(turn.contains(at(63.5)));
  EXPECT_FALSE(turn.contains(at(-3.5)));
  EXPECT_TRUE(turn.contains(at(30.0)));
}

TEST(LengthenedCutters, EndsInsideOrOutsideWhatTheyCutStay) {
  // A blind hole (its floor inside the block) and a bore through a block
  // (its ends in the air): neither end crosses the block's surface.
  for (const char* source :
       {"return box{size=20, center=true} - cylinder{r=2, h=15}:rotate(30, 0, 0)",
        "return box{size=20, center=true} - cylinder{r=2, h=60, center=true}:rotate(30, 0, 0)"}) {
    SCOPED_TRACE(source);
    const SolidPtr part = test::solidOf(source);
    EXPECT_EQ(cuttersLengthened(part, 0.5, [](const Primitive&) { return true; }), part);
  }
}

TEST(LengthenedCutters, AnEndInAnotherCutterGoesOn) {
  // Bores whose ends meet in a ball cut with them (a channel's joint):
  // the end at the ball's centre goes on into the ball, the other, in the
  // air past the block, stays.
  const SolidPtr part = test::solidOf(
      "return box{size=30, center=true} - (cylinder{r=2, h=30}:rotate(30, 0, 0) + sphere(3))");
  const SolidPtr longer = cuttersLengthened(part, 0.5, [](const Primitive&) { return true; });
  ASSERT_NE(longer, part);
  const glm::dmat4 turn = glm::rotate(glm::dmat4(1.0), glm::radians(30.0), glm::dvec3(1, 0, 0));
  const Solid& bore = *cutterOf(longer).asBoolean()->children()[0];
  EXPECT_TRUE(bore.contains(dvec3(turn * glm::dvec4(0.0, 0.0, -0.4, 1.0))));
  EXPECT_FALSE(bore.contains(dvec3(turn * glm::dvec4(0.0, 0.0, 30.1, 1.0))));
}

TEST(LengthenedCutters, OnlyTheCuttersChosenAndNothingElse) {
  // The minuend's cylinder keeps its length; a cutter not chosen is the
  // part itself again.
  const SolidPtr part = test::solidOf("return cylinder{r=3, h=2} - cylinder{r=1, h=2}");
  EXPECT_EQ(cuttersLengthened(part, 0.5, [](const Primitive&) { return false; }), part);
  const SolidPtr longer = cuttersLengthened(part, 0.5, [](const Primitive&) { return true; });
  const Solid& kept = *longer->asBoolean()->children()[0];
  EXPECT_FALSE(kept.contains({2.0, 0.0, 2.1}));
  EXPECT_TRUE(cutterOf(longer).contains({0.0, 0.0, 2.4}));
  EXPECT_FALSE(longer->contains({0.0, 0.0, 1.0}));
  EXPECT_TRUE(longer->contains({2.0, 0.0, 1.0}));
}

}  // namespace
}  // namespace csgray::detail
