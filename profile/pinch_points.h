// Where an evaluated region touches itself at a point: two loops corner
// to corner, a hole's corner on the outline, circles tangent to each
// other, a loop through one point twice. The evaluation keeps such
// points (profile/region_evaluation.h), but a sweep of the region is
// pinched along a line there, a solid no mesh can hold as a 2-manifold.
#pragma once

#include <vector>

#include "profile/profile.h"

namespace csgray::detail {

// Does the evaluated profile's boundary pass through one point twice,
// within 2⁻⁴⁰ of its largest coordinate: two corners at one place, or a
// corner on another edge away from its ends?
bool touchesItself(const Profile& evaluated);
// The points where it does, each once.
std::vector<dvec2> pinchPoints(const Profile& evaluated);

}  // namespace csgray::detail
