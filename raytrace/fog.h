// Fog along a ray (scene.h, Fog): what a ray keeps of the light at the end
// of its way, and what it takes from the fog's colour instead. Of
// constant density, or ground fog: full density up to a height, thinning
// above it as POV-Ray's ground fog does.
#pragma once

#include "scene/scene.h"

namespace csgray::detail {

// The fog's optical depth over a way from `origin` along the unit
// direction `dir`, `length` long (infinite for a ray that meets nothing):
// the integral of the density over the way, over the fog's distance. The
// light at the way's end is kept as exp(−depth).
double fogDepth(const Fog& fog, const dvec3& origin, const dvec3& dir, double length);

// The colour seen over such a way: fog.color + (color − fog.color)·exp(−depth).
dvec3 throughFog(const Fog& fog, const dvec3& color, const dvec3& origin, const dvec3& dir,
                 double length);

}  // namespace csgray::detail
