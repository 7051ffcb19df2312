// Holes that a union fills again. A pin of a hole's radius through the
// hole (a shaft through the bore of a hub cut flush with both its faces)
// puts the pin's wall on the hole's wall, and the union must then resolve
// a contact over the whole wall; for some radii no offset made it a
// 2-manifold. Where the pin holds all of the hole that lies in the part
// it is cut from, the cut does not change the union: (A − B) ∪ C = A ∪ C
// when B ∩ A ⊆ C. The hole is then left out; so is a cone cut and put
// back (a countersink refilled by its own frustum).
#pragma once

#include "engine/solid.h"

namespace csgray::detail {

// The part with each cylinder cut from a solid left out where a cylinder
// united with that cut (in the same union, or a union around it) holds
// all of it within the solid's box: the same axis and radius (as the
// export places both, export/upright_cylinders.h) and at least its length
// there; and each cone cut so where the same cone is united. The part
// itself when there is none.
SolidPtr filledHolesDropped(const SolidPtr& part);

}  // namespace csgray::detail
