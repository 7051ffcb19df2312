// An exported part: a mesh whose triangles remember the material of the
// primitive whose surface they lie on (for the colours of a 3MF file).
#pragma once

#include <cstdint>
#include <vector>

#include "scene/material.h"
#include "tessellation/triangle_mesh.h"

namespace csgray::detail {

struct PartMesh {
  TriangleMesh mesh;
  std::vector<std::uint32_t> material;  // per triangle: an index into materials
  std::vector<MaterialPtr> materials;   // distinct, in order of first use; may hold null
};

// How a file stores a coordinate: the value it reads back as.
using StoredCoordinate = double (*)(double);

}  // namespace csgray::detail
