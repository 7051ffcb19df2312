// The repairs CGAL's Polygon Mesh Processing can make to a triangle mesh
// that is meant to be a closed solid: duplicated vertices merged, faces
// that use a vertex twice or repeat another face removed, orientation made
// consistent, borders stitched, faces without area removed, shells turned
// to face out (cavities in), unused vertices dropped. Holes are not filled
// and self-intersections are not resolved: meshDefect still says so.
#pragma once

#include <string>

#include "tessellation/triangle_mesh.h"

namespace csgray::detail {

// The repaired mesh; `report` says what was done in one line ("stitched 12
// edges, removed 3 degenerate faces, reversed 1 shell"), or is empty when
// the mesh needed nothing.
TriangleMesh repairMesh(const TriangleMesh& mesh, std::string& report);

}  // namespace csgray::detail
