// Balls turned or mirrored. A ball's mesh has its poles on its own z axis
// and its rings about that axis, so a ball turned over, or turned about
// another axis, is cut on other points than the same ball unturned: one
// turned so in a cup of its radius left the cup's wall a hair off its own,
// and the union was not a 2-manifold once rounded to the file, or failed
// the check. Turned or mirrored, it is the same ball, and it is placed
// unturned.
#pragma once

#include <memory>

#include "engine/affine.h"
#include "primitives/sphere.h"

namespace csgray::detail {

// `ball` as placed by `frame`, placed by the frame's move and scale alone
// where the frame's linear part is a turn or a mirror (orthonormal to
// rounding, 10⁻¹², scaled by 1) or one that swaps and reverses axes
// (each column along a coordinate axis, all of one length). Null when
// the frame is a move alone already, or neither (a ball scaled apart: an
// ellipsoid).
std::shared_ptr<const Sphere> unturnedBall(const Sphere& ball, const Affine& frame);

}  // namespace csgray::detail
