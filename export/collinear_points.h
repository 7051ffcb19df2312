// Points a boolean leaves on a straight crease without need. Where a
// cylinder's flat side quad, split by a diagonal into two triangles, passes
// through a flat face of another solid, the outline they cut has a point
// where the diagonal crosses that face: it lies on the straight line
// between its neighbours on the outline, and both sides of the outline are
// flat there. Such a point adds two triangles and holds no shape: the
// holes of the plate(32) benchmark made 147 000 of its 401 000 triangles
// so. Dropping it leaves the surface where it was.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "tessellation/triangle_mesh.h"

namespace csgray::detail {

// Collapses each point of a closed, 2-manifold, outward mesh whose faces
// lie in two planes, one on each side of a straight crease through it,
// into a neighbour on that crease, where the faces that remain keep their
// orientation and the mesh stays 2-manifold. `tags` holds a value per
// triangle (a material); the faces on each side must share one. Faces
// are within `reach` of their planes and the point within `reach` of its
// crease, so that no point of the surface moves farther than that. Points
// no triangle uses any more are removed, the others keep their order.
// Returns how many points were dropped.
std::size_t dropCollinearPoints(TriangleMesh& mesh, std::vector<std::uint32_t>& tags, double reach);

}  // namespace csgray::detail
