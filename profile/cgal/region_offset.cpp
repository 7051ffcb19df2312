// Offsets of regions, as OpenSCAD's offset() has them, with true arcs.
//
// Both offsets are the region united with, or less, a band along its
// boundary: the points within d of an edge, measured along the edge's
// normals (a strip beside a segment, an annular sector beside an arc, on
// both sides: the side away from the offset is in the region, or outside
// it, anyway), plus what each corner adds. A rounded offset adds the
// sector of the disc of radius d about the corner that the strips miss, so
// that the band is every point within d of the boundary: offset(r) =
// region ∪ band for r > 0, region − band for r < 0. An offset by delta adds, at the corners that
// turn towards the offset's side, the mitre (the wedge up to where the moved tangent lines meet) or
// the chamfer (the mitre cut by the line at distance d from the corner, perpendicular to the
// mitre's bisector: Clipper's square joins, which OpenSCAD's chamfer uses). Where an arc meets a
// corner, its tangent line there is what the mitre extends.
//
// Rounded offsets of regions bounded by segments alone are made by the
// convolution method instead, which is faster (convolutionOffset, below).
//
// The strips' corners are rational points exactly on the circles they
// meet (the tangent half-angle substitution gives rational points of a
// circle with a rational radius), so that strips and discs meet without
// slivers where they can; what rounding leaves is dropped by profileOf.
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
ExactPoint pointOnCircle(const ExactPoint& c, const FT& r, double theta) {
  const double s = std::remainder(theta, kTwoPi);
  const bool near = std::abs(s) <= 0.5 * kPi;
  const FT t(std::tan(0.5 * (near ? s : std::remainder(s - kPi, kTwoPi))));
  const FT w = r / (1 + t * t);
  const FT x = w * (1 - t * t), y = w * 2 * t;
  return near ? ExactPoint(c.x() + x, c.y() + y) : ExactPoint(c.x() - x, c.y() - y);
}

ArcTraits::Point_2 onePoint(const ExactPoint& p) { return {p.x(), p.y()}; }

// An edge's direction at its start and end, and its offset corners there:
// the points at distance d along the normals on the left (inner, -1) and
// right (outer, +1) side, exact.
struct EdgeEnds {
  dvec2 startTangent, endTangent;
  ExactPoint startCorner[2], endCorner[2];  // [0]: inner side, [1]: outer side
};

struct Band {
  double d;
  std::vector<ArcPolygon> pieces;
};

// A closed loop of curves (counterclockwise) as a polygon of x-monotone
// pieces that follow each other.
ArcPolygon polygonOfCurves(const std::vector<CircleSegment>& curves) {
  const ArcTraits traits;
  const auto makeMonotone = traits.make_x_monotone_2_object();
  std::vector<ArcTraits::X_monotone_curve_2> pieces;
  for (const CircleSegment& c : curves) {
    std::vector<boost::variant<ArcTraits::Point_2, ArcTraits::X_monotone_curve_2>> parts;
    makeMonotone(c, std::back_inserter(parts));
    std::vector<ArcTraits::X_monotone_curve_2> own;
    for (const auto& part : parts)
      if (const auto* x = boost::get<ArcTraits::X_monotone_curve_2>(&part)) own.push_back(*x);
    // Chain them from the curve's source (a whole circle from any piece).
    for (std::size_t i = 0; i < own.size(); ++i) {
      if (i == 0 && !c.is_full()) {
        for (std::size_t j = 0; j < own.size(); ++j)
          if (own[j].source() == c.source()) std::swap(own[0], own[j]);
      } else if (i > 0) {
        for (std::size_t j = i; j < own.size(); ++j)
          if (own[j].source() == own[i - 1].target()) std::swap(own[i], own[j]);
      }
    }
    pieces.insert(pieces.end(), own.begin(), own.end());
  }
  return ArcPolygon(pieces.begin(), pieces.end());
}

