// Two solids that meet on one flat face of each, in a slanted plane, their
// points there equal to rounding, are joined along the face's border; any
// other contact is refused and leaves the first mesh as it was.
#include "export/cgal/glued_caps.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>
#include <vector>

#include "export/cgal/mesh_validity.h"
#include "prism_mesh.h"

namespace csgray::detail {
namespace {

// A prism along z over the regular hexagon of `radius` about the axis,
// from z0 to z1, turned by `turn` after it is built.
DoubleMesh prism(double radius, double z0, double z1, const glm::dmat4& turn) {
  DoubleMesh made;
  made.mesh = test::prism(test::polygon(6, {0.0, 0.0}, radius), z0, z1);
  for (dvec3& p : made.mesh.points) p = dvec3(turn * glm::dvec4(p, 1.0));
  made.tags.assign(made.mesh.size(), 0);
  return made;
}

const glm::dmat4 kSlant =
    glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(glm::dvec3(1.0, 2.0, 3.0)));

// The second prism built `by` up and then turned, its points then moved
// by a few units in their last place, as a leg placed by its own frame
// has them: the same points on the shared face to rounding.
DoubleMesh upAndTurned(double radius, double by) {
  DoubleMesh made = prism(radius, by, by + 1.0, kSlant);
  int k = 0;
  for (dvec3& p : made.mesh.points) {
    const dvec3 nudge(double(k % 3) - 1.0, double(k % 5) - 2.0, double(k % 2) * 2.0 - 1.0);
    p += 4e-16 * nudge;
    ++k;
  }
  return made;
}

constexpr double kReach = 1e-9 * 4.0;

TEST(GluedCaps, PrismsOnOneSlantedFaceAreJoinedAlongIt) {
  DoubleMesh a = prism(1.0, 0.0, 1.0, kSlant);
  const DoubleMesh b = upAndTurned(1.0, 1.0);
  bool differ = false;  // (the face's points are not the same doubles)
  for (std::uint32_t k = 0; k < 6; ++k) differ = differ || a.mesh.points[6 + k] != b.mesh.points[k];
  EXPECT_TRUE(differ);
  ASSERT_TRUE(glueAtSharedCap(a, b, a.mesh.bounds(), b.mesh.bounds(), kReach));
  // One prism twice as tall: the two hexagons' 4 triangles each are gone,
  // their 6 points shared.
  EXPECT_EQ(a.mesh.points.size(), 18u);
  EXPECT_EQ(a.mesh.size(), 2u * 20u - 8u);
  EXPECT_EQ(a.tags.size(), a.mesh.size());
  EXPECT_TRUE(closedManifold(a.mesh));
  EXPECT_EQ(meshDefect(a.mesh).text, "");
  const double hexagon = 1.5 * std::sqrt(3.0);
  EXPECT_NEAR(a.mesh.volume(), 2.0 * hexagon, 1e-12);
}

TEST(GluedCaps, OtherContactsAreRefusedAndLeaveTheMeshAsItWas) {
  const DoubleMesh first = prism(1.0, 0.0, 1.0, kSlant);
  struct Case {
    const char* what;
    DoubleMesh b;
  };
  const Case cases[] = {
      {"overlapping", upAndTurned(1.0, 0.5)},
      {"a larger face", upAndTurned(1.5, 1.0)},
      {"apart", upAndTurned(1.0, 1.001)},
      {"the same prism", prism(1.0, 0.0, 1.0, kSlant)},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    DoubleMesh a = first;
    EXPECT_FALSE(glueAtSharedCap(a, c.b, a.mesh.bounds(), c.b.mesh.bounds(), kReach));
    EXPECT_EQ(a.mesh.points, first.mesh.points);
    EXPECT_EQ(a.mesh.triangles, first.mesh.triangles);
  }
}

}  // namespace
}  // namespace csgray::detail
