#include "raytrace/edge_lines.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

namespace csgray::detail {

EdgeSide edgeBetween(const SurfaceSample& a, const dvec3& pa, const SurfaceSample& b,
                     const dvec3& pb, double footprint, const EdgeStyle& style) {
  if (!a.surface && !b.surface) return EdgeSide::None;
  if (!a.surface) return EdgeSide::Second;
  if (!b.surface) return EdgeSide::First;
  const EdgeSide nearer = a.t <= b.t ? EdgeSide::First : EdgeSide::Second;
  // A step in depth: b's point lies off a's tangent plane (or a's off
  // b's). On one smooth surface the offset between neighbours is about
  // d²/2R for points d apart on a radius R, small beside d; across an
  // outline it is of the order of d itself.
  const dvec3 d = pb - pa;
  const double apart = glm::length(d);
  const double off =
      std::max(std::abs(glm::dot(d, dvec3(a.normal))), std::abs(glm::dot(d, dvec3(b.normal))));
  if (off > style.jumpPixels * footprint && off > 0.25 * apart) return nearer;
  // A crease: another face, turned by more than the crease angle.
  if (a.surface == b.surface && a.use == b.use && a.face == b.face) return EdgeSide::None;
  const double cosCrease = std::cos(style.creaseDegrees * std::numbers::pi / 180.0);
  if (glm::dot(a.normal, b.normal) < cosCrease) return nearer;
  return EdgeSide::None;
}

}  // namespace csgray::detail
