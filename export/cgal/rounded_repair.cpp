#include "export/cgal/rounded_repair.h"

#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/repair_self_intersections.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <vector>

namespace csgray::detail {

namespace PMP = CGAL::Polygon_mesh_processing;

void removeDegenerateFaces(RoundedMesh& mesh) { PMP::remove_degenerate_faces(mesh); }

std::size_t flipCaps(RoundedMesh& mesh, double reach) {
  using K = CGAL::Epick;
  const auto tags = tagsOf(std::as_const(mesh));
  std::size_t flips = 0;
  const std::vector<RoundedMesh::Face_index> faces(mesh.faces().begin(), mesh.faces().end());
  for (const RoundedMesh::Face_index f : faces) {
    // The longest edge a -> b, its third corner c, and d across it.
    RoundedMesh::Halfedge_index ab = mesh.halfedge(f);
    double longest = -1.0;
    for (const auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const double l =
          CGAL::squared_distance(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)));
      if (l > longest) longest = l, ab = h;
    }
    const RoundedMesh::Halfedge_index ba = mesh.opposite(ab);
    if (mesh.is_border(ba) || (tags && tags[f] != tags[mesh.face(ba)])) continue;
    const RoundedMesh::Vertex_index vc = mesh.target(mesh.next(ab)),
                                    vd = mesh.target(mesh.next(ba));
    const K::Point_3 &a = mesh.point(mesh.source(ab)), &b = mesh.point(mesh.target(ab)),
                     &c = mesh.point(vc), &d = mesh.point(vd);
    if (!(CGAL::squared_distance(c, K::Line_3(a, b)) <= reach * reach)) continue;
    // The faces (a, d, c) and (d, b, c) the flip makes, against (b, a, d).
    const K::Vector_3 across = CGAL::cross_product(a - b, d - b);
    if (!(CGAL::cross_product(d - a, c - a) * across > 0.0 &&
          CGAL::cross_product(b - d, c - d) * across > 0.0))
      continue;
    // (Not where c and d are joined already: the flip would double that edge.)
    if (CGAL::halfedge(vc, vd, mesh).second) continue;
    CGAL::Euler::flip_edge(ab, mesh);
    ++flips;
  }
  return flips;
}

void removeSlivers(RoundedMesh& mesh, double reach) {
  // cos 179.2° = −0.9999; a needle is a face whose longest edge is 1000
  // times its shortest.
  PMP::experimental::remove_almost_degenerate_faces(
      mesh, -0.9999, 1e3, reach, CGAL::parameters::flip_triangle_height_threshold(reach));
  PMP::remove_degenerate_faces(mesh);
}

void removeCrossings(RoundedMesh& mesh, double reach) {
  PMP::experimental::remove_self_intersections(
      mesh, CGAL::parameters::polyhedral_envelope_epsilon(reach));
  PMP::remove_degenerate_faces(mesh);
}

}  // namespace csgray::detail
