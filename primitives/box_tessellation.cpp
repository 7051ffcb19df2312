// Box::objectTessellate: the box's mesh (its exact part is box.cpp).
#include <cstdint>

#include "primitives/box.h"
#include "tessellation/tessellation.h"

namespace csgray::detail {

// Exact: the eight corners, two triangles a face.
TriangleMesh Box::objectTessellate(double tolerance, const Bounds&) const {
  requireTolerance(kind(), tolerance);
  TriangleMesh mesh;
  for (int i = 0; i < 8; ++i)
    mesh.points.emplace_back(i & 1 ? size_.x : 0.0, i & 2 ? size_.y : 0.0, i & 4 ? size_.z : 0.0);
  // Corner i has bit a set when it is on the high side of axis a. Each face
  // as a quad counter-clockwise from outside.
  const std::uint32_t quads[6][4] = {
      {0, 4, 6, 2}, {1, 3, 7, 5},  // x low, x high
      {0, 1, 5, 4}, {2, 6, 7, 3},  // y low, y high
      {0, 2, 3, 1}, {4, 5, 7, 6},  // z low, z high
  };
  for (const auto& q : quads) {
    mesh.triangles.push_back({q[0], q[1], q[2]});
    mesh.triangles.push_back({q[0], q[2], q[3]});
  }
  return mesh;
}

}  // namespace csgray::detail