// The polygon of corner points (doubles or exact), turned counterclockwise.
void addPolygon(Band& band, std::vector<ExactPoint> points) {
  double twiceArea = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i)
    twiceArea += cross(toDouble(points[i]), toDouble(points[(i + 1) % points.size()]));
  if (twiceArea == 0.0) return;
  if (twiceArea < 0.0) std::reverse(points.begin(), points.end());
  std::vector<CircleSegment> curves;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const ExactPoint& a = points[i];
    const ExactPoint& b = points[(i + 1) % points.size()];
    if (a != b) curves.emplace_back(a, b);
  }
  if (curves.size() >= 3) band.pieces.push_back(polygonOfCurves(curves));
}

void addDisc(Band& band, const dvec2& center) {
  const FT r(band.d);
  band.pieces.push_back(
      polygonOfCurves({CircleSegment(PlaneKernel::Circle_2(exactPoint(center), r * r))}));
}

// The points within d of a segment along its normals.
EdgeEnds addSegmentStrip(Band& band, const ProfileEdge& e) {
  const dvec2 t = glm::normalize(e.to - e.from);
  const double angle = std::atan2(-t.x, t.y);  // of the right normal
  const ExactPoint a = exactPoint(e.from), b = exactPoint(e.to);
  const FT d(band.d);
  EdgeEnds ends{t,
                t,
                {pointOnCircle(a, d, angle + kPi), pointOnCircle(a, d, angle)},
                {pointOnCircle(b, d, angle + kPi), pointOnCircle(b, d, angle)}};
  addPolygon(band,
             {ends.startCorner[0], ends.endCorner[0], ends.endCorner[1], ends.startCorner[1]});
  return ends;
}

// The annulus of the points within d of a whole circle, in two halves so
// that each piece is one simple loop: concentric circles, exactly.
void addAnnulus(Band& band, const ExactPoint& c, const FT& radius, double start) {
  const FT outer = radius + FT(band.d), inner = radius - FT(band.d);
  for (const double lo : {start, start + kPi}) {
    const double hi = lo + kPi;
    const ExactPoint p0 = pointOnCircle(c, outer, lo), p1 = pointOnCircle(c, outer, hi);
    std::vector<CircleSegment> curves;
    curves.emplace_back(PlaneKernel::Circle_2(c, outer * outer, CGAL::COUNTERCLOCKWISE),
                        onePoint(p0), onePoint(p1));
    if (inner > 0) {
      const ExactPoint q0 = pointOnCircle(c, inner, lo), q1 = pointOnCircle(c, inner, hi);
      curves.emplace_back(p1, q1);
      curves.emplace_back(PlaneKernel::Circle_2(c, inner * inner, CGAL::CLOCKWISE), onePoint(q1),
                          onePoint(q0));
      curves.emplace_back(q0, p0);
    } else {
      curves.emplace_back(p1, c);
      curves.emplace_back(c, p0);
    }
    band.pieces.push_back(polygonOfCurves(curves));
  }
}

