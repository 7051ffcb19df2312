// The planes of a convex primitive, for the exporter's intersection of
// convex primitives. A box cut by a half-space (a chamfer, a gusset) is a
// convex polytope, whose corners are where three planes meet; CGAL's
// corefinement of the two meshes instead puts extra points where the
// half-space mesh's diagonal crosses the box's faces, exact rationals on
// the cut's edges, and every later boolean then computes with rationals
// built on them (examples/bracket.lua: 2 s for one union of 1 700
// triangles with two such gussets).
#pragma once

#include <optional>
#include <vector>

#include "engine/affine.h"
#include "engine/primitive.h"
#include "tessellation/tessellation.h"

namespace csgray::detail {

// The half-spaces whose intersection is `primitive` placed by `frame`
// (normal·p <= offset, unit normals), or nothing for a primitive that is
// not a box, a half-space, a convex polyhedron, a Platonic solid or an
// untwisted linear_extrude of a convex polygon scaled alike on both axes.
std::optional<std::vector<BoundingPlane>> boundingPlanes(const Primitive& primitive,
                                                         const Affine& frame);

// The planes of a straight extrusion (linear_extrude without twist or
// scale) of any region, placed by `frame`: its bottom cap, its top cap,
// then the four sides of its region's box, which bound the caps' faces
// but are not faces of the extrusion. Nothing for any other primitive.
std::optional<std::vector<BoundingPlane>> prismCapPlanes(const Primitive& primitive,
                                                         const Affine& frame);

}  // namespace csgray::detail
