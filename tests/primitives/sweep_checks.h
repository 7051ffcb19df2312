// Checks the sweeps' tests share: a volume measured from spans along each
// axis, and a mesh that is valid and holds the same volume.
#pragma once

#include <gtest/gtest.h>

#include <numbers>

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

// The primitive's mesh at the tolerance: valid, and within 1 % of `exact`.
inline void expectValidMesh(const Primitive& p, double tolerance, double exact) {
  TriangleMesh mesh = p.tessellate(tolerance, Bounds::everything());
  EXPECT_EQ(meshDefect(mesh).text, "");
  EXPECT_NEAR(mesh.volume(), exact, 0.01 * exact);
}

}  // namespace csgray::detail::test
