#include "export/cgal/rounded_repair.h"

#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/repair_self_intersections.h>

namespace csgray::detail {

namespace PMP = CGAL::Polygon_mesh_processing;

void removeDegenerateFaces(RoundedMesh& mesh) { PMP::remove_degenerate_faces(mesh); }

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
