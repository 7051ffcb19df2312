#include "profile/profile.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <numbers>

#include "profile/bezier.h"

namespace csgray::detail {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Is θ on the arc from a0 to a1 (either way round), ends included?
bool onArc(double theta, double a0, double a1) {
  const double lo = std::min(a0, a1), hi = std::max(a0, a1);
  if (hi - lo >= kTwoPi) return true;
  const double t = lo + std::fmod(std::fmod(theta - lo, kTwoPi) + kTwoPi, kTwoPi);
  return t <= hi;
}

bool inArcCap(const dvec2& p, const ProfileEdge& e) {
  return inUnitArcCap(glm::inverse(e.axes) * (p - e.center), e.angle0, e.angle1);
}

}  // namespace

// By the half-open rule: an end exactly at p's height counts for the edge
// that lies above it.
bool halfLineCrossesSegment(const dvec2& p, const dvec2& a, const dvec2& b) {
  if ((a.y > p.y) == (b.y > p.y)) return false;
  const double x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
  return x > p.x;
}

// The chord cuts the circle in two; the arc bounds the part that holds its
// middle point. The chord over a half-angle h about the middle direction m
// is the line w·m = cos h, and the arc's side is w·m > cos h (for an arc
// past a half circle too, where cos h < 0). Tested so, not by the side of
// the chord's two ends, a tiny arc's cap stays tiny. A whole turn bounds
// the disc.
bool inUnitArcCap(const dvec2& w, double angle0, double angle1) {
  if (glm::dot(w, w) >= 1.0) return false;
  if (std::abs(angle1 - angle0) >= kTwoPi) return true;
  const double mid = 0.5 * (angle0 + angle1);
  const double halfAngle = 0.5 * std::abs(angle1 - angle0);
  return glm::dot(w, dvec2(std::cos(mid), std::sin(mid))) > std::cos(halfAngle);
}

ProfileEdge ProfileEdge::segment(const dvec2& a, const dvec2& b) {
  ProfileEdge e;
  e.kind = Kind::Segment;
  e.from = a;
  e.to = b;
  return e;
}

ProfileEdge ProfileEdge::arc(const dvec2& center, const dmat2& axes, double angle0, double angle1) {
  ProfileEdge e;
  e.kind = Kind::Arc;
  e.center = center;
  e.axes = axes;
  e.angle0 = angle0;
  e.angle1 = angle1;
  e.from = e.arcPoint(angle0);
  e.to = std::abs(angle1 - angle0) >= kTwoPi ? e.from : e.arcPoint(angle1);
  return e;
}

ProfileEdge ProfileEdge::quadratic(const dvec2& a, const dvec2& control, const dvec2& b) {
  ProfileEdge e;
  e.kind = Kind::Quadratic;
  e.from = a;
  e.control1 = control;
  e.to = b;
  return e;
}

ProfileEdge ProfileEdge::cubic(const dvec2& a, const dvec2& control1, const dvec2& control2,
                               const dvec2& b) {
  ProfileEdge e;
  e.kind = Kind::Cubic;
  e.from = a;
  e.control1 = control1;
  e.control2 = control2;
  e.to = b;
  return e;
}

dvec2 ProfileEdge::arcPoint(double theta) const {
  return center + axes * dvec2(std::cos(theta), std::sin(theta));
}

bool ProfileEdge::circular() const {
  const dmat2 g = glm::transpose(axes) * axes;  // s²·I for a circle
  const double scale = std::max(g[0][0], g[1][1]);
  return std::abs(g[0][0] - g[1][1]) <= 1e-12 * scale && std::abs(g[0][1]) <= 1e-12 * scale;
}

ProfileEdge ProfileEdge::transformed(const Affine2& map) const {
  ProfileEdge e = *this;
  e.from = map.apply(from);
  e.to = map.apply(to);
  if (kind == Kind::Arc) {
    e.center = map.apply(center);
    e.axes = map.linear * axes;
  }
  // An affine map of a Bézier curve is the curve of the mapped control
  // points.
  e.control1 = map.apply(control1);
  e.control2 = map.apply(control2);
  return e;
}

void ProfileBounds::include(const dvec2& p) {
  lo = glm::min(lo, p);
  hi = glm::max(hi, p);
}

void ProfileBounds::include(const ProfileBounds& b) {
  lo = glm::min(lo, b.lo);
  hi = glm::max(hi, b.hi);
}

bool Profile::contains(const dvec2& p) const {
  // (A NaN or infinite point fails every comparison of the crossing tests
  // alike, which can make an arc count it in.)
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
  bool inside = false;
  for (const ProfileLoop& loop : loops)
    for (const ProfileEdge& e : loop.edges) {
      // An arc crosses as often as its chord, plus once more when p lies
      // between the two (even-odd: only the parity matters).
      if (e.bezier()) {
        if (bezierCrossesRight(p, e)) inside = !inside;
        continue;
      }
      if (halfLineCrossesSegment(p, e.from, e.to)) inside = !inside;
      if (e.kind == ProfileEdge::Kind::Arc && inArcCap(p, e)) inside = !inside;
    }
  return inside;
}

ProfileBounds Profile::bounds() const {
  ProfileBounds b;
  for (const ProfileLoop& loop : loops)
    for (const ProfileEdge& e : loop.edges) {
      b.include(e.from);
      b.include(e.to);
      if (e.bezier()) includeBezier(b, e);
      if (e.kind != ProfileEdge::Kind::Arc) continue;
      // x(θ) = cx + a·cos θ + c·sin θ is extreme where tan θ = c / a, and
      // likewise y; those extremes that lie on the arc widen the box.
      for (int axis = 0; axis < 2; ++axis) {
        const double theta = std::atan2(e.axes[1][axis], e.axes[0][axis]);
        for (double t : {theta, theta + std::numbers::pi})
          if (onArc(t, e.angle0, e.angle1)) b.include(e.arcPoint(t));
      }
    }
  return b;
}

Profile Profile::transformed(const Affine2& map) const {
  Profile out;
  out.loops.reserve(loops.size());
  for (const ProfileLoop& loop : loops) {
    ProfileLoop& l = out.loops.emplace_back();
    l.edges.reserve(loop.edges.size());
    for (const ProfileEdge& e : loop.edges) l.edges.push_back(e.transformed(map));
  }
  return out;
}

}  // namespace csgray::detail
