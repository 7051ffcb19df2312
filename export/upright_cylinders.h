// Cylinders turned upside down. A cylinder's polygon is not a mirror image
// of itself (its points are each pushed off the circle by a different
// hair, to keep them off other solids' faces), so an axle turned the
// other way from the wheel whose bore it fills has points a hair off the
// bore's points: its wall then runs a hair inside the bore's, and CGAL's
// corefinement crashed on the two, or left faces that cross. The same
// cylinder turned the right way up, standing where its top rim was, has
// the bore's points.
#pragma once

#include <optional>

#include "engine/affine.h"
#include "primitives/cylinder.h"

namespace csgray::detail {

// The frame that places `cylinder` (r1 = r2) where `frame` does, with its
// axis along +x, +y or +z where `frame` has it along −x, −y or −z: turned
// half a turn about its own x axis (or y, whichever then points along a
// positive axis). Nothing when the axis is not so, the cylinder is a cone,
// or the rims would not land on exactly the same planes (the height added
// to the bottom's coordinate and taken off again rounds).
std::optional<Affine> uprightFrame(const Cylinder& cylinder, const Affine& frame);

}  // namespace csgray::detail
