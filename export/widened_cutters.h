// Cylinders of one radius cut away across each other, made a hair wider.
//
// A diamond knurl's cutters, or two bores of one drill crossing in a
// block: cylinders of one radius whose axes meet. Their surfaces are
// tangent at two points (where the two ellipses of their crossing meet,
// Steinmetz's solid), and their meshes, tessellated alike, cross there at
// angles of nothing: the booleans in doubles refuse them, CGAL's take
// minutes, and the rounding to the file's precision can fold them over
// (three such cutters failed as self-intersecting after 80 s). A cylinder
// that is a hair wider than the other meets it in two curves apart, which
// both evaluate at once. Widening a cutter by far less than the tolerance
// changes the part by far less than the tolerance.
#pragma once

#include "engine/solid.h"

namespace csgray::detail {

// The part with every cylinder among a difference's cutters whose axis
// meets the axis of an earlier cylinder of the same radius among them,
// not yet widened (within 10⁻⁹ of the part's size, not parallel, at a
// point both reach within a radius past their ends), made wider: by `by`
// (in the world's lengths) times its place among those so widened, so
// that no two of them keep one radius. The part itself when there are
// none. Cylinders whose frames stretch their circles into ellipses are
// left as they are.
SolidPtr crossingCuttersWidened(const SolidPtr& part, double by);

}  // namespace csgray::detail
