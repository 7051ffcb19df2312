// The Minkowski sum of two regions (region_evaluation.h), exact in the
// cases OpenSCAD's 2D minkowski() is used for: a shape rounded by a
// circle (an offset), two convex shapes one of which is a polygon, and a
// polygon with a convex shape; a shape with arcs and a convex one that is
// not a circle within a part in 10⁴ of the shape's size.
#include <algorithm>
#include <cmath>
#include <glm/matrix.hpp>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <tuple>
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

// The tolerance, relative to a shape's size, within which its circular
// arcs are cut into segments for a sum with a convex shape that is not a
// circle: a part in 10⁴, as for the curved operands of a 3D hull.
constexpr double kArcTolerance = 1e-4;

// The profile with its arcs cut into segments within `tolerance`.
Profile polygonal(const Profile& p, double tolerance) {
  if (straight(p)) return p;
  Profile out;
  for (const std::vector<dvec2>& points : flatten(p, tolerance)) {
    ProfileLoop loop;
    for (std::size_t i = 0; i < points.size(); ++i)
      loop.edges.push_back(ProfileEdge::segment(points[i], points[(i + 1) % points.size()]));
    out.loops.push_back(std::move(loop));
  }
  return out;
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
  const bool convexA = convex(a, pa, tolerance), convexB = convex(b, pb, tolerance);
  // Two convex shapes: the hull of copies of one at the other's corners.
  const bool polygonA = straight(pa), polygonB = straight(pb);
  if ((polygonA || polygonB) && convexA && convexB) {
    const Profile& corners = polygonB ? pb : pa;
    const RegionPtr& moved = polygonB ? a : b;
    std::vector<RegionPtr> copies;
    for (const ProfileEdge& e : corners.loops[0].edges)
      copies.push_back(moved->transformed({dmat2(1.0), e.from}));
    return hull(copies, tolerance);
  }
  // Any shape A and a convex one Q: for a point q0 of Q, A ⊕ Q is A + q0
  // together with each edge of A swept over Q, the hull of Q at the edge's
  // two ends. (A point p + q of the sum whose p + q − q0 lies outside A:
  // along the segment from q to q0, inside Q, p + q − q' leaves A, so it
  // crosses A's boundary at some q'.) Exact for a polygon; A's arcs are
  // cut into segments within kArcTolerance of its size first, and a
  // letter's curves are flattened at its own tolerance (as for a circle:
  // at a small square's finer one they made thousands of edges).
  for (auto [shape, other, otherConvex] :
       {std::tuple(&a, &b, convexB), std::tuple(&b, &a, convexA)}) {
    if (!otherConvex) continue;
    const Profile& q = other == &a ? pa : pb;
    const dvec2 q0 = q.loops[0].edges[0].from;
    Profile own = evaluate(**shape, std::max(tolerance, evaluationTolerance(**shape)));
    const ProfileBounds box = own.bounds();
    own = polygonal(own, std::max(tolerance, kArcTolerance * glm::length(box.hi - box.lo)));
    std::vector<RegionPtr> parts{Region::leaf(own)->transformed({dmat2(1.0), q0})};
    for (const ProfileLoop& loop : own.loops)
      for (const ProfileEdge& e : loop.edges) {
        const RegionPtr ends[] = {(*other)->transformed({dmat2(1.0), e.from}),
                                  (*other)->transformed({dmat2(1.0), e.to})};
        parts.push_back(Region::leaf(hull(ends, tolerance)));
      }
    return evaluate(*Region::boolean(Region::Op::Union, std::move(parts)), tolerance);
  }
  throw std::invalid_argument("of two regions, one must be convex or a circle");
}

}  // namespace csgray::detail
