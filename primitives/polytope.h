// A convex polytope as vertices and faces, the form the Minkowski sum with a
// ball (rounded_polytope.h) and the hull (cgal/point_hull.h) work in: each
// face a plane and the loop of its corners, counter-clockwise seen from
// outside. A polytope of lower dimension keeps what it has: a point, a
// segment (two vertices), or a flat polygon with two faces, its two sides.
#pragma once

#include <cstdint>
#include <vector>

#include "engine/bounds.h"

namespace csgray::detail {

struct Polytope {
  struct Face {
    dvec3 normal{0.0};  // unit, outward
    double offset = 0.0;
    std::vector<std::uint32_t> loop;  // indices into vertices
  };
  // 0: one point; 1: a segment; 2: a flat polygon; 3: a solid.
  int dimension = 0;
  std::vector<dvec3> vertices;  // each a corner: no point of an edge or face
  std::vector<Face> faces;      // none below dimension 2

  Bounds bounds() const {
    Bounds box;
    for (const dvec3& v : vertices) box.include(v);
    return box;
  }
};

}  // namespace csgray::detail
