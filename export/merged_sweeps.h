// Sweeps side by side, exported as one.
//
// The cells of a honeycomb, the tiles of a grid, the strokes of a logo:
// each extruded on its own and the solids united, standing on one plane
// with one height; the steps of a turned part, each a rotate_extrude of
// its own about one axis. Their faces meet only to the rounding of where
// the script put them, and a union in 3D would resolve each such contact
// by moving faces. The sweep of the union of their regions is the same
// solid (a sweep is a preimage, which commutes with booleans), and the
// booleans of regions are exact, with the corners that rounding kept
// apart welded (profile/corner_weld.h).
#pragma once

#include "engine/solid.h"

namespace csgray::detail {

// The part with the sweeps among each union's operands that merge made
// one sweep of the union of their regions; the part itself when there
// are none. Sweeps merge that share a material and a frame but for a
// move within the profile's plane, whose boxes in that plane meet, and
// whose regions' union does not pass through a point twice (which would
// pinch the sweep), and that are either straight linear extrusions of
// one bottom and height, moved within their profile plane, or
// rotate_extrudes of one angle, moved along their axis.
// With evenTouching, a union that touches itself at a point is taken too
// (for export/opened_pinches.h, which opens it there).
SolidPtr sweepsMerged(const SolidPtr& part, bool evenTouching = false);

}  // namespace csgray::detail