// The annular sector of the points within d of an arc along its radii (a
// pie where d reaches the centre). Its corners are on the discs of radius
// d about the arc's ends exactly, so that a rounded offset's discs meet
// them without slivers; its arcs are the circles through those corners
// and the middle of the ideal ones.
EdgeEnds addArcSector(Band& band, const ProfileEdge& e) {
  const double radius = std::sqrt(std::abs(glm::determinant(e.axes)));
  const double sweep = std::clamp(e.angle1 - e.angle0, -kTwoPi, kTwoPi);
  const double turn = sweep > 0.0 ? 1.0 : -1.0;
  const double end = e.angle0 + sweep, middle = e.angle0 + 0.5 * sweep;
  // The tangent turns with the arc; the right normal of a counterclockwise
  // arc points away from the centre.
  const auto tangent = [&](double theta) {
    return turn * dvec2(-std::sin(theta), std::cos(theta));
  };
  const FT d(band.d);
  const ExactPoint c = exactPoint(e.center);
  if (std::abs(sweep) >= kTwoPi) {
    addAnnulus(band, c, FT(radius), e.angle0);
    const ExactPoint a = pointOnCircle(c, FT(radius) - d, e.angle0),
                     b = pointOnCircle(c, FT(radius) + d, e.angle0);
    return {tangent(e.angle0),
            tangent(end),
            {turn > 0 ? a : b, turn > 0 ? b : a},
            {turn > 0 ? a : b, turn > 0 ? b : a}};
  }
  const ExactPoint from = exactPoint(e.from), to = exactPoint(e.to);
  const ExactPoint startAway = pointOnCircle(from, d, e.angle0),
                   startIn = pointOnCircle(from, d, e.angle0 + kPi);
  const ExactPoint endAway = pointOnCircle(to, d, end), endIn = pointOnCircle(to, d, end + kPi);
  const ExactPoint outerMiddle = exactPoint(e.center + (radius + band.d) * direction(middle));
  // Counterclockwise for a counterclockwise arc: out along the far arc,
  // back along the near one (or through the centre).
  std::vector<CircleSegment> curves;
  // A clockwise arc's sector is the counterclockwise one with its ends
  // swapped.
  const bool ccw = turn > 0.0;
  const ExactPoint& first = ccw ? startAway : endAway;
  const ExactPoint& last = ccw ? endAway : startAway;
  const ExactPoint& firstIn = ccw ? startIn : endIn;
  const ExactPoint& lastIn = ccw ? endIn : startIn;
  curves.emplace_back(first, outerMiddle, last);
  if (radius > band.d) {
    curves.emplace_back(last, lastIn);
    curves.emplace_back(lastIn, exactPoint(e.center + (radius - band.d) * direction(middle)),
                        firstIn);
    curves.emplace_back(firstIn, first);
  } else {
    curves.emplace_back(last, c);
    curves.emplace_back(c, first);
  }
  band.pieces.push_back(polygonOfCurves(curves));
  // [0]: the left side, [1]: the right side.
  if (turn > 0.0) return {tangent(e.angle0), tangent(end), {startIn, startAway}, {endIn, endAway}};
  return {tangent(e.angle0), tangent(end), {startAway, startIn}, {endAway, endIn}};
}

EdgeEnds addEdgeBand(Band& band, const ProfileEdge& e) {
  return e.kind == ProfileEdge::Kind::Segment ? addSegmentStrip(band, e) : addArcSector(band, e);
}

enum class Corners { Round, Mitre, Chamfer };

// Do two edges meet without a corner (an arc and its tangent)? Their
// strips' ends then lie a rounding error apart, and which way the boundary
// turns is noise: a disc of radius d about the point covers the seam, and
// what it adds is within d of the boundary, in any offset (or out of any
// inset) anyway.
bool smooth(const EdgeEnds& in, const EdgeEnds& out) {
  return glm::dot(in.endTangent, out.startTangent) > 0.0 &&
         std::abs(cross(in.endTangent, out.startTangent)) <= 1e-12;
}

// The part of the disc of radius d about a corner that the strips miss:
// the sector between the edges' normals on the side the boundary turns
// towards. A point within d of the boundary whose nearest boundary point
// is the corner is there; every other one is in the strip of the edge its
// nearest point is on. The sector's tip is behind the corner, as the
// wedges' are.
void addCornerSector(Band& band, const dvec2& v, const EdgeEnds& in, const EdgeEnds& out) {
  const bool left = cross(in.endTangent, out.startTangent) > 0.0;
  const int side = left ? 1 : 0;  // a left turn opens on the right
  const ExactPoint& p1 = in.endCorner[side];
  const ExactPoint& p2 = out.startCorner[side];
  if (p1 == p2) return;
  const dvec2 n1 = rightNormal(in.endTangent), n2 = rightNormal(out.startTangent);
  const double spread = glm::length(n1 + n2);
  const dvec2 gap = spread > 1e-9 ? (left ? 1.0 : -1.0) * (n1 + n2) / spread : in.endTangent;
  const ExactPoint tip = exactPoint(v - 0.5 * band.d * gap);
  const FT d(band.d);
  const PlaneKernel::Circle_2 circle(exactPoint(v), d * d, CGAL::COUNTERCLOCKWISE);
  // Counterclockwise: the arc runs from p1 to p2 on a left turn, back on a
  // right one.
  const ExactPoint& a = left ? p1 : p2;
  const ExactPoint& b = left ? p2 : p1;
  band.pieces.push_back(
      polygonOfCurves({CircleSegment(tip, a), CircleSegment(circle, onePoint(a), onePoint(b)),
                       CircleSegment(b, tip)}));
}

