#include "export/cgal/exact_boolean.h"

#include <CGAL/Polygon_mesh_processing/corefinement.h>

#include <stdexcept>

namespace {

// The point where the lines of two edges cross, or an exception where they
// do not (exact_mesh.h).
template <class K>
typename K::Point_3 lineCrossing(const typename K::Point_3& a, const typename K::Point_3& b,
                                 const typename K::Point_3& c, const typename K::Point_3& d) {
  const auto crossing =
      typename K::Intersect_3()(typename K::Line_3(a, b), typename K::Line_3(c, d));
  const auto* point = crossing ? boost::get<typename K::Point_3>(&*crossing) : nullptr;
  if (point == nullptr)
    throw std::runtime_error("CGAL met two coplanar edges that overlap or run parallel");
  return *point;
}

}  // namespace

namespace CGAL::CommonKernelFunctors {
template <>
CGAL::Epeck::Approximate_kernel::Point_3
Construct_line_line_intersection_point_3<CGAL::Epeck::Approximate_kernel>::operator()(
    const CGAL::Epeck::Approximate_kernel::Point_3& a,
    const CGAL::Epeck::Approximate_kernel::Point_3& b,
    const CGAL::Epeck::Approximate_kernel::Point_3& c,
    const CGAL::Epeck::Approximate_kernel::Point_3& d) const {
  return lineCrossing<CGAL::Epeck::Approximate_kernel>(a, b, c, d);
}
template <>
CGAL::Epeck::Exact_kernel::Point_3
Construct_line_line_intersection_point_3<CGAL::Epeck::Exact_kernel>::operator()(
    const CGAL::Epeck::Exact_kernel::Point_3& a, const CGAL::Epeck::Exact_kernel::Point_3& b,
    const CGAL::Epeck::Exact_kernel::Point_3& c,
    const CGAL::Epeck::Exact_kernel::Point_3& d) const {
  return lineCrossing<CGAL::Epeck::Exact_kernel>(a, b, c, d);
}
}  // namespace CGAL::CommonKernelFunctors

namespace csgray::detail {

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

}  // namespace csgray::detail
