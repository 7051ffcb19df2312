#include "export/filled_holes.h"

#include <algorithm>
#include <glm/mat3x3.hpp>
#include <memory>
#include <vector>

#include "engine/boolean.h"
#include "export/upright_cylinders.h"
#include "primitives/cylinder.h"

namespace csgray::detail {

namespace {

// A cylinder or cone as the export places it: its axis along +x, +y or
// +z where it lies along one (export/upright_cylinders.h); null for
// another solid.
std::shared_ptr<const Cylinder> placedCylinder(const Solid& solid) {
  auto* cylinder = dynamic_cast<const Cylinder*>(&solid);
  if (!cylinder) return nullptr;
  if (auto upright = uprightCylinder(*cylinder, cylinder->frame())) return upright;
  return std::static_pointer_cast<const Cylinder>(cylinder->shared_from_this());
}

// The coordinate axis a cylinder's frame has its axis along, unscaled
// and not reversed, or -1.
int axisOf(const Cylinder& cylinder) {
  const glm::dmat4& m = cylinder.frame().worldFromObject();
  for (int k = 0; k < 3; ++k)
    if (m[2][k] == 1.0 && m[2][(k + 1) % 3] == 0.0 && m[2][(k + 2) % 3] == 0.0) return k;
  return -1;
}

// Does `pin` hold all of `hole` that lies in `box`? The same cone, or
// cylinders on one axis line, bit for bit, with one radius, the pin at
// least as long there.
bool holds(const Cylinder& pin, const Cylinder& hole, const Bounds& box) {
  const glm::dmat4 &p = pin.frame().worldFromObject(), &h = hole.frame().worldFromObject();
  if (p == h && pin.r1() == hole.r1() && pin.r2() == hole.r2() && pin.height() == hole.height())
    return true;
  const int k = axisOf(hole);
  if (k < 0 || axisOf(pin) != k || pin.r1() != hole.r1() || pin.r1() != pin.r2() ||
      hole.r1() != hole.r2())
    return false;
  if (glm::dmat3(p) != glm::dmat3(h)) return false;
  for (int j = 0; j < 3; ++j)
    if (j != k && p[3][j] != h[3][j]) return false;
  const double lo = std::max(h[3][k], box.lo[k]), hi = std::min(h[3][k] + hole.height(), box.hi[k]);
  return lo >= p[3][k] && hi <= p[3][k] + pin.height();
}

SolidPtr dropped(const SolidPtr& solid, const std::vector<std::shared_ptr<const Cylinder>>& pins);

// A union's operands and the pins they and the unions around them add.
SolidPtr droppedInUnion(const Boolean& node, std::vector<std::shared_ptr<const Cylinder>> pins) {
  for (const SolidPtr& operand : node.children())
    if (auto pin = placedCylinder(*operand)) pins.push_back(std::move(pin));
  std::vector<SolidPtr> operands;
  for (const SolidPtr& operand : node.children()) operands.push_back(dropped(operand, pins));
  return node.withOperands(std::move(operands));
}

SolidPtr dropped(const SolidPtr& solid, const std::vector<std::shared_ptr<const Cylinder>>& pins) {
  const Boolean* node = solid->asBoolean();
  if (!node) return solid;
  if (node->op() == Boolean::Op::Union) return droppedInUnion(*node, pins);
  std::vector<SolidPtr> operands;
  const auto children = node->children();
  for (std::size_t i = 0; i < children.size(); ++i) {
    const bool cutter = node->op() == Boolean::Op::Difference && i > 0;
    if (cutter && !pins.empty())
      if (auto hole = placedCylinder(*children[i])) {
        const Bounds& box = children[0]->bounds();
        if (std::any_of(pins.begin(), pins.end(),
                        [&](const auto& pin) { return holds(*pin, *hole, box); }))
          continue;
      }
    // Holes of the minuend only: a cutter's own holes (a ring cut from the
    // part) are left as they are.
    const bool minuend = node->op() == Boolean::Op::Difference && i == 0;
    operands.push_back(dropped(children[i], minuend ? pins : decltype(pins){}));
  }
  return node->withOperands(std::move(operands));
}

}  // namespace

SolidPtr filledHolesDropped(const SolidPtr& part) { return dropped(part, {}); }

}  // namespace csgray::detail
