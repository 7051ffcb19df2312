#include "export/swept_rims.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <numbers>

#include "engine/boolean.h"
#include "engine/degrees.h"
#include "primitives/cylinder.h"

namespace csgray::detail {

SweptRims::SweptRims(
    const Solid& part,
    const std::function<std::shared_ptr<const Primitive>(const Primitive&)>& placed) {
  // A cylinder that only ever cuts (an operand of a difference after its
  // first) gains nothing from a shared polygon: a hole cut again where the
  // sweep has one is the same hole with either polygon, and walls in one
  // plane cost CGAL more (a plate's six turned holes cut again by their
  // cylinders: 0.7 s, and 1.4 s with shared polygons).
  std::function<void(const Solid&, bool)> visit = [&](const Solid& solid, bool cutting) {
    if (auto* cylinder = dynamic_cast<const Cylinder*>(&solid)) {
      const auto shape = std::static_pointer_cast<const Cylinder>(placed(*cylinder));
      if (shape->r1() == shape->r2() && !cutting) {
        cylinders_.push_back({shape->frame().worldFromObject(), shape->r1()});
        kept_.insert(cylinder);
      }
      return;
    }
    if (auto* turn = dynamic_cast<const Revolution*>(&solid)) {
      turns_.push_back(std::static_pointer_cast<const Revolution>(placed(*turn)));
      return;
    }
    auto* boolean = dynamic_cast<const Boolean*>(&solid);
    const bool difference = boolean && boolean->op() == Boolean::Op::Difference;
    bool first = true;
    for (const SolidPtr& child : solid.children()) {
      visit(*child, cutting || (difference && !first));
      first = false;
    }
  };
  visit(part, false);
}

namespace {

// Rounding of the frames' products, and the grid of 2⁻³⁰ the exporter
// snaps the frames of a part turned as a whole to (EvaluationFrame).
constexpr double kSlack = 1e-8;

// A cylinder's x and y axes in the plane z = 0 of another frame, m taking
// the cylinder's frame into that one: where its axis lies along that
// frame's z axis (either way) and its x and y axes are a turn or a mirror
// of the plane's (to kSlack); nothing where it is tilted or scaled.
std::optional<dmat2> axesInPlane(const glm::dmat4& m) {
  const glm::dvec3 x(m[0]), y(m[1]), z(m[2]);
  const bool alongZ = std::abs(x.z) <= kSlack && std::abs(y.z) <= kSlack &&
                      std::abs(z.x) <= kSlack && std::abs(z.y) <= kSlack &&
                      std::abs(std::abs(z.z) - 1.0) <= kSlack;
  if (!alongZ || std::abs(glm::length(x) - 1.0) > kSlack ||
      std::abs(glm::length(y) - 1.0) > kSlack || std::abs(glm::dot(x, y)) > kSlack)
    return std::nullopt;
  return dmat2(x.x, x.y, y.x, y.y);
}

}  // namespace

std::vector<CircleRim> SweptRims::of(const LinearExtrusion& sweep) const {
  std::vector<CircleRim> rims;
  if (!sweep.prism()) return rims;
  for (const Rim& cylinder : cylinders_) {
    // The cylinder in the sweep's frame, its rim a circle in the sweep's
    // plane with its points where flatten() puts them: bit for bit where
    // the frames are the same, within rounding where the cylinder is
    // turned or mirrored (its points are then placed through its own axes,
    // as it places them).
    const glm::dmat4 m = sweep.frame().objectFromWorld() * cylinder.worldFromObject;
    const std::optional<dmat2> axes = axesInPlane(m);
    if (!axes) continue;
    const dmat2 d = *axes - dmat2(1.0);
    const bool turned = glm::length(d[0]) > 1e-12 || glm::length(d[1]) > 1e-12;
    rims.push_back({dvec2(m[3].x, m[3].y), cylinder.radius, turned ? *axes : dmat2(1.0)});
  }
  return rims;
}

std::optional<CirclePolygon> SweptRims::turnedWallPolygon(const Primitive& original,
                                                          const Cylinder& cylinder,
                                                          double tolerance) const {
  if (cylinder.r1() != cylinder.r2() || !kept_.contains(&original)) return std::nullopt;
  const double r = cylinder.r1();
  for (const auto& turn : turns_) {
    const glm::dmat4 m = turn->frame().objectFromWorld() * cylinder.frame().worldFromObject();
    // On the turn's axis, upright, its own axes a turn about it.
    const std::optional<dmat2> axes = axesInPlane(m);
    if (!axes || m[2].z < 0.0 || glm::determinant(*axes) < 0.0 ||
        glm::length(dvec2(m[3].x, m[3].y)) > 1e-9 * r + 0x1p-29)
      continue;
    const std::optional<int> steps =
        turn->wallSteps(r, m[3].z, m[3].z + cylinder.height(), turn->objectTolerance(tolerance));
    if (!steps) continue;
    // The turn's ring k lies at 360°·k/steps in its frame: the cylinder's
    // step k there, counted from its own x axis.
    CirclePolygon polygon;
    polygon.segments = *steps;
    polygon.error = r * (1.0 - std::cos(std::numbers::pi / *steps));
    polygon.phase = -std::atan2((*axes)[0].y, (*axes)[0].x);
    return polygon;
  }
  return std::nullopt;
}

std::optional<CirclePolygon> SweptRims::turnedEndPolygon(const Cylinder& cylinder,
                                                         double tolerance) const {
  if (cylinder.r1() != cylinder.r2()) return std::nullopt;
  const double r = cylinder.r1(), h = cylinder.height();
  for (const auto& turn : turns_) {
    const double angle = turn->angleDegrees();
    if (!(angle < 360.0)) continue;
    const glm::dmat4 inTurn = turn->frame().objectFromWorld() * cylinder.frame().worldFromObject();
    // Each end face in turn, turned into the plane y = 0 with the region's
    // plane (ρ, z) as (x, z): the turn's wedge then lies at y > 0 beside
    // the start face, and at y < 0 beside the end face.
    for (const double at : {0.0, angle}) {
      const dvec2 cs = unitCircleDegrees(at);
      glm::dmat4 unturn(1.0);
      unturn[0] = glm::dvec4(cs.x, -cs.y, 0.0, 0.0);
      unturn[1] = glm::dvec4(cs.y, cs.x, 0.0, 0.0);
      const glm::dmat4 m = unturn * inTurn;
      const glm::dvec3 x(m[0]), y(m[1]), z(m[2]), o(m[3]);
      // Square on the face: the cylinder's axis along ±y, its own x and y
      // axes unit vectors in the plane.
      const double size = r + h + glm::length(o);
      const bool square = std::abs(z.x) <= kSlack && std::abs(z.z) <= kSlack &&
                          std::abs(std::abs(z.y) - 1.0) <= kSlack && std::abs(x.y) <= kSlack &&
                          std::abs(y.y) <= kSlack && std::abs(glm::length(x) - 1.0) <= kSlack &&
                          std::abs(glm::length(y) - 1.0) <= kSlack &&
                          std::abs(glm::dot(x, y)) <= kSlack;
      if (!square) continue;
      // The end on the face, the other end outside the wedge.
      const glm::dvec3 top = o + h * z;
      const double outward = at == 0.0 ? -1.0 : 1.0;
      glm::dvec3 foot;
      if (std::abs(o.y) <= kSlack * size && top.y * outward > 0.0)
        foot = o;
      else if (std::abs(top.y) <= kSlack * size && o.y * outward > 0.0)
        foot = top;
      else
        continue;
      const dvec2 center(foot.x, foot.z);
      if (!(center.x - r > 0.0)) continue;
      const auto loop = turn->circleLoop(center, r, turn->objectTolerance(tolerance));
      if (!loop) continue;
      // The loop's point at loop->phase about the centre, in the
      // cylinder's own angles: its x and y axes are orthonormal in (x, z).
      const dvec2 d(std::cos(loop->phase), std::sin(loop->phase));
      CirclePolygon polygon;
      polygon.segments = loop->segments;
      polygon.error = r * (1.0 - std::cos(std::numbers::pi / loop->segments));
      polygon.phase = std::atan2(glm::dot(dvec2(y.x, y.z), d), glm::dot(dvec2(x.x, x.z), d));
      return polygon;
    }
  }
  return std::nullopt;
}

}  // namespace csgray::detail
