#include "mesh/exact_boolean.h"

#include <CGAL/Polygon_mesh_processing/corefinement.h>

namespace csgray {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;

// A corefinement cuts faces into triangles and copies faces from one mesh
// into the other; each new face keeps the material tag it came from.
struct TagVisitor : PMP::Corefinement::Default_visitor<ExactMesh> {
  using Face = ExactMesh::Face_index;
  std::uint32_t splitTag = 0;
  void before_subface_creations(Face split, ExactMesh& mesh) { splitTag = tagsOf(mesh)[split]; }
  void after_subface_created(Face created, ExactMesh& mesh) { tagsOf(mesh)[created] = splitTag; }
  void after_face_copy(Face from, const ExactMesh& source, Face to, ExactMesh& target) {
    tagsOf(target)[to] = tagsOf(source)[from];
  }
};

}  // namespace

bool exactBoolean(ExactMesh& a, ExactMesh& b, Boolean::Op op) {
  tagsOf(a);
  tagsOf(b);
  TagVisitor visitor;
  auto np = CGAL::parameters::visitor(visitor);
  switch (op) {
    case Boolean::Op::Union:
      return PMP::corefine_and_compute_union(a, b, a, np);
    case Boolean::Op::Intersection:
      return PMP::corefine_and_compute_intersection(a, b, a, np);
    case Boolean::Op::Difference:
      return PMP::corefine_and_compute_difference(a, b, a, np);
  }
  return false;
}

}  // namespace csgray
