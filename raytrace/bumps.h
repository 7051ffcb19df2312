// Bump mapping (Blinn, "Simulation of Wrinkled Surfaces", SIGGRAPH '78):
// a surface shaded as if raised along its normal by a height field, here
// a material's bump depth times the brightness of its bump pattern. To
// first order the raised surface's normal is the normal less the height's
// gradient along the surface; the shape itself stays as it is, so
// silhouettes and shadows are the smooth shape's.
#pragma once

#include <glm/mat3x3.hpp>

#include "scene/material.h"

namespace csgray::detail {

// The normal `facing` (unit, towards the ray) tilted by m's bumps
// (m.bumps set). outward: +1 if facing is the surface's outward normal,
// −1 if its opposite (the height raises the surface outward either way).
// texturePoint, textureNormal and textureFromWorld are the hit's in texture
// space: the raised surface is made there, where the heights were given,
// and its normal brought to the world, so a part scaled after its
// material has its bumps scaled with it.
dvec3 bumpedNormal(const Material& m, const dvec3& facing, double outward,
                   const dvec3& texturePoint, const dvec3& textureNormal,
                   const glm::dmat3& textureFromWorld);

// The brightness of a linear colour: its luminance Y, by the weights of
// ITU-R BT.709 (the primaries of sRGB).
double luminance(const dvec3& color);

}  // namespace csgray::detail
