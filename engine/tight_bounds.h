// The box of a solid's own points, which Solid::bounds() may exceed: a
// boolean's box is its operands' (a cube less half of it keeps the whole
// cube's), a turned shape's is its turned box. OpenSCAD's resize, and the
// size a user reads (csgray info, csgray view's panel), mean this box.
#pragma once

#include "engine/solid.h"

namespace csgray::detail {

// Found by rays through the exact solid: along each axis, a grid of
// parallel rays across the loose box meets the solid's lowest and highest
// points on its lines; about the few best of them, ever finer grids close
// in on the extreme, to about 10⁻⁹ of the box. So the box holds only points
// of the solid's surface, and is exact for a flat face, a rim or a ball's
// pole alike. A feature narrower than a first grid cell (a 64th of the
// loose box) that reaches farthest may be missed. The loose box is
// bounds() within the box of the primitives where they are
// (engine/parts_box.h, with a larger budget than bounds() has). Where
// the rays meet nothing (an empty solid), for one too small for them
// (under 10⁻¹⁰⁰ across) and for an unbounded solid, the box is that
// loose box; `metNothing`, if given, says whether the rays met nothing
// (the solid is empty, or all of it narrower than their spacing).
Bounds tightBounds(const Solid& solid, bool* metNothing = nullptr);

}  // namespace csgray::detail
