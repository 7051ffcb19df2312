// Booleans of prisms of one height, exported as one prism.
//
// A frame cut from a plate, a lattice of bars clipped to its outline,
// slots cut through: boxes and straight extrusions standing on one plane
// with one height, their cutters passing through. Their top and bottom
// faces are coplanar, and booleans in 3D meet them face on face, where
// CGAL's corefinement slows to minutes (a frame with 34 bars clipped to
// it ran past 180 s). Within the slab between the two planes each such
// solid is the prism of a region, and a boolean of prisms is the prism of
// the boolean of their regions: for the slab S and prisms P(R) = R × S,
//   (∪ Aᵢ) ∩ S = P(∪ Rᵢ),   (∩ Aᵢ) ∩ S = P(∩ Rᵢ),   (A − ∪ Bⱼ) ∩ S = P(R − ∪ Rⱼ),
// where Aᵢ ∩ S = P(Rᵢ). A union of prisms that fill the slab exactly, an
// intersection with one of them, or a difference of one of them is
// within S, and so equals its prism. The booleans of regions are exact
// (profile/region_evaluation.h).
#pragma once

#include "engine/solid.h"

namespace csgray::detail {

// The part with each boolean whose operands are, within the slab of its
// first box or straight linear extrusion (for an intersection, of any
// operand's first), prisms of that slab as above,
// made one straight linear extrusion of the boolean of their regions; the
// part itself when there are none. The prisms must share a material and
// stand on the slab's plane: each a box or straight linear extrusion whose
// frame, seen from the first's, keeps the profile plane and the extrusion
// axis (a move, a turn or a scale within the plane, a move or scale along
// the axis). Made one only where two operands of a boolean in it fill the
// slab, so that their faces meet on its planes: cutters and clips that
// all pass through it leave nothing face on face, and the booleans in 3D
// are then the quicker (400 holes through a plate: 0.03 s against 0.14 s
// in the plane). A boolean whose region touches itself at a point would
// be pinched there (profile/pinch_points.h): a union of prisms alone (the
// pixels of a QR code, corner to corner) gets a square `bridge` wide over
// each such point, as a union joins solids that share only an edge
// (docs/cli.md, "Contacts"); any other is not made one. Of a union that
// is not one prism, the operands that lie within one slab are made one
// where every other operand lies off that slab, across one of its planes
// (a QR code's pixels, and the plate they stand on).
SolidPtr prismBooleansMerged(const SolidPtr& part, double bridge = 0.0);

}  // namespace csgray::detail
