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

// Where the cutter's end goes, and what around it: the solid it cuts,
// and the cutter (of that difference) it belongs to.
struct CutSite {
  const Solid& cut;
  const Solid& cutter;
};

// Does an end at `centre`, facing `outward` (a unit vector), cross the
// surface of what it cuts, or end in another of the cutters: is the point
// twice `by` before it inside what it cuts, and the point as far past it
// outside that or inside the cutter? Then it is flush with a face of what
// it cuts, or buried in what is cut away anyway (three bores meeting in a
// ball). An end inside (a blind hole's floor, a bore's end where a block
// goes on) or outside (a bore through a block, its ends in the air) stays
// where it is: a pin standing on that floor, or put back through that
// bore, would be left a hair off it.
bool leaves(const CutSite& site, const dvec3& centre, const dvec3& outward, double by) {
  const dvec3 past = centre + 2.0 * by * outward;
  return site.cut.contains(centre - 2.0 * by * outward) &&
         (!site.cut.contains(past) || site.cutter.contains(past));
}

// The turn through part of a whole one, turned on past each end face that
// leaves what it cuts (leaves) by the angle that moves its farthest point by `by`. Where
// that would make a whole turn, or neither end leaves, the turn as it is.
SolidPtr turnedOn(const Revolution& turn, double by, const CutSite& site, int& made) {
  const glm::dmat4& m = turn.frame().worldFromObject();
  // The farthest point's distance from the axis, in the world: the
  // region's reach times the most the frame stretches the plane z = 0.
  const ProfileBounds& region = turn.region()->bounds();
  const double reach = std::max(std::abs(region.lo.x), std::abs(region.hi.x)) *
                       std::max(glm::length(glm::dvec3(m[0])), glm::length(glm::dvec3(m[1])));
  if (!(reach > 0.0)) return turn.shared_from_this();
  const double degrees = glm::degrees(by / reach);
  // Each end face's middle (the region's box's), and the way on past it.
  const dvec2 middle = 0.5 * (region.lo + region.hi);
  auto endLeaves = [&](double at, double sense) {
    const double a = glm::radians(at);
    const dvec3 centre(m *
                       glm::dvec4(middle.x * std::cos(a), middle.x * std::sin(a), middle.y, 1.0));
    const dvec3 on(m * glm::dvec4(-std::sin(a) * sense, std::cos(a) * sense, 0.0, 0.0));
    return glm::length(on) > 0.0 && leaves(site, centre, glm::normalize(on), by);
  };
  const bool start = endLeaves(0.0, -1.0), end = endLeaves(turn.angleDegrees(), 1.0);
  const double before = start ? degrees : 0.0, after = end ? degrees : 0.0;
  if ((!start && !end) || !(turn.angleDegrees() + before + after < 360.0))
    return turn.shared_from_this();
  const SolidPtr longer =
      Primitive::create<Revolution>(turn.region(), turn.angleDegrees() + before + after)
          ->withFrame(Affine::fromMatrix(
              m * glm::rotate(glm::dmat4(1.0), glm::radians(-before), glm::dvec3(0.0, 0.0, 1.0))));
  const SolidPtr placed = static_cast<const Primitive&>(*longer).withMaterial(turn.material());
  placed->setOrigin(turn.origin());
  ++made;
  return placed;
}

// The cylinder or cone `by` longer past each end that is not a tip and
// leaves what it cuts (leaves): its frame moved back along its axis for the bottom, its
// height longer, and a cone's radii going on along its side. Counts those
// it makes in `made`.
SolidPtr lengthened(const Primitive& primitive, double by, const CutSite& site,
                    const std::function<bool(const Primitive&)>& which, int& made) {
  if (!which(primitive)) return primitive.shared_from_this();
  if (auto* turn = dynamic_cast<const Revolution*>(&primitive))
    return turnedOn(*turn, by, site, made);
  auto* cylinder = dynamic_cast<const Cylinder*>(&primitive);
  if (!cylinder) return primitive.shared_from_this();
  glm::dmat4 m = cylinder->frame().worldFromObject();
  const double axis = glm::length(glm::dvec3(m[2]));
  if (!(axis > 0.0)) return primitive.shared_from_this();
  const dvec3 up = glm::dvec3(m[2]) / axis;
  const double along = by / axis;  // in the cylinder's own lengths
  const double h = cylinder->height(), slope = (cylinder->r2() - cylinder->r1()) / h;
  double r1 = cylinder->r1(), r2 = cylinder->r2(), height = h;
  const bool bottom = r1 > 0.0 && r1 - slope * along > 0.0 && leaves(site, dvec3(m[3]), -up, by);
  const bool top =
      r2 > 0.0 && r2 + slope * along > 0.0 && leaves(site, dvec3(m[3] + h * m[2]), up, by);
  if (!bottom && !top) return primitive.shared_from_this();
  if (bottom) {
    r1 -= slope * along;
    height += along;
    m[3] -= along * m[2];
  }
  if (top) {
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
    const CutSite site{*children[0], *children[i]};
    operands.push_back(cutter ? children[i]->mapPrimitives([&](const Primitive& p) {
      return lengthened(p, by, site, which, made);
    })
                              : withLongerCutters(children[i], by, which, made));
  }
  return node->withOperands(std::move(operands));
}

}  // namespace

SolidPtr cuttersLengthened(const SolidPtr& part, double by,
                           const std::function<bool(const Primitive&)>& which) {
  int made = 0;
  SolidPtr longer = withLongerCutters(part, by, which, made);
  return made > 0 ? longer : part;
}

}  // namespace csgray::detail
