// A part's sweeps of booleans of regions taken apart, for the export's
// last try.
//
// A sweep is meshed from its region as one set of polygons. Where the
// region touches itself (two squares corner to corner, two circles side
// by side, a square on another's corner in a rotate_extrude), its loops
// meet at a point or cross near one, and the sweep's mesh has an edge of
// four faces, or faces that cross: no mesh that a check lets through. The
// same sweep of each operand of the region's boolean, combined by that
// boolean, is the same solid (a sweep is a preimage, which commutes with
// booleans); so taken, the touching is between solids, and the booleans
// resolve it as they resolve any contact (docs/cli.md, "Contacts").
#pragma once

#include "engine/solid.h"

namespace csgray::detail {

// The part with each sweep of a boolean of regions replaced by that
// boolean of the sweeps of its operands, down to the region's leaves, and
// a leaf of several loops by the union of each outline less the holes
// directly inside it (where that is the leaf: loops that do not cross);
// the part itself when it has no such sweep. Throws std::invalid_argument
// where an operand cannot be swept so (a hole of a rotate_extrude's
// region that reaches across the axis).
SolidPtr sweepsTakenApart(const SolidPtr& part);

}  // namespace csgray::detail
