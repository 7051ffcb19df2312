// The volume of a solid as `csgray check` measures the exact one: the
// lengths of the spans of three grids of rays, one along each axis, each
// ray jittered within its cell (stratified sampling: unbiased, and no
// aliasing with a regular pattern of holes), the three averaged.
#pragma once

#include "engine/solid.h"

namespace csgray::detail {

// grid × grid rays per axis. Throws std::invalid_argument for an unbounded
// solid or a grid outside 1 to 4096.
double gridVolume(const Solid& solid, int grid);

}  // namespace csgray::detail
