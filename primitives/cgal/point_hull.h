// The convex hull of points, by CGAL (convex_hull_3, and convex_hull_2 in
// the plane of flat point sets), as a Polytope: the hull's triangles that
// lie in one plane (by CGAL's exact coplanarity test on the given doubles)
// merged into one face, and only the corners kept as vertices.
#pragma once

#include <span>

#include "primitives/polytope.h"

namespace csgray::detail {

// Points within a part in 10⁹ of the set's size of a plane or a line count
// as lying on it: the hull is then a polygon or a segment (its dimension).
// Throws std::invalid_argument for no points or a point that is not finite.
Polytope pointHull(std::span<const dvec3> points);

}  // namespace csgray::detail
