// MeshSolid::objectTessellate: the polyhedron's own triangles as a mesh
// (its exact part is mesh_solid.cpp).
#include <cstdint>
#include <limits>
#include <vector>

#include "primitives/mesh_solid.h"
#include "tessellation/tessellation.h"

namespace csgray::detail {

// Exact: the solid's own triangles, with the points they use.
TriangleMesh MeshSolid::objectTessellate(double tolerance, const Bounds&) const {
  requireTolerance(kind(), tolerance);
  const std::vector<dvec3>& points = this->points();
  TriangleMesh mesh;
  constexpr auto kUnused = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> index(points.size(), kUnused);
  mesh.triangles.reserve(triangles().size());
  for (const Triangle& t : triangles()) {
    TriangleMesh::Triangle out;
    for (int k = 0; k < 3; ++k) {
      std::uint32_t& i = index[t[k]];
      if (i == kUnused) {
        i = static_cast<std::uint32_t>(mesh.points.size());
        mesh.points.push_back(points[t[k]]);
      }
      out[k] = i;
    }
    mesh.triangles.push_back(out);
  }
  return mesh;
}

}  // namespace csgray::detail
