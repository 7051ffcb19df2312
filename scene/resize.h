// OpenSCAD's resize(newsize, auto): the scale factors that give a box the
// sizes asked for. Shared by solids and 2D regions (dims 3 or 2), and by
// the import of OpenSCAD's .csg files.
#pragma once

#include <array>

#include "engine/bounds.h"
#include "profile/region.h"

namespace csgray::detail {

// The factors along each axis (the first dims of them; the others 1): a
// size of 0 keeps the axis (factor 1), or, where autoAxes says so, takes
// the largest factor of the axes that were given, so that the shape keeps
// its proportions (all sizes 0: all factors 1). Throws std::invalid_argument ("resize: ...") for a
// size that is negative or not finite, and for a box that is empty, unbounded or flat along an axis
// that is to be resized.
dvec3 resizeFactors(const Bounds& box, const dvec3& newSize, const std::array<bool, 3>& autoAxes,
                    int dims = 3);

// The map of the plane that resizes the region: its own box
// (tightBounds) scaled about the origin by resizeFactors in two
// dimensions; autoAxes as there, for x and y.
Affine2 regionResizeMap(const Region& region, const dvec2& newSize,
                        const std::array<bool, 2>& autoAxes);

}  // namespace csgray::detail
