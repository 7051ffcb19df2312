// Checks the primitives' tests share: a volume measured from spans along
// each axis, a mesh that is closed and oriented, and one that is valid and
// holds the same volume.
#pragma once

#include <gtest/gtest.h>

#include <map>
#include <numbers>
#include <utility>

#include "engine/primitive.h"
#include "export/cgal/mesh_validity.h"
#include "tessellation/triangle_mesh.h"
#include "test_support.h"

namespace csgray::detail::test {

// Volumes from spans along z, x and y (the solid turned so each axis is
// z), within `relative` (0.5 %).
inline void expectVolume(const SolidPtr& s, double exact, double relative = 0.005) {
  EXPECT_NEAR(gridVolume(*s, s->bounds(), 300), exact, relative * exact) << "along z";
  for (const dvec3& axis : {dvec3(0, 1, 0), dvec3(1, 0, 0)}) {
    SolidPtr turned = s->transformed(Affine::rotation(std::numbers::pi / 2, axis));
    EXPECT_NEAR(gridVolume(*turned, turned->bounds(), 300), exact, relative * exact)
        << "turned about " << axis.x << " " << axis.y;
  }
}

// Closed and consistently oriented (every directed edge once, and its
// opposite once), and free of crossings by the exporter's exact check.
inline void expectClosedMesh(const TriangleMesh& mesh) {
  ASSERT_FALSE(mesh.empty());
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  int bad = 0;
  for (const auto& [edge, count] : directed) {
    auto opposite = directed.find({edge.second, edge.first});
    bad += count != 1 || opposite == directed.end() || opposite->second != 1;
  }
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(meshDefect(mesh).text, "");
}

// The primitive's mesh at the tolerance: valid, and within 1 % of `exact`.
inline void expectValidMesh(const Primitive& p, double tolerance, double exact) {
  TriangleMesh mesh = p.tessellate(tolerance, Bounds::everything());
  EXPECT_EQ(meshDefect(mesh).text, "");
  EXPECT_NEAR(mesh.volume(), exact, 0.01 * exact);
}

}  // namespace csgray::detail::test
