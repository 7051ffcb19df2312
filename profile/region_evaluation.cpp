// The parts of region_evaluation.h that need no exact arithmetic: areas and
// polygons of evaluated profiles. evaluate() and the offsets are in cgal/.
#include "profile/region_evaluation.h"

#include <algorithm>
#include <cmath>
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

std::vector<std::vector<dvec2>> flatten(const Profile& profile, double tolerance) {
  requireTolerance("a region's outline", tolerance);
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  std::vector<std::vector<dvec2>> polygons;
  polygons.reserve(profile.loops.size());
  for (const ProfileLoop& loop : profile.loops) {
    std::vector<dvec2>& points = polygons.emplace_back();
    for (const ProfileEdge& e : loop.edges) {
      points.push_back(e.from);
      if (e.bezier()) {
        const int steps = bezierSteps(e, tolerance);
        for (int k = 1; k < steps; ++k) points.push_back(bezierPoint(e, double(k) / steps));
      }
      if (e.kind != ProfileEdge::Kind::Arc) continue;
      double turn = e.angle1 - e.angle0;
      if (std::abs(turn) > kTwoPi) turn = std::copysign(kTwoPi, turn);
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

}  // namespace csgray::detail
