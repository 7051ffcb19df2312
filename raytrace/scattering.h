// Random directions for light that scatters: about a surface's normal for
// diffuse (Lambertian) bounces and ambient occlusion, and about the mirror
// or refracted direction for glossy surfaces. Each takes two uniform
// numbers in [0, 1), so a pixel's generator (sampler.h) makes it the same
// on every run.
#pragma once

#include "engine/ray.h"

namespace csgray::detail {

// A unit direction on the hemisphere about the unit normal n, with density
// cos θ / π (θ from n): the sampling that cancels Lambert's cosine, so that
// a diffuse bounce's estimate is the albedo times the mean of what the
// rays see (Pharr, Jakob and Humphreys, Physically Based Rendering, 3rd
// ed., 13.6.3: Malley's method).
dvec3 cosineDirection(const dvec3& n, double u, double v);

// A unit direction about the unit direction `ideal`, from the lobe
// cos^e θ with e = 2/gloss² − 2 (gloss in (0, 1]: 1 scatters over the
// hemisphere, near 0 stays near the ideal; Phong's lobe, with the exponent
// for a roughness as in Walter et al., "Microfacet models for refraction
// through rough surfaces", EGSR 2007, eq. 25's link to Beckmann). A
// direction that would leave on the wrong side of the surface (its dot
// product with `side` not positive) is the ideal one.
dvec3 glossyDirection(const dvec3& ideal, const dvec3& side, double gloss, double u, double v);

}  // namespace csgray::detail
