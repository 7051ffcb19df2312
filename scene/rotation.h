// Rotations as users give them, in degrees: about x, then y, then z
// (OpenSCAD's rotate([x, y, z])), or about an axis. For parts, open
// surfaces and textures alike.
#pragma once

#include "engine/affine.h"

namespace csgray::detail {

// degrees.x about the x axis, then degrees.y about y, then degrees.z about z.
Affine rotationDegrees(const dvec3& degrees);
// angle degrees about the axis through the origin (right-handed).
Affine rotationDegrees(double angle, const dvec3& axis);

}  // namespace csgray::detail
