// How many pieces a part is meant to be, against which `csgray check`
// weighs the shells of its mesh: more shells than pieces is a warning
// that a cut goes through the part, or that its solids meet only in an
// edge or a point and were kept apart there (docs/check.md).
#pragma once

#include <cstddef>

#include "engine/solid.h"
#include "tessellation/mesh_shells.h"

namespace csgray::detail {

// The pieces of `solid` (prepared) that its mesh should show: the operands
// of its top union (unions within it looked through) that the mesh's
// shells join, each shell joined to the shells within `near` of it (solids
// that touch, kept apart by a hair) and to the operands it lies on; an
// operand no shell is found on joins those its box overlaps. A ring
// around a rod that it does not touch is two pieces, a base cut through
// by a slot one, and a sweep alone in its piece as many as its region has
// apart (the letters of a word), and a two-sheet quadric alone in its
// piece (clipped, cut) as many as the sheets its shells lie on.
std::size_t modelPieces(const Solid& solid, const TriangleMesh& mesh, const MeshShells& shells,
                        double near);

}  // namespace csgray::detail
