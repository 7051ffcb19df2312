#include "export/cgal/exact_boolean.h"

#include <CGAL/Polygon_mesh_processing/corefinement.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <vector>

#include "engine/cancellation.h"

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
  // A large corefinement runs for seconds: a caller's cancel stops it
  // at the next step of any of its stages (engine/cancellation.h).
  void progress_filtering_intersections(double) const { stopIfCancelled(); }
  void edge_face_intersections_step() const { stopIfCancelled(); }
  void intersection_of_coplanar_faces_step() const { stopIfCancelled(); }
  void triangulating_faces_step() const { stopIfCancelled(); }
};

// The mesh rebuilt with its vertices in the order of their points (x, then
// y, then z) and its faces in the order of their corners, each face from
// its lowest corner. CGAL's corefinement gives its boxes to
// box_intersection_d as pointers, whose order breaks ties, so the order of
// the vertices and faces it makes follows where its boxes lay in memory,
// which changes from run to run; what is made from the mesh next (a
// boolean in doubles, an operand moved off another) depends on that order
// through rounding. In this order, the same operands give the same mesh,
// and the export the same file.
void putInOrder(ExactMesh& mesh) {
  using Vertex = ExactMesh::Vertex_index;
  std::vector<Vertex> vertices(mesh.vertices().begin(), mesh.vertices().end());
  std::sort(vertices.begin(), vertices.end(), [&](Vertex u, Vertex v) {
    const CGAL::Comparison_result c = CGAL::compare_xyz(mesh.point(u), mesh.point(v));
    return c != CGAL::EQUAL ? c == CGAL::SMALLER : u < v;
  });
  ExactMesh ordered;
  std::vector<std::uint32_t> rank(mesh.number_of_vertices() + mesh.number_of_removed_vertices());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    rank[vertices[i]] = std::uint32_t(i);
    ordered.add_vertex(mesh.point(vertices[i]));
  }
  struct Face {
    std::array<std::uint32_t, 3> corners;
    std::uint32_t tag;
  };
  const auto tags = tagsOf(mesh);
  std::vector<Face> faces;
  faces.reserve(mesh.number_of_faces());
  for (auto f : mesh.faces()) {
    Face face{{}, tags[f]};
    int k = 0;
    for (Vertex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) face.corners[k++] = rank[v];
    std::rotate(face.corners.begin(), std::min_element(face.corners.begin(), face.corners.end()),
                face.corners.end());
    faces.push_back(face);
  }
  std::sort(faces.begin(), faces.end(), [](const Face& x, const Face& y) {
    return x.corners != y.corners ? x.corners < y.corners : x.tag < y.tag;
  });
  auto orderedTags = tagsOf(ordered);
  for (const Face& face : faces) {
    const auto f =
        ordered.add_face(Vertex(face.corners[0]), Vertex(face.corners[1]), Vertex(face.corners[2]));
    if (f == ExactMesh::null_face()) return;  // (not a 2-manifold: left as it is)
    orderedTags[f] = face.tag;
  }
  mesh = std::move(ordered);
}

}  // namespace

bool exactBoolean(ExactMesh& a, ExactMesh& b, Boolean::Op op) {
  tagsOf(a);
  tagsOf(b);
  TagVisitor visitor;
  auto np = CGAL::parameters::visitor(visitor);
  bool made = false;
  switch (op) {
    case Boolean::Op::Union:
      made = PMP::corefine_and_compute_union(a, b, a, np);
      break;
    case Boolean::Op::Intersection:
      made = PMP::corefine_and_compute_intersection(a, b, a, np);
      break;
    case Boolean::Op::Difference:
      made = PMP::corefine_and_compute_difference(a, b, a, np);
      break;
  }
  if (made) putInOrder(a);
  return made;
}

}  // namespace csgray::detail
