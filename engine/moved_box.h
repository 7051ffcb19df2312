// The world box of an object box under an affine frame.
#pragma once

#include "engine/affine.h"
#include "engine/bounds.h"

namespace csgray::detail {

// The box of the eight corners of a finite box, mapped by worldFromObject.
Bounds movedBox(const Bounds& objectBox, const Affine& worldFromObject);
Bounds movedBox(const Bounds& objectBox, const glm::dmat4& worldFromObject);
// The box of a ball (radius r about the object point centre) or of a disc
// (the same, in the plane z = centre.z), mapped by worldFromObject: an
// ellipsoid or an ellipse, whose reach along world axis i from the mapped
// centre is r times the length of row i of the linear part M (its support
// function h(e) = e·c + r·|Mᵀe|; Schneider, "Convex Bodies: The
// Brunn-Minkowski Theory", 2nd ed., §1.7), of its first two columns for
// the disc. Widened by 10⁻¹² of the size, so that rounding cannot leave a
// point of the surface outside.
Bounds movedBall(const dvec3& centre, double r, const Affine& worldFromObject);
Bounds movedDisc(const dvec3& centre, double r, const Affine& worldFromObject);

}  // namespace csgray::detail
