// The world box of an object box under an affine frame.
#pragma once

#include "engine/affine.h"
#include "engine/bounds.h"

namespace csgray::detail {

// The box of the eight corners of a finite box, mapped by worldFromObject.
Bounds movedBox(const Bounds& objectBox, const Affine& worldFromObject);

}  // namespace csgray::detail
