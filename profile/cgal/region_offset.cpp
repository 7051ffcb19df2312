// Offsets of regions, as OpenSCAD's offset() has them, with true arcs:
// offset(r) rounds the corners it makes with arcs of radius r, offset(delta)
// makes them sharp (the moved edges extended to where they meet: a mitre)
// or cut (the chamfer: the mitre cut by the line at distance delta from
// the corner, square to its bisector, Clipper's square join, which
// OpenSCAD's chamfer uses). Where an arc meets a corner, its tangent line
// there is what the mitre extends.
//
// Each is the set of points about which one set of curves winds a
// positive number of times (offsetCurves, below), in one arrangement. The
// moved edges' ends are rational points exactly on the circles of radius
// d about the corners (the tangent half-angle substitution gives rational
// points of a circle with a rational radius), so that they and the
// corners' arcs meet exactly; what rounding leaves is dropped by
// positiveWindingFill.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "profile/cgal/polygon_set.h"
#include "profile/region_evaluation.h"
#include "tessellation/tessellation.h"

namespace csgray::detail {

namespace {

using FT = PlaneKernel::FT;
using ExactPoint = PlaneKernel::Point_2;
using ArcTraits = CGAL::Arr_circle_segment_traits_2<PlaneKernel>;

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

double cross(const dvec2& a, const dvec2& b) { return a.x * b.y - a.y * b.x; }
dvec2 rightNormal(const dvec2& t) { return {t.y, -t.x}; }
dvec2 direction(double angle) { return {std::cos(angle), std::sin(angle)}; }

dvec2 toDouble(const ExactPoint& p) { return {CGAL::to_double(p.x()), CGAL::to_double(p.y())}; }

// A rational point on the circle about c of radius r, at about angle θ:
// c ± r·((1 − t²)/(1 + t²), 2t/(1 + t²)) with t = tan(θ/2) (or tan of
// half of θ − π, for the far half, so that |t| ≤ 1) is on the circle
// exactly for any rational t.
// A t within rounding of 0 or ±1 is taken as that, which puts the point at
// c ± (r, 0) or c ± (0, r) exactly: tan(−π/4) is −0.9999999999999999, and
// the ends of a rectangle's edges moved by r would otherwise lie a hair off
// the axes through its corners, and off a circle of radius r about the
// corner that a later boolean holds against them (a rounded plate less its
// corners' circles gave slivers a hair wide that no mesh could hold).
ExactPoint pointOnCircle(const ExactPoint& c, const FT& r, double theta) {
  const double s = std::remainder(theta, kTwoPi);
  const bool near = std::abs(s) <= 0.5 * kPi;
  double tangent = std::tan(0.5 * (near ? s : std::remainder(s - kPi, kTwoPi)));
  if (std::abs(std::abs(tangent) - 1.0) <= 4e-16) tangent = std::copysign(1.0, tangent);
  if (std::abs(tangent) <= 4e-16) tangent = 0.0;
  const FT t(tangent);
  const FT w = r / (1 + t * t);
  const FT x = w * (1 - t * t), y = w * 2 * t;
  return near ? ExactPoint(c.x() + x, c.y() + y) : ExactPoint(c.x() - x, c.y() - y);
}

ArcTraits::Point_2 onePoint(const ExactPoint& p) { return {p.x(), p.y()}; }

enum class Corners { Round, Mitre, Chamfer };

// An offset as the points about which one set of curves winds a positive
// number of times (the convolution method of Minkowski sums: Wein, "Exact
// and efficient construction of planar Minkowski sums using the
// convolution method", ESA 2006; the joins as Clipper's). Every edge is
// moved by |d| along its normal on the offset's side; where the loop turns
// away from that side the moved edges are joined by the arc of radius |d|
// about the corner (or the mitre, or the chamfer), and where it turns
// towards it, through the corner itself.
//
// Why that is exact: let the curves grow from the boundary (moved by 0)
// to the offset (moved by |d|). The winding number about a point x starts
// as 1 inside the region and 0 outside, and changes only as a curve passes
// x: by one, the same way for every curve, since each moves towards the
// offset's side of itself (its right for a growing offset, its left for a
// shrinking one). A join through the corner only lengthens along itself
// and passes nothing. So the winding number is 1 or 0 plus (or minus) the
// number of times x is passed, and it is passed exactly when it lies
// within |d| of the boundary on the offset's side: its nearest boundary
// point is inside an edge, which passes it moving along its normal, or a
// corner that turns away from that side, whose arc passes it. An arc that
// would pass its centre (a hollow smaller than the offset) is cut there:
// beyond, it would turn round and pass points the other way, so its ends
// go on to the centre as segments, which pass nothing, and the points
// beyond are within |d| of its ends, which their corners' arcs pass. A
// mitre or a chamfer passes what the arc would and the rest of its wedge,
// which is what those offsets add at a corner.
//
// The curves meet one another only where the offset folds over itself, so
// the arrangement is about as large as the boundary: a band of pieces
// along it (a strip per edge, a sector per corner, each overlapping its
// neighbours) united by CGAL took four times as long, and on one closing
// (examples/wall_hook.lua's) left a ring along an arc that the inset should
// have taken away (docs/performance.md, 2026-11-27).

// Appends the segment from a to b, unless they are one point (CGAL's
// sweep takes no curve without length).
void addSegment(std::vector<CircleSegment>& curves, const ExactPoint& a, const ExactPoint& b) {
  if (a != b) curves.emplace_back(a, b);
}

// An edge moved by |d| to the offset's side: where it starts and ends
// (exact points on the circles of radius |d| about its ends, shared with
// the joins), the curves between, and its tangents at its ends.
struct MovedEdge {
  ExactPoint start, end;
  std::vector<CircleSegment> curve;
  dvec2 startTangent, endTangent;
};

// side: +1 to move the edge along its right normal (a growing offset), -1
// along its left one.
MovedEdge movedEdge(const ProfileEdge& e, const FT& r, double rr, int side) {
  const double flip = side > 0 ? 0.0 : kPi;
  if (e.kind == ProfileEdge::Kind::Segment) {
    const dvec2 t = glm::normalize(e.to - e.from);
    const double angle = std::atan2(-t.x, t.y) + flip;  // the right normal's, or the left's
    MovedEdge m{pointOnCircle(exactPoint(e.from), r, angle),
                pointOnCircle(exactPoint(e.to), r, angle),
                {},
                t,
                t};
    addSegment(m.curve, m.start, m.end);
    return m;
  }
  // An arc of radius ρ about c: its right normal is the outward radius on
  // a counterclockwise arc, so each point moves to c + k·(its direction
  // from c) with k = ρ ± |d|.
  const double radius = std::sqrt(std::abs(glm::determinant(e.axes)));
  const double sweep = std::clamp(e.angle1 - e.angle0, -kTwoPi, kTwoPi);
  const double turn = sweep > 0.0 ? 1.0 : -1.0;
  const double end = e.angle0 + sweep;
  const auto tangent = [&](double theta) {
    return turn * dvec2(-std::sin(theta), std::cos(theta));
  };
  const bool outward = (turn > 0.0) == (side > 0);
  const double k = outward ? radius + rr : radius - rr;
  const double flipArc = outward ? 0.0 : kPi;
  MovedEdge m{pointOnCircle(exactPoint(e.from), r, e.angle0 + flipArc),
              pointOnCircle(exactPoint(e.to), r, end + flipArc),
              {},
              tangent(e.angle0),
              tangent(end)};
  const ExactPoint c = exactPoint(e.center);
  if (std::abs(sweep) >= kTwoPi) {  // a whole circle: its loop has no corner
    if (k > 0.0)
      m.curve.emplace_back(PlaneKernel::Circle_2(
          c, FT(k) * FT(k), turn > 0.0 ? CGAL::COUNTERCLOCKWISE : CGAL::CLOCKWISE));
    return m;  // a hollow the offset fills leaves nothing
  }
  if (k <= 1e-12 * radius) {  // cut at the centre
    addSegment(m.curve, m.start, c);
    addSegment(m.curve, c, m.end);
    return m;
  }
  const ExactPoint middle = exactPoint(e.center + k * direction(e.angle0 + 0.5 * sweep));
  if (CGAL::collinear(m.start, middle, m.end))  // an arc too flat for its points
    addSegment(m.curve, m.start, m.end);
  else
    m.curve.emplace_back(m.start, middle, m.end);
  return m;
}

// Joins the moved edges at a corner that turns away from the offset's
// side (its outside, for a growing offset): the arc of radius |d| about
// it, the mitre (the moved edges extended to where they meet) or the
// chamfer (the mitre cut by the line at distance |d| from the corner,
// square to its bisector: Clipper's square join, which OpenSCAD's chamfer
// uses). Each of them moves outwards as |d| grows, as the arc does.
void joinOpenCorner(const dvec2& v, const MovedEdge& in, const MovedEdge& out, const FT& r,
                    int side, Corners how, std::vector<CircleSegment>& curves) {
  const double turn = cross(in.endTangent, out.startTangent);
  if (how == Corners::Round) {
    const PlaneKernel::Circle_2 circle(exactPoint(v), r * r,
                                       turn > 0.0 ? CGAL::COUNTERCLOCKWISE : CGAL::CLOCKWISE);
    curves.emplace_back(circle, onePoint(in.end), onePoint(out.start));
    return;
  }
  const double d = CGAL::to_double(r);
  const dvec2 n1 = double(side) * rightNormal(in.endTangent),
              n2 = double(side) * rightNormal(out.startTangent);
  const double c = glm::dot(n1, n2);
  // Mitres of corners that nearly turn back reach far: cut them as
  // Clipper does past its mitre limit.
  constexpr double kMitreLimit = 1e6;
  if (how == Corners::Mitre && 1.0 + c >= 2.0 / (kMitreLimit * kMitreLimit)) {
    const ExactPoint mitre = exactPoint(v + d * (n1 + n2) / (1.0 + c));
    addSegment(curves, in.end, mitre);
    addSegment(curves, mitre, out.start);
    return;
  }
  // The square cut at distance d from v: the moved lines reach it
  // d·tan(α/4) past the moved corners, α the angle the normal turns.
  const double alpha = std::atan2(std::abs(cross(n1, n2)), c);
  const double reach = d * std::tan(0.25 * alpha);
  const ExactPoint c1 = exactPoint(toDouble(in.end) + reach * in.endTangent);
  const ExactPoint c2 = exactPoint(toDouble(out.start) - reach * out.startTangent);
  addSegment(curves, in.end, c1);
  addSegment(curves, c1, c2);
  addSegment(curves, c2, out.start);
}

Profile offsetCurves(const Profile& boundary, double d, Corners how) {
  const FT r(std::abs(d));
  const int side = d > 0.0 ? 1 : -1;
  std::vector<CircleSegment> curves;
  std::vector<MovedEdge> moved;
  std::vector<dvec2> corners;  // corners[i]: where edge i ends
  for (const ProfileLoop& loop : boundary.loops) {
    moved.clear();
    corners.clear();
    for (const ProfileEdge& e : loop.edges) {
      if (e.from == e.to && e.kind == ProfileEdge::Kind::Segment) continue;
      moved.push_back(movedEdge(e, r, std::abs(d), side));
      corners.push_back(e.to);
    }
    for (std::size_t i = 0; i < moved.size(); ++i) {
      const MovedEdge& in = moved[i];
      const MovedEdge& out = moved[(i + 1) % moved.size()];
      curves.insert(curves.end(), in.curve.begin(), in.curve.end());
      if (moved.size() == 1 || in.end == out.start) continue;
      const double turn = std::atan2(cross(in.endTangent, out.startTangent),
                                     glm::dot(in.endTangent, out.startTangent));
      // Where the loop hardly turns, the chord: which way so short an arc
      // runs would be rounding's to say, and the chord passes what the arc
      // would, but for a sliver a rounding error wide.
      if (std::abs(turn) < 1e-9) {
        addSegment(curves, in.end, out.start);
      } else if (turn * side > 0.0) {
        joinOpenCorner(corners[i], in, out, r, side, how, curves);
      } else {
        const ExactPoint corner = exactPoint(corners[i]);
        addSegment(curves, in.end, corner);
        addSegment(curves, corner, out.start);
      }
    }
  }
  return positiveWindingFill(curves);
}

void requireFiniteOffset(double d, const char* name) {
  if (std::isfinite(d)) return;
  std::ostringstream msg;
  msg << "offset: " << name << " must be a finite number (got " << d << ")";
  throw std::invalid_argument(msg.str());
}

Profile offsetBy(const Region& region, double d, Corners corners, double ellipseTolerance) {
  requireTolerance("a region's ellipses", ellipseTolerance);
  ArcPolygonSet set = polygonSetOf(region, ellipseTolerance);
  if (d == 0.0) return profileOf(set);
  return offsetCurves(profileOf(set), d, corners);
}

}  // namespace

Profile offsetRounded(const Region& region, double r, double ellipseTolerance) {
  requireFiniteOffset(r, "r");
  return offsetBy(region, r, Corners::Round, ellipseTolerance);
}

Profile offsetDelta(const Region& region, double delta, bool chamfer, double ellipseTolerance) {
  requireFiniteOffset(delta, "delta");
  return offsetBy(region, delta, chamfer ? Corners::Chamfer : Corners::Mitre, ellipseTolerance);
}

}  // namespace csgray::detail
