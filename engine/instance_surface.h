// The surface at a boundary, in the world's frame. A boundary names a
// primitive, whose frame is the world's unless the primitive lies under
// instances (engine/instance.h): a shared primitive is in its instance's
// child's frame, and the boundary alone does not say which of its uses the
// ray met. The use is found again from the root: down the instances whose
// boxes hold the point, to the primitive that has a boundary there, and its
// normal is brought back up through their frames. Only the one boundary
// that is shaded pays for it; a tree without instances pays nothing.
#pragma once

#include <cstdint>

#include "engine/solid.h"

namespace csgray::detail {

struct BoundarySurface {
  dvec3 normal;         // unit, outward from the primitive (a flip is the caller's)
  dvec3 texturePoint;   // Primitive::texturePoint, when asked for
  dvec3 textureNormal;  // Primitive::textureNormal, when asked for
  // Which use of the primitive: 0 where it has one; under instances, a key
  // of the instances on the way to it, the same for the same use (the edge
  // lines tell two uses of one primitive apart by it).
  std::uintptr_t use = 0;
};

// The surface at boundary b (b.primitive not null) of a ray through root,
// given in the frame root is in.
BoundarySurface boundarySurface(const Solid& root, const Ray& ray, const Boundary& b,
                                bool texture = false);

}  // namespace csgray::detail
