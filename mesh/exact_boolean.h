// One boolean of two closed exact meshes, by CGAL's corefinement
// (Polygon Mesh Processing, "Corefinement and Boolean Operations").
#pragma once

#include "mesh/exact_mesh.h"
#include "modeler/boolean.h"

namespace csgray {

// a = a op b, in place; the faces keep their material tags. False when the
// result would not be a 2-manifold (the operands touch along an edge or at
// a point) or CGAL cannot settle the contact: both meshes are then
// corefined (each still bounds its operand), not combined.
bool exactBoolean(ExactMesh& a, ExactMesh& b, Boolean::Op op);

}  // namespace csgray
