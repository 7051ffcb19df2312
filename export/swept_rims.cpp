#include "export/swept_rims.h"

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
  constexpr double kSlack = 1e-12;  // rounding of the frames' products
  for (const Rim& cylinder : cylinders_) {
    // The cylinder in the sweep's frame: its axis must be the sweep's z
    // axis's direction and its x axis the sweep's (to rounding), so that
    // its rim is a circle in the sweep's plane with its points where
    // flatten() puts them, bit for bit where the frames are the same.
    const glm::dmat4 m = sweep.frame().objectFromWorld() * cylinder.worldFromObject;
    const glm::dvec3 x(m[0]), y(m[1]), z(m[2]);
    const glm::dvec3 ex(1.0, 0.0, 0.0), ey(0.0, 1.0, 0.0), ez(0.0, 0.0, 1.0);
    if (glm::length(x - ex) > kSlack || glm::length(y - ey) > kSlack ||
        glm::length(z - ez) > kSlack)
      continue;
    rims.push_back({dvec2(m[3].x, m[3].y), cylinder.radius});
  }
  return rims;
}

}  // namespace csgray::detail
