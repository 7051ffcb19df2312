// A part of the tree kept in doubles: a primitive's tessellation, or the
// result of a boolean made in doubles (double_boolean.h), as an indexed
// triangle mesh with a material tag on each face. The evaluator keeps a
// piece so while each boolean it goes into is made in doubles too, and
// builds CGAL's exact mesh from it (face by face, which costs more than
// the boolean that made it) only where something needs CGAL: a boolean
// the doubles decline, a contact, a weld, a glue.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "export/cgal/exact_mesh.h"
#include "tessellation/triangle_mesh.h"

namespace csgray::detail {

struct DoubleMesh {
  TriangleMesh mesh;
  std::vector<std::uint32_t> tags;  // per triangle: its material's tag

  bool empty() const { return mesh.empty(); }
  // Adds other's shells (a disjoint union), tags kept.
  void append(const DoubleMesh& other);
};

// Is the mesh closed and 2-manifold, consistently oriented: each directed
// edge used once and its reverse once, no face with a corner twice, and the
// faces around each vertex one fan? (What building CGAL's mesh face by
// face and finding no border checks, in linear time.)
bool closedManifold(const TriangleMesh& mesh);

// CGAL's exact mesh of it: vertex i and face j of the one are vertex i and
// face j of the other, tags kept. Throws std::runtime_error where CGAL
// cannot add a face (a mesh that is not a 2-manifold).
ExactMesh exactOf(const DoubleMesh& doubles);

// The exact mesh in doubles, its vertices and faces in their order (the
// removed ones left out); nothing when a coordinate is not a double (a
// corefinement's new point) or a face is not a triangle.
std::optional<DoubleMesh> doublesOf(const ExactMesh& exact);

}  // namespace csgray::detail
