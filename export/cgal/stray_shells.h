// Shells of an export that the exact solid does not hold. Where a kept
// solid lies inside a cutter, tangent to it (a ball in a rod of its radius
// that is cut away), both meshes straddle their surfaces within the
// tolerance, so the kept one's vertices stand out of the cutter's chords
// and the cut leaves slivers of it behind: separate shells, each thinner
// than about twice the tolerance, all of whose inside lies outside the
// exact part.
#pragma once

#include <cstddef>

#include "engine/solid.h"
#include "export/part_mesh.h"

namespace csgray::detail {

// Removes from the part the thin shells (of two or more: volume at most
// the tolerance times the area) whose inside the exact solid classifies as
// outside: at the largest few faces of a shell, the point halfway through
// the material, against each face's normal, must be outside `solid` for
// every such face (and at least two). Cavities (shells whose faces look
// inwards) and shells the rays leave without crossing are kept. Returns
// how many shells were removed.
std::size_t removeStrayShells(PartMesh& part, const Solid& solid, double tolerance);

}  // namespace csgray::detail
