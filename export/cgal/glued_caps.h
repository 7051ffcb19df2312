// The union of two solids that meet on one flat face of each, the same
// polygon to rounding, in a plane of any slant: a pipe's straight leg on
// the end face of its bend. glued_union.h glues such solids where the
// plane is one of the axes' and the faces are the same triangles, point
// for point; in a slanted plane the two solids' points, each placed by
// its own frame, differ in their last bits, and a corefinement of the two
// faces a hair apart leaves slivers along the whole wall (a face that
// later crosses the leg's wall was then refused as self-intersecting). So
// the faces are dropped from both meshes and the meshes joined along the
// polygon, the second's points there moved onto the first's.
#pragma once

#include "engine/bounds.h"
#include "export/cgal/double_mesh.h"

namespace csgray::detail {

// a = a ∪ b where the faces of b whose corners all lie within `reach` of
// corners of a are a flat face of b (its corners within `reach` of one
// plane), the faces of a on those corners are a's face turned over with
// the same border, and each solid lies on its own side of that plane near
// the other (every other point of a within b's box, grown by `reach`, on
// a's side by more than `reach`, and the same for b): then the two meet
// only in that face, and the union is the two meshes joined along its
// border. Returns false, leaving a as it was, when any of this does not
// hold or the joined mesh would not be a closed 2-manifold; the caller
// then unites them as before. Faces keep their material tags.
bool glueAtSharedCap(DoubleMesh& a, const DoubleMesh& b, const Bounds& boxA, const Bounds& boxB,
                     double reach);

}  // namespace csgray::detail
