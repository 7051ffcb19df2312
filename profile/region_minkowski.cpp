// The Minkowski sum of two regions (region_evaluation.h), exact in the
// cases OpenSCAD's 2D minkowski() is used for: a shape rounded by a
// circle (an offset), and two convex shapes one of which is a polygon.
#include <algorithm>
#include <cmath>
#include <glm/matrix.hpp>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <vector>

#include "profile/region_evaluation.h"

namespace csgray::detail {

namespace {

struct Circle {
  dvec2 center;
  double r;
};

// The region's circle, when it is one: a single loop of one arc of a
// circle all the way round.
std::optional<Circle> circleOf(const Profile& p) {
  if (p.loops.size() != 1 || p.loops[0].edges.size() != 1) return std::nullopt;
  const ProfileEdge& e = p.loops[0].edges[0];
  if (e.kind != ProfileEdge::Kind::Arc || !e.circular()) return std::nullopt;
  if (std::abs(std::abs(e.angle1 - e.angle0) - 2.0 * std::numbers::pi) > 1e-12) return std::nullopt;
  return Circle{e.center, std::sqrt(std::abs(glm::determinant(e.axes)))};
}

bool straight(const Profile& p) {
  for (const ProfileLoop& loop : p.loops)
    for (const ProfileEdge& e : loop.edges)
      if (e.kind != ProfileEdge::Kind::Segment) return false;
  return true;
}

// One loop whose hull has its area: convex.
bool convex(const RegionPtr& region, const Profile& p, double tolerance) {
  if (p.loops.size() != 1) return false;
  const double own = area(p);
  const RegionPtr one[] = {region};
  return own > 0.0 && area(hull(one, tolerance)) <= own * (1.0 + 1e-9);
}

}  // namespace

Profile minkowskiSum(const RegionPtr& a, const RegionPtr& b, double tolerance) {
  const Profile pa = evaluate(*a, tolerance), pb = evaluate(*b, tolerance);
  // Rounding by a circle is the offset by its radius, moved by its centre:
  // the shape's offset{r=}, at the shape's own tolerance. The circle is an
  // exact arc; its own, finer tolerance (a hundredth of a letter's, for a
  // small circle) made the offset of a letter's curves take minutes.
  for (auto [shape, circle] : {std::pair(&a, circleOf(pb)), std::pair(&b, circleOf(pa))})
    if (circle)
      return offsetRounded(*(*shape)->transformed({dmat2(1.0), circle->center}), circle->r,
                           std::max(tolerance, evaluationTolerance(**shape)));
  // Two convex shapes: the hull of copies of one at the other's corners.
  const bool polygonA = straight(pa), polygonB = straight(pb);
  if ((polygonA || polygonB) && convex(a, pa, tolerance) && convex(b, pb, tolerance)) {
    const Profile& corners = polygonB ? pb : pa;
    const RegionPtr& moved = polygonB ? a : b;
    std::vector<RegionPtr> copies;
    for (const ProfileEdge& e : corners.loops[0].edges)
      copies.push_back(moved->transformed({dmat2(1.0), e.from}));
    return hull(copies, tolerance);
  }
  throw std::invalid_argument(
      "of two regions, one must be a circle, or both convex and one a polygon");
}

}  // namespace csgray::detail
