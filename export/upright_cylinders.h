// Cylinders and cones turned upside down, or mirrored. A cylinder's
// polygon is not a mirror image of itself (its points are each pushed off
// the circle by a different hair, to keep them off other solids' faces),
// so an axle turned the other way from the wheel whose bore it fills, or
// mirrored, has points a hair off the bore's points: its wall then runs a
// hair inside the bore's, and CGAL's corefinement crashed on the two, or
// left faces that cross. The same cylinder turned the right way up
// (standing where its top rim was) and not mirrored has the bore's points;
// so has a countersink's cone on its screw's shank, turned with it, and a
// pin turned about its own axis, by a quarter or by any other angle.
#pragma once

#include <memory>

#include "engine/affine.h"
#include "primitives/cylinder.h"

namespace csgray::detail {

// `cylinder` (a cylinder or a cone frustum) as placed by `frame`, made the
// same solid in the one frame of its axis's direction where `frame`'s
// axes lie along coordinate axes: its axis along +x, +y or +z (where
// `frame` has it reversed, it stands on its top rim, its radii swapped),
// its own x and y along the other two in their order (x before y before
// z), each scaled as `frame` scales it; where they lie off the axes
// (turned about its axis by another angle, or mirrored across a
// diagonal) but are perpendicular and as long as each other, unturned
// too. An elliptic cylinder turned so keeps its turn, and a reversed
// axis or a mirror is undone by turning it over about its own x or
// reversing that. Null when the frame is that already, its axis does not
// lie along a coordinate axis or its rims are slanted against it, its x
// and y lie along axes but are scaled apart (an elliptic cylinder), they
// are an elliptic cylinder's turned about its axis and nothing is
// reversed or mirrored, or the rims would not land on exactly the same
// planes (the height added to the bottom's coordinate and taken off
// again rounds).
std::shared_ptr<const Cylinder> uprightCylinder(const Cylinder& cylinder, const Affine& frame);

}  // namespace csgray::detail
