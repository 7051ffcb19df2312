#include "export/widened_cutters.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

#include "engine/boolean.h"
#include "primitives/cylinder.h"

namespace csgray::detail {

namespace {

// Radii and axes this close (relative to the part's size) are one.
constexpr double kHair = 1e-9;

// A cylinder among a difference's cutters, in the world.
struct Cutter {
  const Cylinder* cylinder;
  dvec3 point, direction;  // the bottom's centre; unit, along the axis
  double radius, length;
};

// The cylinders among the cutters (unions of them looked into), whose
// frames keep their circles round.
void collect(const Solid& solid, std::vector<Cutter>& out) {
  if (auto* cylinder = dynamic_cast<const Cylinder*>(&solid)) {
    if (cylinder->r1() != cylinder->r2() || !(cylinder->r1() > 0.0)) return;
    const glm::dmat4& m = cylinder->frame().worldFromObject();
    const dvec3 x(m[0]), y(m[1]), z(m[2]);
    const double sx = glm::length(x), sy = glm::length(y), sz = glm::length(z);
    if (!(sz > 0.0) || std::abs(sx - sy) > kHair * sx || std::abs(glm::dot(x, y)) > kHair * sx * sy)
      return;
    out.push_back({cylinder, dvec3(m[3]), z / sz, cylinder->r1() * sx, cylinder->height() * sz});
    return;
  }
  const Boolean* node = solid.asBoolean();
  if (node && node->op() == Boolean::Op::Union)
    for (const SolidPtr& child : node->children()) collect(*child, out);
}

// Are the radii of a and b one, and do their axes meet (not parallel)
// where both cylinders reach (within a radius past an end: the lines of
// two bores at right angles in an angle bracket meet beyond both)?
bool crossAlike(const Cutter& a, const Cutter& b, double size) {
  if (std::abs(a.radius - b.radius) > kHair * std::max(a.radius, b.radius)) return false;
  const dvec3 normal = glm::cross(a.direction, b.direction);
  const double sine = glm::length(normal);
  if (!(sine > 1e-6)) return false;
  const dvec3 w = a.point - b.point;
  if (std::abs(glm::dot(w, normal)) / sine > kHair * size) return false;
  // The meeting point's place along each axis (the closest points of two
  // lines, Schneider and Eberly, Geometric Tools for Computer Graphics,
  // 10.8.2, with unit directions).
  const double c = glm::dot(a.direction, b.direction), d = glm::dot(a.direction, w),
               e = glm::dot(b.direction, w), denominator = 1.0 - c * c;
  const double s = (c * e - d) / denominator, t = (e - c * d) / denominator;
  auto within = [](double at, const Cutter& cutter) {
    return at >= -cutter.radius && at <= cutter.length + cutter.radius;
  };
  return within(s, a) && within(t, b);
}

SolidPtr widened(const SolidPtr& solid, double by, double size, int& made) {
  const Boolean* node = solid->asBoolean();
  if (!node) return solid;
  const auto children = node->children();
  std::vector<SolidPtr> operands;
  for (const SolidPtr& child : children) operands.push_back(widened(child, by, size, made));
  if (node->op() == Boolean::Op::Difference) {
    std::vector<Cutter> cutters;
    for (std::size_t i = 1; i < children.size(); ++i) collect(*children[i], cutters);
    std::vector<int> place(cutters.size(), 0);  // among those widened, from 1
    int widenedHere = 0;
    for (std::size_t j = 1; j < cutters.size(); ++j)
      for (std::size_t i = 0; i < j; ++i)
        if (place[i] == 0 && crossAlike(cutters[i], cutters[j], size)) {
          place[j] = ++widenedHere;
          break;
        }
    if (widenedHere > 0) {
      for (std::size_t i = 1; i < operands.size(); ++i)
        operands[i] = operands[i]->mapPrimitives([&](const Primitive& p) -> SolidPtr {
          for (std::size_t k = 0; k < cutters.size(); ++k) {
            if (cutters[k].cylinder != &p || place[k] == 0) continue;
            const Cylinder& c = *cutters[k].cylinder;
            const double stretch = cutters[k].radius / c.r1();  // world per object length
            const double r = c.r1() + place[k] * by / stretch;
            const SolidPtr wider =
                Primitive::create<Cylinder>(r, r, c.height())->withFrame(c.frame());
            const SolidPtr placed =
                static_cast<const Primitive&>(*wider).withMaterial(c.material());
            placed->setOrigin(c.origin());
            return placed;
          }
          return p.shared_from_this();
        });
      made += widenedHere;
    }
  }
  return node->withOperands(std::move(operands));
}

}  // namespace

SolidPtr crossingCuttersWidened(const SolidPtr& part, double by) {
  const Bounds& box = part->bounds();
  if (!box.finite()) return part;
  const double size = std::max({1.0, glm::length(box.lo), glm::length(box.hi)});
  int made = 0;
  SolidPtr wider = widened(part, by, size, made);
  return made > 0 ? wider : part;
}

}  // namespace csgray::detail
