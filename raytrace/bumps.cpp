#include "raytrace/bumps.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace csgray::detail {

double luminance(const dvec3& color) {
  return 0.2126 * color.r + 0.7152 * color.g + 0.0722 * color.b;
}

dvec3 bumpedNormal(const Material& m, const dvec3& facing, double outward,
                   const dvec3& texturePoint, const dvec3& textureNormal,
                   const glm::dmat3& textureFromWorld) {
  // The height's gradient in texture space by central differences, a step
  // far below any pattern's detail and far above the point's rounding.
  const double h = 1e-6 * std::max({1.0, std::abs(texturePoint.x), std::abs(texturePoint.y),
                                    std::abs(texturePoint.z)});
  auto height = [&](const dvec3& p) {
    return m.bumpDepth * luminance(m.bumps->colorAt(p, textureNormal));
  };
  dvec3 gradient;
  for (int i = 0; i < 3; ++i) {
    dvec3 step(0.0);
    step[i] = h;
    gradient[i] = (height(texturePoint + step) - height(texturePoint - step)) / (2.0 * h);
  }
  // In the world: the chain rule through texturePoint's derivative.
  gradient = glm::transpose(textureFromWorld) * gradient;
  const dvec3 along = gradient - glm::dot(gradient, facing) * facing;
  const dvec3 tilted = facing - outward * along;
  const double length = glm::length(tilted);
  return length > 0.0 && std::isfinite(length) ? tilted / length : facing;
}

}  // namespace csgray::detail
