#include "export/swept_rims.h"

#include <cmath>
#include <glm/geometric.hpp>

#include "primitives/cylinder.h"

namespace csgray::detail {

SweptRims::SweptRims(const Solid& part, const std::function<Affine(const Primitive&)>& placed) {
  std::function<void(const Solid&)> visit = [&](const Solid& solid) {
    if (auto* cylinder = dynamic_cast<const Cylinder*>(&solid)) {
      if (cylinder->r1() == cylinder->r2())
        cylinders_.push_back({placed(*cylinder).worldFromObject(), cylinder->r1()});
      return;
    }
    for (const SolidPtr& child : solid.children()) visit(*child);
  };
  visit(part);
}

std::vector<CircleRim> SweptRims::of(const LinearExtrusion& sweep) const {
  std::vector<CircleRim> rims;
  if (!sweep.prism()) return rims;
  // Rounding of the frames' products, and the grid of 2⁻³⁰ the exporter
  // snaps the frames of a part turned as a whole to (EvaluationFrame).
  constexpr double kSlack = 1e-8;
  for (const Rim& cylinder : cylinders_) {
    // The cylinder in the sweep's frame: its axis must be the sweep's z
    // axis (either way), and its x and y axes a turn or a mirror of the
    // sweep's about it (to rounding), so that its rim is a circle in the
    // sweep's plane with its points where flatten() puts them: bit for bit
    // where the frames are the same, within rounding where the cylinder is
    // turned or mirrored (its points are then placed through its own axes,
    // as it places them).
    const glm::dmat4 m = sweep.frame().objectFromWorld() * cylinder.worldFromObject;
    const glm::dvec3 x(m[0]), y(m[1]), z(m[2]);
    const glm::dvec3 ex(1.0, 0.0, 0.0);
    const bool planar = std::abs(x.z) <= kSlack && std::abs(y.z) <= kSlack &&
                        std::abs(z.x) <= kSlack && std::abs(z.y) <= kSlack &&
                        std::abs(std::abs(z.z) - 1.0) <= kSlack;
    if (!planar || std::abs(glm::length(x) - 1.0) > kSlack ||
        std::abs(glm::length(y) - 1.0) > kSlack || std::abs(glm::dot(x, y)) > kSlack)
      continue;
    const bool turned = glm::length(x - ex) > 1e-12 || glm::length(y - glm::dvec3(0, 1, 0)) > 1e-12;
    rims.push_back(
        {dvec2(m[3].x, m[3].y), cylinder.radius, turned ? dmat2(x.x, x.y, y.x, y.y) : dmat2(1.0)});
  }
  return rims;
}

}  // namespace csgray::detail
