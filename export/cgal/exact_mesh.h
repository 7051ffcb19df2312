// The meshes the exporter's booleans work on: exact ones while the tree is
// evaluated, rounded ones (doubles) once it is done, each face tagged with
// the material of the primitive it came from. The heavy CGAL algorithms on
// them live in exact_boolean.cpp and rounded_repair.cpp, each compiled
// once, so that the evaluator around them builds in seconds.
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstdint>
#include <vector>

#include "tessellation/triangle_mesh.h"

namespace csgray::detail {

// Exact constructions (Epeck): a corefinement's new points are exact, so
// the next boolean in a chain sees them where they are.
using ExactMesh = CGAL::Surface_mesh<CGAL::Epeck::Point_3>;
// The result, rounded to what a file holds.
using RoundedMesh = CGAL::Surface_mesh<CGAL::Epick::Point_3>;

}  // namespace csgray::detail

// CGAL 5.5's intersection of coplanar faces in a corefinement asks for the
// point where two edges' lines cross also where the edges overlap or run
// parallel (seen with cylinders on a grid of boxes, tests/contact_export_
// test.cpp), and dereferences the answer that is not a point: a crash.
// These specialisations of the kernel's functor, for the interval and the
// exact kernel that Epeck evaluates with, throw instead (exact_boolean.cpp),
// and the export reports the operands.
namespace CGAL::CommonKernelFunctors {
template <>
CGAL::Epeck::Approximate_kernel::Point_3
Construct_line_line_intersection_point_3<CGAL::Epeck::Approximate_kernel>::operator()(
    const CGAL::Epeck::Approximate_kernel::Point_3&,
    const CGAL::Epeck::Approximate_kernel::Point_3&,
    const CGAL::Epeck::Approximate_kernel::Point_3&,
    const CGAL::Epeck::Approximate_kernel::Point_3&) const;
template <>
CGAL::Epeck::Exact_kernel::Point_3
Construct_line_line_intersection_point_3<CGAL::Epeck::Exact_kernel>::operator()(
    const CGAL::Epeck::Exact_kernel::Point_3&, const CGAL::Epeck::Exact_kernel::Point_3&,
    const CGAL::Epeck::Exact_kernel::Point_3&, const CGAL::Epeck::Exact_kernel::Point_3&) const;
}  // namespace CGAL::CommonKernelFunctors

namespace csgray::detail {

inline constexpr const char* kMaterialTag = "f:material";

// A mesh's material tags, added (as 0) where it has none yet.
template <class Mesh>
auto tagsOf(Mesh& mesh) {
  return mesh.template add_property_map<typename Mesh::Face_index, std::uint32_t>(kMaterialTag, 0)
      .first;
}
template <class Mesh>
auto tagsOf(const Mesh& mesh) {
  return const_cast<Mesh&>(mesh)
      .template property_map<typename Mesh::Face_index, std::uint32_t>(kMaterialTag)
      .first;
}

// A vertex's point, rounded to doubles.
template <class Mesh>
dvec3 pointOf(const Mesh& mesh, typename Mesh::Vertex_index v) {
  const auto& p = mesh.point(v);
  return dvec3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
}

// A vertex's point near enough: the middle of the interval its lazy
// exact coordinates carry. Unlike pointOf, it never has CGAL compute an
// exact value to narrow that interval (CGAL's to_double does where the
// interval is wide), which narrows what later constructions from it
// carry: for a look at the mesh that must leave it as it was.
inline double approximately(double x) { return x; }
template <class Exact>
double approximately(const CGAL::Lazy_exact_nt<Exact>& x) {
  return CGAL::to_double(x.approx());
}
template <class Mesh>
dvec3 approximatePointOf(const Mesh& mesh, typename Mesh::Vertex_index v) {
  const auto& p = mesh.point(v);
  return dvec3(approximately(p.x()), approximately(p.y()), approximately(p.z()));
}

// The mesh as plain triangles: its points rounded to doubles (by
// pointOf, or approximatePointOf), in the order of its vertices, and its
// faces, each from the target of its halfedge on.
template <class Mesh>
TriangleMesh trianglesOf(const Mesh& mesh, bool approximate = false) {
  TriangleMesh out;
  std::vector<std::uint32_t> index(mesh.number_of_vertices() + mesh.number_of_removed_vertices());
  out.points.reserve(mesh.number_of_vertices());
  for (auto v : mesh.vertices()) {
    index[v] = std::uint32_t(out.points.size());
    out.points.push_back(approximate ? approximatePointOf(mesh, v) : pointOf(mesh, v));
  }
  out.triangles.reserve(mesh.number_of_faces());
  for (auto f : mesh.faces()) {
    TriangleMesh::Triangle t{};
    int k = 0;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) t[k++ % 3] = index[v];
    out.triangles.push_back(t);
  }
  return out;
}

}  // namespace csgray::detail
