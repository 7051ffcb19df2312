// Walls along an axis that two meshes share to rounding are made flush:
// the later mesh's lines move onto the earlier's, and nothing else moves.
#include "export/aligned_walls.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/vec2.hpp>
#include <numbers>
#include <vector>

#include "export/cgal/mesh_validity.h"
#include "prism_mesh.h"

namespace csgray::detail {
namespace {

using glm::dvec2;

using test::polygon;
using test::prism;

TEST(AlignAxisLines, ALaterMeshsWallsMoveOntoAnEarliersWithinReach) {
  // A pin through a plate's hole, each placed by its own frame: the pin's
  // corners differ from the hole's in their last bits.
  const dvec2 center(20.3, -4.1);
  TriangleMesh hole = prism(polygon(12, center, 3.0), 0.0, 5.0);
  TriangleMesh pin = prism(polygon(12, center, 3.0, 3e-15), -3.0, 9.0);
  const TriangleMesh holeBefore = hole, pinBefore = pin;
  TriangleMesh* meshes[] = {&hole, &pin};
  const std::vector<bool> moved = alignAxisLines(meshes, 1e-12);
  EXPECT_EQ(moved, (std::vector<bool>{false, true}));
  EXPECT_EQ(hole.points, holeBefore.points);
  for (std::size_t i = 0; i < pin.points.size(); ++i) {
    // Across the axis the hole's corner, along it where it was.
    EXPECT_EQ(pin.points[i].x, hole.points[i % 12].x);
    EXPECT_EQ(pin.points[i].y, hole.points[i % 12].y);
    EXPECT_EQ(pin.points[i].z, pinBefore.points[i].z);
  }
  EXPECT_EQ(pin.triangles, pinBefore.triangles);
  EXPECT_TRUE(meshDefect(pin).valid()) << meshDefect(pin).text;
}

TEST(AlignAxisLines, LinesBeyondReachOrAlreadyFlushStay) {
  const dvec2 center(1.0, 2.0);
  TriangleMesh a = prism(polygon(8, center, 1.0), 0.0, 1.0);
  TriangleMesh far = prism(polygon(8, center, 1.0, 1e-9), 0.5, 2.0);
  TriangleMesh flush = prism(polygon(8, center, 1.0), -1.0, 0.5);
  const TriangleMesh farBefore = far, flushBefore = flush;
  TriangleMesh* meshes[] = {&a, &far, &flush};
  EXPECT_EQ(alignAxisLines(meshes, 1e-12), (std::vector<bool>(3, false)));
  EXPECT_EQ(far.points, farBefore.points);
  EXPECT_EQ(flush.points, flushBefore.points);
}

TEST(AlignAxisLines, TwoLinesOfOneMeshNearOneLineStay) {
  // Moving both onto it would fold the wall between them.
  TriangleMesh a = prism({{0, 0}, {1, 0}, {0, 1}}, 0.0, 1.0);
  TriangleMesh b = prism({{1e-13, 0}, {2e-13, 0}, {0.5, -1}}, 0.0, 2.0);
  const TriangleMesh before = b;
  TriangleMesh* meshes[] = {&a, &b};
  alignAxisLines(meshes, 1e-12);
  EXPECT_EQ(b.points[0], before.points[0]);
  EXPECT_EQ(b.points[1], before.points[1]);
}

TEST(AlignAxisLines, EveryAxisIsAligned) {
  // The same prism laid along x: its lines along x move onto the other's.
  auto alongX = [](TriangleMesh mesh) {
    for (dvec3& p : mesh.points) p = dvec3(p.z, p.x, p.y);
    return mesh;
  };
  TriangleMesh a = alongX(prism(polygon(6, {0.0, 0.0}, 2.0), 0.0, 4.0));
  TriangleMesh b = alongX(prism(polygon(6, {0.0, 0.0}, 2.0, -2e-15), 1.0, 7.0));
  TriangleMesh* meshes[] = {&a, &b};
  EXPECT_EQ(alignAxisLines(meshes, 1e-12), (std::vector<bool>{false, true}));
  for (std::size_t i = 0; i < b.points.size(); ++i) {
    EXPECT_EQ(b.points[i].y, a.points[i % 6].y);
    EXPECT_EQ(b.points[i].z, a.points[i % 6].z);
  }
}

}  // namespace
}  // namespace csgray::detail