// The wedge that fills the corner at v between an edge that ends there and
// one that starts there, on the given side (+1 outer, -1 inner), if the
// boundary turns towards that side.
void addCornerWedge(Band& band, const dvec2& v, const EdgeEnds& in, const EdgeEnds& out, int side,
                    Corners corners) {
  const double turn = cross(in.endTangent, out.startTangent);
  if (turn * side <= 0.0) return;
  const ExactPoint& p1 = in.endCorner[side > 0 ? 1 : 0];
  const ExactPoint& p2 = out.startCorner[side > 0 ? 1 : 0];
  const dvec2 n1 = rightNormal(in.endTangent), n2 = rightNormal(out.startTangent);
  const double c = glm::dot(n1, n2);
  const double alpha = std::atan2(std::abs(cross(n1, n2)), c);  // the angle the normal turns
  const double d = band.d;
  // Mitres of corners that nearly turn back reach far: cut them as
  // Clipper does past its mitre limit.
  constexpr double kMitreLimit = 1e6;
  // The wedge's tip is not the corner but a point d/2 behind it, on the
  // other side: its sides then cross the strips' ends instead of running
  // along them a rounding error apart (which left needles), and what it
  // adds there is within d of the corner, in the band anyway.
  const double spread = glm::length(n1 + n2);
  const dvec2 gap =
      spread > 1e-9 ? double(side) * (n1 + n2) / spread : in.endTangent;  // the way the wedge opens
  const ExactPoint tip = exactPoint(v - 0.5 * d * gap);
  if (corners == Corners::Mitre && 1.0 + c >= 2.0 / (kMitreLimit * kMitreLimit)) {
    const dvec2 mitre = v + side * d * (n1 + n2) / (1.0 + c);
    addPolygon(band, {tip, p1, exactPoint(mitre), p2});
    return;
  }
  // The square cut at distance d from v: the moved lines reach it
  // d·tan(α/4) past the moved corners (Clipper's square join).
  const double reach = d * std::tan(0.25 * alpha);
  const dvec2 c1 = toDouble(p1) + reach * in.endTangent;
  const dvec2 c2 = toDouble(p2) - reach * out.startTangent;
  addPolygon(band, {tip, p1, exactPoint(c1), exactPoint(c2), p2});
}

// The band of the boundary of an evaluated profile, on both sides of its
// edges, with the corners of `side` filled as `corners` says.
ArcPolygonSet boundaryBand(const Profile& boundary, double d, int side, Corners corners) {
  Band band{d, {}};
  for (const ProfileLoop& loop : boundary.loops) {
    std::vector<EdgeEnds> ends;
    ends.reserve(loop.edges.size());
    for (const ProfileEdge& e : loop.edges) ends.push_back(addEdgeBand(band, e));
    for (std::size_t i = 0; i < loop.edges.size(); ++i) {
      if (loop.edges.size() == 1) break;  // a whole circle has no corner
      const std::size_t next = (i + 1) % loop.edges.size();
      const dvec2 v = loop.edges[i].to;
      if (smooth(ends[i], ends[next]))
        addDisc(band, v);
      else if (corners == Corners::Round)
        addCornerSector(band, v, ends[i], ends[next]);
      else
        addCornerWedge(band, v, ends[i], ends[next], side, corners);
    }
  }
  ArcPolygonSet set;
  if (!band.pieces.empty()) set.join(band.pieces.begin(), band.pieces.end());
  return set;
}

