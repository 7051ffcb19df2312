#include "export/lengthened_cutters.h"

#include <glm/geometric.hpp>
#include <vector>

#include "engine/boolean.h"
#include "primitives/cylinder.h"

namespace csgray::detail {

namespace {

// The cylinder or cone `by` longer past each end that is not a tip: its
// frame moved back along its axis for the bottom, its height longer, and
// a cone's radii going on along its side. Counts those it makes in `made`.
SolidPtr lengthened(const Primitive& primitive, double by,
                    const std::function<bool(const Cylinder&)>& which, int& made) {
  auto* cylinder = dynamic_cast<const Cylinder*>(&primitive);
  if (!cylinder || !which(*cylinder)) return primitive.shared_from_this();
  glm::dmat4 m = cylinder->frame().worldFromObject();
  const double axis = glm::length(glm::dvec3(m[2]));
  if (!(axis > 0.0)) return primitive.shared_from_this();
  const double along = by / axis;  // in the cylinder's own lengths
  const double h = cylinder->height(), slope = (cylinder->r2() - cylinder->r1()) / h;
  double r1 = cylinder->r1(), r2 = cylinder->r2(), height = h;
  if (r1 > 0.0 && r1 - slope * along > 0.0) {
    r1 -= slope * along;
    height += along;
    m[3] -= along * m[2];
  }
  if (r2 > 0.0 && r2 + slope * along > 0.0) {
    r2 += slope * along;
    height += along;
  }
  const SolidPtr placed =
      Primitive::create<Cylinder>(r1, r2, height)->withFrame(Affine::fromMatrix(m));
  const SolidPtr longer = static_cast<const Primitive&>(*placed).withMaterial(cylinder->material());
  longer->setOrigin(cylinder->origin());
  ++made;
  return longer;
}

SolidPtr withLongerCutters(const SolidPtr& solid, double by,
                           const std::function<bool(const Cylinder&)>& which, int& made) {
  const Boolean* node = solid->asBoolean();
  if (!node) return solid;
  std::vector<SolidPtr> operands;
  const auto children = node->children();
  for (std::size_t i = 0; i < children.size(); ++i) {
    const bool cutter = node->op() == Boolean::Op::Difference && i > 0;
    operands.push_back(cutter ? children[i]->mapPrimitives([&](const Primitive& p) {
      return lengthened(p, by, which, made);
    })
                              : withLongerCutters(children[i], by, which, made));
  }
  auto copy = std::make_shared<Boolean>(node->op(), std::move(operands));
  copy->setOrigin(node->origin());
  return copy;
}

}  // namespace

SolidPtr cuttersLengthened(const SolidPtr& part, double by,
                           const std::function<bool(const Cylinder&)>& which) {
  int made = 0;
  SolidPtr longer = withLongerCutters(part, by, which, made);
  return made > 0 ? longer : part;
}

}  // namespace csgray::detail
