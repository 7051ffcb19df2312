#include "raytrace/fog.h"

#include <cmath>
#include <glm/common.hpp>

#include "engine/ray.h"

namespace csgray::detail {

namespace {

// Ground fog's density at height z: 1 up to the offset, then
// 1 / (1 + (z − offset) / altitude)², a quarter at offset + altitude.
double density(const Fog& fog, double z) {
  if (z <= fog.offset) return 1.0;
  const double w = 1.0 + (z - fog.offset) / fog.altitude;
  return 1.0 / (w * w);
}

// The density's integral by height, from the offset: z − offset below it,
// altitude · (1 − 1 / (1 + (z − offset) / altitude)) above, so that the
// fog above the offset holds as much as `altitude` of full density.
double heightIntegral(const Fog& fog, double z) {
  if (z <= fog.offset) return z - fog.offset;
  return fog.altitude * (1.0 - 1.0 / (1.0 + (z - fog.offset) / fog.altitude));
}

}  // namespace

double fogDepth(const Fog& fog, const dvec3& origin, const dvec3& dir, double length) {
  if (!fog.ground()) return length / fog.distance;
  // Along the way the height is z0 + s·dz, so ∫ density ds is the
  // integral by height over dz.
  const double z0 = origin.z, dz = dir.z;
  if (length == kInfinity) {
    // Level (dz may be −0) or down: endless fog of full density at last.
    if (!(dz > 0.0)) return kInfinity;
    return (fog.altitude - heightIntegral(fog, z0)) / dz / fog.distance;
  }
  // A way that hardly climbs takes the density at its middle (the
  // difference of the integrals would lose its digits).
  if (!(length * std::abs(dz) > 1e-9 * (1.0 + std::abs(z0) + fog.altitude)))
    return length * density(fog, z0 + 0.5 * length * dz) / fog.distance;
  return (heightIntegral(fog, z0 + length * dz) - heightIntegral(fog, z0)) / dz / fog.distance;
}

dvec3 throughFog(const Fog& fog, const dvec3& color, const dvec3& origin, const dvec3& dir,
                 double length) {
  const double depth = fogDepth(fog, origin, dir, length);
  if (depth == kInfinity) return fog.color;
  return glm::mix(fog.color, color, std::exp(-depth));
}

}  // namespace csgray::detail
