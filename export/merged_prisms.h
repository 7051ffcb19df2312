// Straight extrusions side by side, exported as one.
//
// The cells of a honeycomb, the tiles of a grid, the strokes of a logo:
// each extruded on its own and the solids united, standing on one plane
// with one height. Their side faces meet only to the rounding of where
// the script put them, and a union in 3D would resolve each such contact
// by moving faces. The extrusion of the union of their regions is the
// same solid (a prism over a union is the union of the prisms), and the
// booleans of regions are exact, with the corners that rounding kept
// apart welded (profile/corner_weld.h).
#pragma once

#include "engine/solid.h"

namespace csgray::detail {

// The part with the straight linear extrusions among each union's
// operands that share a material, a frame but for a move within their
// profile plane, a bottom and a height, and whose boxes meet, merged
// into one extrusion of the union of their regions, where that union's
// boundary does not pass through a point twice; the part itself when
// there are none.
SolidPtr prismsMerged(const SolidPtr& part);

}  // namespace csgray::detail
