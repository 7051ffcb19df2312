#include "export/cgal/mesh_probe.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <optional>

namespace csgray::detail {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Surface = CGAL::Surface_mesh<Point>;
using FaceTree =
    CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<Surface>>>;
using Soup = std::vector<Kernel::Triangle_3>;
using SoupTree = CGAL::AABB_tree<
    CGAL::AABB_traits<Kernel, CGAL::AABB_triangle_primitive<Kernel, Soup::const_iterator>>>;

Point point(const dvec3& p) { return Point(p.x, p.y, p.z); }

// The mesh as a Surface_mesh, if every face fits into one consistently
// oriented 2-manifold and it is closed.
std::optional<Surface> closedSurface(const TriangleMesh& mesh) {
  Surface surface;
  std::vector<Surface::Vertex_index> vertices;
  vertices.reserve(mesh.points.size());
  for (const dvec3& p : mesh.points) vertices.push_back(surface.add_vertex(point(p)));
  for (const TriangleMesh::Triangle& t : mesh.triangles) {
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return std::nullopt;
    if (surface.add_face(vertices[t[0]], vertices[t[1]], vertices[t[2]]) == Surface::null_face())
      return std::nullopt;
  }
  if (!CGAL::is_closed(surface)) return std::nullopt;
  return surface;
}

}  // namespace

struct MeshProbe::Impl {
  TriangleMesh mesh;
  Soup soup;
  SoupTree soupTree;
  std::optional<Surface> surface;
  std::optional<FaceTree> faceTree;
  std::optional<CGAL::Side_of_triangle_mesh<Surface, Kernel>> side;
};

MeshProbe::MeshProbe(const TriangleMesh& mesh) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.mesh = mesh;
  m.soup.reserve(mesh.size());
  for (const TriangleMesh::Triangle& t : mesh.triangles)
    m.soup.emplace_back(point(mesh.points[t[0]]), point(mesh.points[t[1]]),
                        point(mesh.points[t[2]]));
  m.soupTree.insert(m.soup.cbegin(), m.soup.cend());
  m.soupTree.build();
  m.soupTree.accelerate_distance_queries();
  m.surface = closedSurface(mesh);
  if (m.surface) {
    m.faceTree.emplace(faces(*m.surface).first, faces(*m.surface).second, *m.surface);
    m.faceTree->build();
    m.side.emplace(*m.faceTree);
  }
}

MeshProbe::~MeshProbe() = default;

bool MeshProbe::canClassify() const { return impl_->side.has_value(); }

MeshProbe::Side MeshProbe::side(const dvec3& p) const {
  switch ((*impl_->side)(point(p))) {
    case CGAL::ON_BOUNDED_SIDE:
      return Side::Inside;
    case CGAL::ON_BOUNDARY:
      return Side::Boundary;
    default:
      return Side::Outside;
  }
}

double MeshProbe::volume() const {
  if (impl_->surface)
    return CGAL::to_double(CGAL::Polygon_mesh_processing::volume(*impl_->surface));
  return impl_->mesh.volume();
}

double MeshProbe::area() const {
  if (impl_->surface) return CGAL::to_double(CGAL::Polygon_mesh_processing::area(*impl_->surface));
  return impl_->mesh.area();
}

double MeshProbe::distance(const dvec3& p) const {
  return std::sqrt(CGAL::to_double(impl_->soupTree.squared_distance(point(p))));
}

}  // namespace csgray::detail
