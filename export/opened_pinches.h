// Sweeps of regions that touch themselves at a point, opened there.
//
// A region whose boundary passes through a point twice (a hole tangent to
// the outline, two squares corner to corner, a letter's strokes meeting
// at its apex) sweeps to a solid pinched along a line, which no 2-manifold
// mesh holds; nor, taken apart (export/sweeps_apart.h), do the solids
// that touch along it always resolve. The export's last try sweeps such a
// region shrunk by a hair instead: the pinch opens into a slit that thin,
// as a cut through touching material does (docs/cli.md, "Contacts"), and
// every other face moves by that hair, far below the tolerance.
#pragma once

#include "engine/solid.h"

namespace csgray::detail {

// The part with each sweep whose region touches itself at a point made
// the sweep of that region offset inward by `by`; the part itself when it
// has none.
SolidPtr pinchesOpened(const SolidPtr& part, double by);

}  // namespace csgray::detail
