// Quick answers, in doubles, to "can these two faces of a mesh meet?",
// for the validity check's many pairs of neighbouring faces. Each answers
// only when rounding cannot have changed the answer (Shewchuk's static
// error bounds) and otherwise says it cannot tell, so that the caller asks
// CGAL's exact predicates: the filters make the check faster, never
// different.
#pragma once

#include "engine/ray.h"

namespace csgray::detail {

// Triangles a and b share no corner: true when they certainly do not meet
// (one lies strictly on one side of the other's plane, or their shadows
// on a coordinate plane are strictly apart, as the faces of a flat cap
// are).
bool certainlyApart(const dvec3 a[3], const dvec3 b[3]);

// Triangles a and b share corner a[0] == b[0]: true when they certainly
// meet only there (the far corners of one lie strictly on one side of the
// other's plane, or, for faces in one plane, of an edge line of the other
// through the shared corner).
bool certainlyMeetOnlyAtCorner(const dvec3 a[3], const dvec3 b[3]);

// Triangles a = (u, w, p) and b = (w, u, q) share the edge u–w, run along
// it in opposite directions, as in an oriented mesh: true when they
// certainly are not folded onto each other (their normals point to the
// same side: the surface goes on across the edge rather than doubling
// back).
bool certainlyNotFolded(const dvec3 a[3], const dvec3 b[3]);

}  // namespace csgray::detail
