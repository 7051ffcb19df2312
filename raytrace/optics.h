// The geometric optics of a surface: mirror reflection, refraction by
// Snell's law with total internal reflection, and the Fresnel reflectance
// of a dielectric interface.
#pragma once

#include <optional>

#include "engine/ray.h"

namespace csgray::detail {

// d mirrored in the plane with unit normal n: d − 2(d·n)n.
dvec3 reflect(const dvec3& d, const dvec3& n);

// The refracted direction of the unit direction d at a surface with unit
// normal n facing against d, going from index n1 into index n2 (Snell's
// law: n1 sin α = n2 sin β; Hecht, Optics, 4.4). None past the critical angle: total
// internal reflection.
std::optional<dvec3> refract(const dvec3& d, const dvec3& n, double n1, double n2);

// The share of unpolarised light reflected at the interface, for the
// cosine of the angle of incidence (Fresnel equations, the mean of the s-
// and p-polarised reflectances; Hecht, Optics, 4.6.2). 1 past the critical
// angle.
double fresnelReflectance(double cosIncidence, double n1, double n2);

}  // namespace csgray::detail
