// The parts of region_evaluation.h that need no exact arithmetic: areas and
// polygons of evaluated profiles. evaluate() and the offsets are in cgal/.
#include "profile/region_evaluation.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <numbers>

#include "profile/bezier.h"
#include "tessellation/tessellation.h"

namespace csgray::detail {

namespace {

double cross(const dvec2& a, const dvec2& b) { return a.x * b.y - a.y * b.x; }

// The largest singular value of a 2×2 matrix: how far it stretches.
double largestStretch(const dmat2& m) {
  const double p = glm::dot(m[0], m[0]), s = glm::dot(m[1], m[1]), q = glm::dot(m[0], m[1]);
  return std::sqrt(0.5 * (p + s) + std::hypot(0.5 * (p - s), q));
}

// The radius of an arc of a circle given as evaluate() gives them (axes
// r·I, its angles measured from +x), or 0 for any other edge.
double gridRadius(const ProfileEdge& e) {
  const dmat2& a = e.axes;
  const bool circle = e.kind == ProfileEdge::Kind::Arc && a[0][1] == 0.0 && a[1][0] == 0.0 &&
                      a[0][0] == a[1][1] && a[0][0] > 0.0;
  return circle ? a[0][0] : 0.0;
}

// The points of an arc of a circle about center from angle0 through turn,
// in its sense, after its first point: the points of a cylinder's rim of
// its radius (circlePolygon, placed as primitives/cylinder_tessellation.cpp
// places them: CirclePolygon::pointAt) that lie strictly inside the arc.
// A rim point within 10⁻⁹ of a step of an end counts as at it. An end that
// is another arc of the same circle (`fromJoined`, `toJoined`: no corner)
// is left to the rim's points, the one at that end included where it is a
// step.
//
// A corner keeps its exact point on the circle (a flat face through it
// stays flush with what stands on it), and the rim's chord is followed to
// within the rim's error of it, along the arc (to a point a hair inside
// the chord), before the outline turns to the corner. A chord from the
// corner straight to the next step would sag up to 1.5 times the rim's
// error when it spans nearly a step, and would leave the rim: a cylinder
// of the radius beside the sweep would show the sliver between them as a
// crevice a step long. The turn instead leaves a notch no deeper than the
// rim's error, and the corner's turn stays a turn (a point at the
// corner's own angle would fold back on a flat end that runs along the
// radius). An arc shorter than twice that is its chord.
//
// A rim turned about its axis (its first point not on +x), or mirrored, is
// followed in its own frame, the arc's angles measured from its x axis
// and in its sense; an unturned rim's frame is the plane's, so its points
// are the same bits either way.
void addGridPoints(std::vector<dvec2>& points, const CircleRim& rim, const CirclePolygon& polygon,
                   double angle0, double turn, bool fromJoined, bool toJoined,
                   const dvec2& arriving, const dvec2& leaving) {
  constexpr double kEps = 1e-9;
  const dvec2& center = rim.center;
  const double radius = rim.radius;
  // The rim's frame to the plane's, and back.
  const dmat2 rimFromPlane = glm::inverse(rim.axes);
  auto toPlane = [&](const dvec2& v) { return rim.axes * v; };
  auto toRim = [&](const dvec2& v) { return rimFromPlane * v; };
  if (rim.axes != dmat2(1.0)) {
    // The arc in the rim's frame: from where its start lies there, and the
    // other way round where the rim is mirrored (a pin placed by mirror()).
    const dvec2 start = rimFromPlane * dvec2(std::cos(angle0), std::sin(angle0));
    angle0 = std::atan2(start.y, start.x);
    if (glm::determinant(rim.axes) < 0.0) turn = -turn;
  }
  const double perStep = polygon.segments / (2.0 * std::numbers::pi);
  // In steps along the arc's sense, so that the arc runs upwards.
  const double sense = turn < 0.0 ? -1.0 : 1.0;
  const double u0 = sense * angle0 * perStep, u1 = u0 + std::abs(turn) * perStep;
  // The rim's error along the arc, in steps.
  const double reach = polygon.error * perStep / radius;
  if (!fromJoined && !toJoined && u1 - u0 < 2.0 * reach) return;
  const auto n = static_cast<long long>(polygon.segments);
  auto rimPoint = [&](double k) {
    const long long signedStep = std::llround(sense * k);
    return center +
           toPlane(polygon.pointAt(radius, static_cast<std::uint32_t>(((signedStep % n) + n) % n)));
  };
  // The point of the rim's chord from step k to k + 1 at u.
  auto chordPoint = [&](double k, double u) {
    const dvec2 a = toRim(rimPoint(k) - center), e = toRim(rimPoint(k + 1.0) - rimPoint(k));
    const double theta = sense * u / perStep;
    const dvec2 d(std::cos(theta), std::sin(theta));
    // center + s·d on the chord a + t·e: s (d × e) = a × e; then a part in
    // 10⁹ nearer the centre, so that the outline runs into a cylinder on
    // the rim there rather than along its face to rounding (which left the
    // union slivers that rounding made cross).
    return center + toPlane((1.0 - 1e-9) * (cross(a, e) / cross(d, e)) * d);
  };
  const double first = fromJoined ? std::ceil(u0 - kEps) : std::floor(u0 + kEps) + 1.0;
  const double last = toJoined ? std::floor(u1 - kEps) : std::ceil(u1 - kEps) - 1.0;
  // Room for a turn at both corners, each within reach of its own.
  const double room = std::min(reach, (u1 - u0) / 3.0);
  // Where the edge that meets a corner turns back along the arc (a side
  // running into the circle tangentially from the other side: a cusp), a
  // turn point on the far side of that edge's line (the region lies left
  // of every edge) would cross the edge, and is left out: the corner then
  // lies inside the rim there, and the chord from it to the next rim point
  // inside the rim polygon too. Elsewhere (a side leaving the arc along
  // its tangent, or at an angle) the turn point stays.
  auto turnPoint = [&](double k, double u, const dvec2& corner, const dvec2& edge,
                       double arcAngle) {
    const dvec2 p = chordPoint(k, u);
    const dvec2 arcDirection = toPlane(sense * dvec2(-std::sin(arcAngle), std::cos(arcAngle)));
    if (glm::dot(edge, arcDirection) < 0.0 && cross(edge, p - corner) < 0.0) return;
    points.push_back(p);
  };
  if (!fromJoined && (first > last || first - u0 > room))
    turnPoint(std::floor(u0 + kEps), u0 + room, points.back(), arriving, angle0);
  for (double k = first; k <= last; k += 1.0) points.push_back(rimPoint(k));
  if (!toJoined && (first > last || u1 - last > room)) {
    const double a = sense * u1 / perStep;
    turnPoint(std::ceil(u1 - kEps) - 1.0, u1 - room,
              center + toPlane(radius * dvec2(std::cos(a), std::sin(a))), leaving, a);
  }
}

// The direction in which an edge leaves its start (atEnd false) or reaches
// its end (atEnd true).
dvec2 tangentAt(const ProfileEdge& e, bool atEnd) {
  switch (e.kind) {
    case ProfileEdge::Kind::Segment:
      return e.to - e.from;
    case ProfileEdge::Kind::Arc: {
      const double angle = atEnd ? e.angle1 : e.angle0;
      const double sense = e.angle1 < e.angle0 ? -1.0 : 1.0;
      return sense * (e.axes * dvec2(-std::sin(angle), std::cos(angle)));
    }
    case ProfileEdge::Kind::Quadratic:
      return atEnd ? e.to - e.control1 : e.control1 - e.from;
    case ProfileEdge::Kind::Cubic:
      return atEnd ? e.to - e.control2 : e.control1 - e.from;
  }
  return e.to - e.from;
}

}  // namespace

double area(const Profile& evaluated) {
  // Green's theorem: the area is ½∮(x dy − y dx). Along a segment that is
  // ½ from × to; along an arc p(θ) = c + A·(cos θ, sin θ) the integrand is
  // c × p'(θ) + det A, which integrates to c × (to − from) + det A·Δθ;
  // along a Bézier curve it is a polynomial (bezierAreaTerm).
  double sum = 0.0;
  for (const ProfileLoop& loop : evaluated.loops)
    for (const ProfileEdge& e : loop.edges) {
      if (e.kind == ProfileEdge::Kind::Segment)
        sum += cross(e.from, e.to);
      else if (e.bezier())
        sum += bezierAreaTerm(e);
      else
        sum += cross(e.center, e.to - e.from) + glm::determinant(e.axes) * (e.angle1 - e.angle0);
    }
  return 0.5 * sum;
}

double evaluationTolerance(const Region& region) {
  bool curves = false;
  region.forEachLeaf([&](const Profile& leaf) {
    for (const ProfileLoop& loop : leaf.loops)
      for (const ProfileEdge& e : loop.edges) curves = curves || e.bezier();
  });
  const double fraction = curves ? 1e-5 : 1e-7;
  const ProfileBounds& b = region.bounds();
  const double size = b.empty() ? 0.0 : std::max(b.hi.x - b.lo.x, b.hi.y - b.lo.y);
  return size > 0.0 ? fraction * size : fraction;
}

std::vector<std::vector<dvec2>> flatten(const Profile& profile, double tolerance,
                                        std::span<const CircleRim> rims, double rimTolerance) {
  requireTolerance("a region's outline", tolerance);
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  // The rim an arc lies on, if any: its centre to a part in 10⁹ of its
  // radius and of its distance from the origin, or within the grid of 2⁻³⁰
  // to which the exporter snaps the frames of a part turned as a whole.
  auto rimOf = [&](const ProfileEdge& e) -> const CircleRim* {
    const double r = gridRadius(e);
    if (r == 0.0) return nullptr;
    for (const CircleRim& rim : rims)
      if (std::abs(rim.radius - r) <= 1e-9 * r &&
          glm::length(rim.center - e.center) <= 1e-9 * (r + glm::length(e.center)) + 0x1p-30)
        return &rim;
    return nullptr;
  };
  std::vector<std::vector<dvec2>> polygons;
  polygons.reserve(profile.loops.size());
  for (const ProfileLoop& loop : profile.loops) {
    std::vector<dvec2>& points = polygons.emplace_back();
    const std::size_t count = loop.edges.size();
    for (std::size_t i = 0; i < count; ++i) {
      const ProfileEdge& e = loop.edges[i];
      const ProfileEdge& before = loop.edges[(i + count - 1) % count];
      const CircleRim* rim = rims.empty() ? nullptr : rimOf(e);
      const double onGrid = rim ? gridRadius(e) : 0.0;
      // Where two arcs of one circle meet (a circle CGAL split into
      // halves), the point between them is no corner: the grid's points
      // stand in for it, as on a cylinder's rim.
      auto sameCircle = [&](const ProfileEdge& other) {
        return onGrid > 0.0 && gridRadius(other) == onGrid && other.center == e.center;
      };
      const bool joined = sameCircle(before);
      if (!joined) points.push_back(e.from);
      if (e.bezier()) {
        const int steps = bezierSteps(e, tolerance);
        for (int k = 1; k < steps; ++k) points.push_back(bezierPoint(e, double(k) / steps));
      }
      if (e.kind != ProfileEdge::Kind::Arc) continue;
      double turn = e.angle1 - e.angle0;
      if (std::abs(turn) > kTwoPi) turn = std::copysign(kTwoPi, turn);
      if (onGrid > 0.0) {
        // About the rim's own centre and radius, to which the arc's may
        // differ by rounding: the cylinder's points, bit for bit.
        const ProfileEdge& after = loop.edges[(i + 1) % count];
        addGridPoints(points, *rim, circlePolygon(rim->radius, rimTolerance), e.angle0, turn,
                      joined, sameCircle(after), tangentAt(before, true), tangentAt(after, false));
        continue;
      }
      // An ellipse's inscribed polygon is the image of the unit circle's,
      // so it strays by at most the circle's sagitta times the largest
      // stretch of the axes; a full circle gets at least 8 sides (as
      // arcSegments gives the cylinders), an arc its share of them.
      const int least =
          std::max(1, static_cast<int>(std::ceil(8.0 * std::abs(turn) / kTwoPi - 1e-9)));
      const int n = arcSegments(largestStretch(e.axes), std::abs(turn), tolerance, least);
      for (int k = 1; k < n; ++k) points.push_back(e.arcPoint(e.angle0 + turn * k / n));
    }
  }
  return polygons;
}

ProfileBounds tightBounds(const Region& region) {
  return evaluate(region, evaluationTolerance(region)).bounds();
}

}  // namespace csgray::detail
