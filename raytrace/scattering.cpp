#include "raytrace/scattering.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

namespace csgray::detail {

namespace {

// The direction at angle θ (from cos θ) and φ about the unit axis a.
dvec3 aboutAxis(const dvec3& a, double cosTheta, double phi) {
  // An orthonormal basis about a (Duff et al., "Building an orthonormal
  // basis, revisited", JCGT 6(1), 2017).
  const double sign = std::copysign(1.0, a.z);
  const double p = -1.0 / (sign + a.z), q = a.x * a.y * p;
  const dvec3 t(1.0 + sign * a.x * a.x * p, sign * q, -sign * a.x);
  const dvec3 b(q, sign + a.y * a.y * p, -a.y);
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  return glm::normalize(sinTheta * std::cos(phi) * t + sinTheta * std::sin(phi) * b + cosTheta * a);
}

}  // namespace

dvec3 cosineDirection(const dvec3& n, double u, double v) {
  // A uniform point on the disc, lifted to the hemisphere: cos θ = √(1 − u).
  return aboutAxis(n, std::sqrt(1.0 - u), 2.0 * std::numbers::pi * v);
}

dvec3 glossyDirection(const dvec3& ideal, const dvec3& side, double gloss, double u, double v) {
  const double exponent = 2.0 / (gloss * gloss) - 2.0;
  // cos θ = u^(1/(e+1)) draws θ with density ∝ cos^e θ · sin θ.
  const dvec3 d =
      aboutAxis(ideal, std::pow(1.0 - u, 1.0 / (exponent + 1.0)), 2.0 * std::numbers::pi * v);
  return glm::dot(d, side) > 0.0 ? d : ideal;
}

}  // namespace csgray::detail
