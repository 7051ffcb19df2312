// The union of two solids stacked face to face, without a corefinement:
// where one stands on the other and their faces in the plane of contact
// are the same triangles (a frustum on the frustum below it, a shaft on a
// hub of its radius), those faces are dropped from both and the two
// meshes are joined along the border they leave.
#pragma once

#include "engine/bounds.h"
#include "export/cgal/exact_mesh.h"

namespace csgray::detail {

// a = a ∪ b when a and b meet only in one axis-aligned plane (boxA and
// boxB, the boxes of their points, touch in that plane and nowhere
// overlap) and the faces of a in that plane are, triangle for triangle,
// the faces of b there turned over. Every point of either mesh in the
// plane must be a double (as a primitive's tessellation makes them), and
// must be a corner of one of those faces, so that the meshes touch
// nowhere else. Returns false, leaving both meshes as they were, when any
// of this does not hold or the joined mesh would not be a closed
// 2-manifold; the caller then corefines. Faces keep their material tags.
bool glueAcrossPlane(ExactMesh& a, const ExactMesh& b, const Bounds& boxA, const Bounds& boxB);

// Do the boxes meet in one axis-aligned plane and nowhere else? The first
// thing glueAcrossPlane asks, and all it asks of the boxes: false, and it
// would return false.
bool meetInPlane(const Bounds& boxA, const Bounds& boxB);

}  // namespace csgray::detail
