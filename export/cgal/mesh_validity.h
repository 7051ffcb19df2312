// Is a triangle mesh the boundary of a printable solid? Closed, 2-manifold,
// outward-oriented, free of degenerate faces and of self-intersections:
// checked with CGAL's exact predicates.
#pragma once

#include <string>

#include "tessellation/triangle_mesh.h"

namespace csgray::detail {

// An empty string when the mesh is valid; otherwise one line that says what
// the first problem found is and where (face or vertex indices from 0 and a
// point), e.g. "open: the edge from vertex 3 (1, 0, 2) to vertex 7 (...) has
// one face".
std::string meshDefect(const TriangleMesh& mesh);

}  // namespace csgray::detail