// A rounded offset of a boundary of segments, made as Minkowski sums with
// a disc are by the convolution method (Wein, "Exact and efficient
// construction of planar Minkowski sums using the convolution method",
// ESA 2006): every edge moved by |d| along its normal on the offset's
// side, and the moved edges of each corner joined by the arc of radius |d|
// about it that turns the way the loop turns there (backwards, where the
// loop turns away from the offset's side). The curves cross one another
// only where the offset folds over itself, not at every corner as the
// band's pieces overlap, so the arrangement is about as large as the
// boundary.
//
// The offset is then the set of points about which these curves wind a
// positive number of times. Grow the disc about x from a point to radius
// |d|: the winding number changes only as the moved curves pass x, and it
// counts the pieces of the region within the disc less their holes (the
// convolution's winding numbers, after Guibas, Ramshaw and Stolfi, "A
// kinetic framework for computational geometry", FOCS 1983). A piece has
// a hole only where a hole of the region lies wholly within the disc, so
// the rule is exact when no hole is that small. For an inset (d < 0, the
// edges moved inwards) the curves are those of the complement run
// backwards, and the same holds of the region's islands.
// segmentsWithoutSmallLoops says when it may be used; the tests hold both
// to distances from the boundary.
Profile convolutionOffset(const Profile& boundary, double d) {
  const FT r(std::abs(d));
  std::vector<CircleSegment> curves;
  struct MovedEdge {
    dvec2 to, tangent;
    ExactPoint start, end;
  };
  std::vector<MovedEdge> moved;
  for (const ProfileLoop& loop : boundary.loops) {
    moved.clear();
    for (const ProfileEdge& e : loop.edges) {
      if (e.from == e.to) continue;
      const dvec2 t = glm::normalize(e.to - e.from);
      // The angle of the right normal (away from the region), or of the
      // left one for an inset.
      const double angle = std::atan2(-t.x, t.y) + (d > 0.0 ? 0.0 : kPi);
      moved.push_back({e.to, t, pointOnCircle(exactPoint(e.from), r, angle),
                       pointOnCircle(exactPoint(e.to), r, angle)});
    }
    for (std::size_t i = 0; i < moved.size(); ++i) {
      const MovedEdge& in = moved[i];
      const MovedEdge& out = moved[(i + 1) % moved.size()];
      curves.emplace_back(in.start, in.end);
      if (in.end == out.start) continue;
      // Where the loop hardly turns, the chord: which way so short an arc
      // runs would be rounding's to say.
      const double turn =
          std::atan2(cross(in.tangent, out.tangent), glm::dot(in.tangent, out.tangent));
      if (std::abs(turn) < 1e-9) {
        curves.emplace_back(in.end, out.start);
        continue;
      }
      const PlaneKernel::Circle_2 circle(exactPoint(in.to), r * r,
                                         turn > 0.0 ? CGAL::COUNTERCLOCKWISE : CGAL::CLOCKWISE);
      curves.emplace_back(circle, onePoint(in.end), onePoint(out.start));
    }
  }
  return positiveWindingFill(curves);
}

// May a rounded offset by d take the convolution? Every edge a segment,
// and no loop that could lie within a disc of radius |d|: a hole for a
// growing offset, an island for a shrinking one. A hole that lies within
// such a disc about its box's centre is filled by the offset whole, so it
// is left out of the boundary; one whose box is less than 2|d| wide and
// tall, but does not lie in that disc, might still fit in another.
bool segmentsWithoutSmallLoops(Profile& boundary, double d) {
  const double r = std::abs(d);
  std::vector<ProfileLoop> kept;
  for (ProfileLoop& loop : boundary.loops) {
    double twiceArea = 0.0;
    ProfileBounds box;
    for (const ProfileEdge& e : loop.edges) {
      if (e.kind != ProfileEdge::Kind::Segment) return false;
      twiceArea += cross(e.from, e.to);
      box.include(e.from);
    }
    const bool hole = twiceArea < 0.0;
    const dvec2 size = box.hi - box.lo;
    if (hole != (d > 0.0) || std::max(size.x, size.y) > 2.0 * r) {
      kept.push_back(std::move(loop));
      continue;
    }
    if (!hole || 0.5 * glm::length(size) >= r) return false;
  }
  boundary.loops = std::move(kept);
  return true;
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
  const Profile boundary = profileOf(set);
  if (Profile segments = boundary;
      corners == Corners::Round && segmentsWithoutSmallLoops(segments, d))
    return convolutionOffset(segments, d);
  const ArcPolygonSet band = boundaryBand(boundary, std::abs(d), d > 0.0 ? 1 : -1, corners);
  if (d > 0.0)
    set.join(band);
  else
    set.difference(band);
  return profileOf(set);
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
