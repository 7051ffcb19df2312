// What users do to regions (the script's r:rotate(a), r:offset{r=},
// hull(a, b), ...; the library's csgray::Region), with the checks and
// messages of the script: each function names itself in its errors
// ("mirror: the normal must not be zero"). The maps are exact at quarter
// turns and mirror images bit for bit (engine/degrees.h).
#pragma once

#include <optional>
#include <vector>

#include "profile/region.h"

namespace csgray::detail {

// The region moved by a map of the plane. Refuses a map that squashes the
// plane (singular) or a result whose coordinates overflow. `function`
// names the caller in messages.
RegionPtr mappedRegion(const Region& region, const Affine2& map, const char* function);

// Counterclockwise about the origin by degrees.
Affine2 turnMap(double degrees);
// Scaled by factors along x and y; refuses a factor of 0.
Affine2 scaleMap(const dvec2& factors, const char* function);
// The reflection in the line through the origin with this normal (not zero).
Affine2 mirrorMap(const dvec2& normal, const char* function);

// OpenSCAD's offset(): by r with rounded corners, or by delta with sharp
// ones (chamfer: cut off); one of r and delta, and chamfer only with delta.
RegionPtr offsetRegion(const Region& region, std::optional<double> r, std::optional<double> delta,
                       std::optional<bool> chamfer);
// The convex hull of the regions (at least one).
RegionPtr hullOfRegions(const std::vector<RegionPtr>& regions);
// The Minkowski sum of the regions, pair by pair from the first
// (region_evaluation.h, minkowskiSum: what it can take).
RegionPtr minkowskiOfRegions(const std::vector<RegionPtr>& regions);
// The area of the region, evaluated exactly where its edges allow.
double regionArea(const Region& region);

}  // namespace csgray::detail
