#include "raytrace/optics.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace csgray::detail {

dvec3 reflect(const dvec3& d, const dvec3& n) { return d - 2.0 * glm::dot(d, n) * n; }

std::optional<dvec3> refract(const dvec3& d, const dvec3& n, double n1, double n2) {
  // T = η·d + (η·cos α − cos β)·n with η = n1/n2, cos α = −d·n and
  // cos² β = 1 − η²(1 − cos² α) (Heckbert's form of Snell's law).
  double eta = n1 / n2;
  double cosAlpha = -glm::dot(d, n);
  double cos2Beta = 1.0 - eta * eta * (1.0 - cosAlpha * cosAlpha);
  if (cos2Beta < 0.0) return std::nullopt;
  return glm::normalize(eta * d + (eta * cosAlpha - std::sqrt(cos2Beta)) * n);
}

double fresnelReflectance(double cosIncidence, double n1, double n2) {
  double cosI = std::clamp(std::abs(cosIncidence), 0.0, 1.0);
  double sinT = n1 / n2 * std::sqrt(std::max(0.0, 1.0 - cosI * cosI));
  if (sinT >= 1.0) return 1.0;
  double cosT = std::sqrt(1.0 - sinT * sinT);
  double rs = (n1 * cosI - n2 * cosT) / (n1 * cosI + n2 * cosT);
  double rp = (n1 * cosT - n2 * cosI) / (n1 * cosT + n2 * cosI);
  return 0.5 * (rs * rs + rp * rp);
}

}  // namespace csgray::detail
