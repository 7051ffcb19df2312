// One boolean of two closed exact meshes, by CGAL's corefinement
// (Polygon Mesh Processing, "Corefinement and Boolean Operations").
#pragma once

#include "engine/boolean.h"
#include "export/cgal/exact_mesh.h"

namespace csgray::detail {

// a = a op b, in place; the faces keep their material tags. False when the
// result would not be a 2-manifold (the operands touch along an edge or at
// a point): both meshes are then corefined (each still bounds its operand),
// not combined. Throws what CGAL throws when it cannot cut a face ("Unauthorized
// intersections of constraints"); the meshes may then be half cut. Throws
// Cancelled (engine/cancellation.h) at a step of the corefinement once the
// calling thread's cancel flag is set.
bool exactBoolean(ExactMesh& a, ExactMesh& b, Boolean::Op op);

}  // namespace csgray::detail
