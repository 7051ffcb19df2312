#include "raytrace/bumps.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace csgray::detail {

namespace {

// v over its largest component's size, so that its length neither
// overflows nor underflows; 0 stays 0.
dvec3 scaledDown(const dvec3& v) {
  const double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  return largest > 0.0 && std::isfinite(largest) ? v / largest : v;
}

}  // namespace

double luminance(const dvec3& color) {
  return 0.2126 * color.r + 0.7152 * color.g + 0.0722 * color.b;
}

dvec3 bumpedNormal(const Material& m, const dvec3& facing, double outward,
                   const dvec3& texturePoint, const dvec3& textureNormal,
                   const glm::dmat3& textureFromWorld) {
  // The height's gradient in texture space by forward differences (four
  // evaluations of the pattern, not central differences' six: a pattern of
  // six octaves of noise is the cost of a bumpy surface), a step far below
  // any pattern's detail, whose error h·H'' is then far below what shading
  // shows, and far above the point's rounding.
  const double h = 1e-6 * std::max({1.0, std::abs(texturePoint.x), std::abs(texturePoint.y),
                                    std::abs(texturePoint.z)});
  auto height = [&](const dvec3& p) {
    return m.bumpDepth * luminance(m.bumps->colorAt(p, textureNormal));
  };
  const double here = height(texturePoint);
  dvec3 gradient;
  for (int i = 0; i < 3; ++i) {
    dvec3 step(0.0);
    step[i] = h;
    gradient[i] = (height(texturePoint + step) - here) / h;
  }
  // The raised surface is made in texture space, where the pattern and
  // its heights were given, so that the bumps scale with the part as it
  // is scaled afterwards: there the normal of the side raised (the one
  // the world's outward normal comes from) less the gradient along the
  // surface. A normal goes to the world by the transpose of the world's
  // map into texture space (the inverse transpose of the other way).
  const glm::dmat3 toWorld = glm::transpose(textureFromWorld);
  dvec3 up = glm::normalize(scaledDown(textureNormal));
  if (glm::dot(toWorld * up, outward * facing) < 0.0) up = -up;
  const dvec3 raised = scaledDown(up - (gradient - glm::dot(gradient, up) * up));
  const dvec3 world = scaledDown(toWorld * raised);
  const double length = glm::length(world);
  return length > 0.0 && std::isfinite(length) ? outward * (world / length) : facing;
}

}  // namespace csgray::detail
