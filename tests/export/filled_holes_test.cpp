// Holes that a union fills again are left out of the part, and only
// those: (A − B) ∪ C = A ∪ C when B ∩ A ⊆ C.
#include "export/filled_holes.h"

#include <gtest/gtest.h>

#include <string>

#include "engine/boolean.h"
#include "script/script.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

SolidPtr part(const std::string& source) {
  const Scene scene = runScript(source, "part.lua", test::exampleOptions());
  return scene.objects.size() == 1 ? scene.objects[0] : unionOf(scene.objects);
}

// How many differences the tree holds.
int differences(const Solid& solid) {
  int count = 0;
  if (const Boolean* node = solid.asBoolean()) count += node->op() == Boolean::Op::Difference;
  for (const SolidPtr& child : solid.children()) count += differences(*child);
  return count;
}

TEST(FilledHoles, APinThroughAFlushBoreLeavesTheBoreOut) {
  for (const char* source :
       {// through a tube from below its bottom to above its top
        "return cylinder{r=5, h=2} - cylinder{r=1, h=2} + cylinder{r=1, h=4}:translate(0, 0, -1)",
        // a bore longer than the plate, the pin as long as the plate
        "return cylinder{r=5, h=2} - cylinder{r=1, h=10, center=true} + cylinder{r=1, h=2}",
        // a union around the union the cut is in, the pin turned over
        "return union((cylinder{r=5, h=2} - cylinder{r=1, h=2}) + box(1):translate(6, 0, 0),\n"
        "             cylinder{r=1, h=4}:rotate(180, 0, 0):translate(0, 0, 3))",
        // a countersink put back by the same frustum
        "return box(10):translate(-5, -5, 0) - cylinder{r1=1, r2=3, h=10}\n"
        "       + cylinder{r1=1, r2=3, h=10}"}) {
    SCOPED_TRACE(source);
    const SolidPtr solid = part(source);
    const SolidPtr filled = filledHolesDropped(solid);
    EXPECT_EQ(differences(*solid), 1);
    EXPECT_EQ(differences(*filled), 0);
    // The same solid.
    for (const dvec3& p : {dvec3(0, 0, 1), dvec3(0.99, 0, 0.5), dvec3(3, 0, 1), dvec3(0, 0, -0.5),
                           dvec3(2.5, 0, 9), dvec3(6.5, 0.5, 0.5)})
      EXPECT_EQ(filled->contains(p), solid->contains(p)) << p.x << " " << p.y << " " << p.z;
  }
}

TEST(FilledHoles, AHoleThePinDoesNotFillStays) {
  for (const char* source : {
           // a pin shorter than the hole in the plate
           "return cylinder{r=5, h=2} - cylinder{r=1, h=2} + cylinder{r=1, h=1}",
           // thinner than the hole
           "return cylinder{r=5, h=2} - cylinder{r=1, h=2} + cylinder{r=0.9, h=2}",
           // off its axis
           "return cylinder{r=5, h=2} - cylinder{r=1, h=2} + cylinder{r=1, h=2}:translate(0.5, 0, "
           "0)",
           // tilted
           "return cylinder{r=5, h=2} - cylinder{r=1, h=2} + cylinder{r=1, h=2}:rotate(1, 0, 0)",
           // a hole in a cutter, not in the part: the pin does not reach
           // where the cutter's hole keeps the box
           "return box(10):translate(-5, -5, -5) - (cylinder{r=3, h=2} - cylinder{r=1, h=2})\n"
           "       + cylinder{r=1, h=1}:translate(0, 0, 20)",
           // another cone
           "return box(10):translate(-5, -5, 0) - cylinder{r1=1, r2=3, h=10}\n"
           "       + cylinder{r1=1, r2=3.5, h=10}",
       }) {
    SCOPED_TRACE(source);
    const SolidPtr solid = part(source);
    EXPECT_EQ(filledHolesDropped(solid), solid);
  }
}

}  // namespace
}  // namespace csgray::detail
