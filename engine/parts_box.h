// The box of a solid's primitives where they are: the box its flattened
// copy (every instance replaced by its child moved into place) has as its
// bounds(). An instance's box taken from its child's box instead, the
// eight moved corners, grows with each turn of a boolean turned again and
// again, by up to cos a + sin a (a gear turned 10° at each of its 36
// teeth, 24 across, had a box 4 000 across); this one does not: the
// frames compose before any box is taken.
#pragma once

#include <cstddef>

#include "engine/solid.h"

namespace csgray::detail {

// Under `outer`, visiting at most `budget` nodes (a part shared through k
// levels of instances can have 2^k uses); where the budget runs out, a
// node's own boundsUnder stands for what is below it.
Bounds partsBox(const Solid& solid, const Affine& outer, std::size_t& budget);

}  // namespace csgray::detail
