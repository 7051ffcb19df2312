// What rounding an exact boolean's result to doubles can break, mended by
// CGAL's Polygon Mesh Processing without moving the surface further than
// the caller allows.
#pragma once

#include "export/cgal/exact_mesh.h"

namespace csgray::detail {

// Faces left without area (a point rounded onto another, or onto the line
// through two others): their edges collapsed and faces flipped away; no
// other point moves.
void removeDegenerateFaces(RoundedMesh& mesh);

// Caps (a face whose corner lies within `reach` of its longest edge)
// flipped across that edge, where both faces the flip makes turn the way
// the face across it does; returns how many. A grown box's face whose
// diagonal runs through the corner of a box it touches has such a face,
// flat in doubles, and rounding to floats turns it over onto its
// neighbour; CGAL's sliver removal (below) leaves it so.
std::size_t flipCaps(RoundedMesh& mesh, double reach);

// Slivers (a face thinner than `reach`, or with an angle within 0.8° of
// 180°) collapsed or flipped away.
void removeSlivers(RoundedMesh& mesh, double reach);

// The faces that cross removed and their holes filled, each patch within
// `reach` of the faces it replaces (CGAL's smoothing and hole filling may
// otherwise move the surface far: a vertex of a rotated union moved 1.2 mm).
void removeCrossings(RoundedMesh& mesh, double reach);

}  // namespace csgray::detail
