// Instancing in memory: the script library's Sierpinski tetrahedron is
// built of transformed uses of the level below, which share it, so each
// level costs the same few allocations however many tetrahedra it shows
// (4^level). Copies would cost at least one allocation per tetrahedron
// (operator new counted by allocation_counter.h).
#include <gtest/gtest.h>

#include <string>

#include "allocation_counter.h"
#include "engine/boolean.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

TEST(InstanceMemory, SierpinskiGrowsWithItsLevelsNotItsTetrahedra) {
  auto allocationsFor = [](int level) {
    const long before = test::allocations();
    SolidPtr s =
        test::solidOf("return sierpinski_tetrahedron{level=" + std::to_string(level) + "}");
    const long made = test::allocations() - before;
    EXPECT_EQ(s->primitiveCount(), std::size_t(1) << (2 * level));
    return made;
  };
  allocationsFor(1);  // the first script's one-time costs
  long previous = allocationsFor(5);
  for (int level = 6; level <= 10; ++level) {
    const long now = allocationsFor(level);
    // One more level is four uses and one union (and the script's own
    // values): a few dozen allocations, where copies would add 3·4^(level−1)
    // tetrahedra (3 072 to 786 432).
    EXPECT_LT(now - previous, 500) << "level " << level;
    previous = now;
  }
}

}  // namespace
}  // namespace csgray::detail
