#include "export/lengthened_cutters.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "engine/boolean.h"
#include "primitives/cylinder.h"
#include "primitives/revolution.h"

namespace csgray::detail {

namespace {

// The turn through part of a whole one, turned on past each end face by
// the angle that moves its farthest point by `by`: started that much
// before, its angle twice that more. Where that would make a whole turn,
// the turn as it is.
SolidPtr turnedOn(const Revolution& turn, double by, int& made) {
  const glm::dmat4& m = turn.frame().worldFromObject();
  // The farthest point's distance from the axis, in the world: the
  // region's reach times the most the frame stretches the plane z = 0.
  const ProfileBounds& region = turn.region()->bounds();
  const double reach = std::max(std::abs(region.lo.x), std::abs(region.hi.x)) *
                       std::max(glm::length(glm::dvec3(m[0])), glm::length(glm::dvec3(m[1])));
  if (!(reach > 0.0)) return turn.shared_from_this();
  const double degrees = glm::degrees(by / reach);
  if (!(turn.angleDegrees() + 2.0 * degrees < 360.0)) return turn.shared_from_this();
  const SolidPtr longer =
      Primitive::create<Revolution>(turn.region(), turn.angleDegrees() + 2.0 * degrees)
          ->withFrame(Affine::fromMatrix(
              m * glm::rotate(glm::dmat4(1.0), glm::radians(-degrees), glm::dvec3(0.0, 0.0, 1.0))));
  const SolidPtr placed = static_cast<const Primitive&>(*longer).withMaterial(turn.material());
  placed->setOrigin(turn.origin());
  ++made;
  return placed;
}

// The cylinder or cone `by` longer past each end that is not a tip: its
// frame moved back along its axis for the bottom, its height longer, and
// a cone's radii going on along its side. Counts those it makes in `made`.
SolidPtr lengthened(const Primitive& primitive, double by,
                    const std::function<bool(const Primitive&)>& which, int& made) {
  if (!which(primitive)) return primitive.shared_from_this();
  if (auto* turn = dynamic_cast<const Revolution*>(&primitive)) return turnedOn(*turn, by, made);
  auto* cylinder = dynamic_cast<const Cylinder*>(&primitive);
  if (!cylinder) return primitive.shared_from_this();
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
                           const std::function<bool(const Primitive&)>& which, int& made) {
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
                           const std::function<bool(const Primitive&)>& which) {
  int made = 0;
  SolidPtr longer = withLongerCutters(part, by, which, made);
  return made > 0 ? longer : part;
}

}  // namespace csgray::detail
