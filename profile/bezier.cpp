#include "profile/bezier.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "engine/solvers/quartic.h"

namespace csgray::detail {

namespace {

// The control points P0 ... Pn.
int controlPoints(const ProfileEdge& e, dvec2* p) {
  p[0] = e.from;
  p[1] = e.control1;
  if (e.kind == ProfileEdge::Kind::Quadratic) {
    p[2] = e.to;
    return 2;
  }
  p[2] = e.control2;
  p[3] = e.to;
  return 3;
}

}  // namespace

dvec2 BezierPolynomial::at(double s) const {
  dvec2 v = c[degree];
  for (int k = degree - 1; k >= 0; --k) v = v * s + c[k];
  return v;
}

dvec2 BezierPolynomial::slope(double s) const {
  dvec2 v = double(degree) * c[degree];
  for (int k = degree - 1; k >= 1; --k) v = v * s + double(k) * c[k];
  return v;
}

BezierPolynomial bezierPolynomial(const ProfileEdge& e) {
  dvec2 p[4];
  BezierPolynomial b;
  b.degree = controlPoints(e, p);
  b.c[0] = p[0];
  if (b.degree == 2) {
    b.c[1] = 2.0 * (p[1] - p[0]);
    b.c[2] = p[0] - 2.0 * p[1] + p[2];
  } else {
    b.c[1] = 3.0 * (p[1] - p[0]);
    b.c[2] = 3.0 * (p[0] - 2.0 * p[1] + p[2]);
    b.c[3] = p[3] - p[0] + 3.0 * (p[1] - p[2]);
  }
  return b;
}

dvec2 bezierPoint(const ProfileEdge& e, double s) {
  dvec2 p[4];
  const int n = controlPoints(e, p);
  if (s == 0.0) return p[0];
  if (s == 1.0) return p[n];
  for (int level = n; level > 0; --level)
    for (int k = 0; k < level; ++k) p[k] = (1.0 - s) * p[k] + s * p[k + 1];
  return p[0];
}

void includeBezier(ProfileBounds& box, const ProfileEdge& e) {
  box.include(e.from);
  box.include(e.to);
  const BezierPolynomial b = bezierPolynomial(e);
  for (int axis = 0; axis < 2; ++axis) {
    // B'(s)[axis] = d0 + d1·s + d2·s².
    const double d0 = b.c[1][axis], d1 = 2.0 * b.c[2][axis],
                 d2 = b.degree == 3 ? 3.0 * b.c[3][axis] : 0.0;
    double roots[2];
    int count = 0;
    if (d2 == 0.0) {
      if (d1 != 0.0) roots[count++] = -d0 / d1;
    } else {
      const double disc = d1 * d1 - 4.0 * d2 * d0;
      if (disc >= 0.0) {
        const double q = -0.5 * (d1 + std::copysign(std::sqrt(disc), d1));
        roots[count++] = q / d2;
        if (q != 0.0) roots[count++] = d0 / q;
      }
    }
    for (int i = 0; i < count; ++i)
      if (roots[i] > 0.0 && roots[i] < 1.0) box.include(bezierPoint(e, roots[i]));
  }
}

bool bezierCrossesRight(const dvec2& p, const ProfileEdge& e) {
  // The curve lies in its control points' hull: when that is all to the
  // right of p, every crossing counts and their parity is the ends' (the
  // segment rule); when it is all left of p, or all above or below it,
  // none counts.
  dvec2 c[4];
  const int degree = controlPoints(e, c);
  dvec2 lo = c[0], hi = c[0];
  for (int k = 1; k <= degree; ++k) lo = glm::min(lo, c[k]), hi = glm::max(hi, c[k]);
  if (hi.x <= p.x || lo.y > p.y || hi.y <= p.y) return false;
  if (lo.x > p.x) return (e.from.y > p.y) != (e.to.y > p.y);
  const BezierPolynomial b = bezierPolynomial(e);
  // h(s) = y(s) − p.y; the curve is above p's height where h > 0.
  double h[4] = {e.from.y - p.y, b.c[1].y, b.c[2].y, b.degree == 3 ? b.c[3].y : 0.0};
  int n = b.degree;
  while (n > 0 && h[n] == 0.0) --n;
  double roots[4];
  const int count = n > 0 ? polynomialSublevelBoundaries(h, n, 0.0, 1.0, roots) : 0;
  // The curve is cut at the roots into stretches each above or not; each
  // change between neighbours (the start, the stretches, the end) is a
  // crossing at the point between them.
  bool parity = false;
  bool above = e.from.y > p.y;
  double start = 0.0;
  for (int i = 0; i <= count; ++i) {
    const double end = i < count ? roots[i] : 1.0;
    const bool stretch = polynomialValue(h, n, 0.5 * (start + end)) > 0.0;
    if (stretch != above) {
      const double x = i == 0 ? e.from.x : b.at(start).x;
      if (x > p.x) parity = !parity;
      above = stretch;
    }
    start = end;
  }
  if ((e.to.y > p.y) != above && e.to.x > p.x) parity = !parity;
  return parity;
}

double bezierAreaTerm(const ProfileEdge& e) {
  // x = Σ a_i s^i, y = Σ b_j s^j: x y' − y x' = Σ (j − i)·a_i·b_j·s^(i+j−1),
  // whose integral over [0, 1] is Σ (j − i)·a_i·b_j / (i + j).
  const BezierPolynomial b = bezierPolynomial(e);
  double sum = 0.0;
  for (int i = 0; i <= b.degree; ++i)
    for (int j = 0; j <= b.degree; ++j)
      if (i != j) sum += double(j - i) * b.c[i].x * b.c[j].y / double(i + j);
  return sum;
}

int bezierSteps(const ProfileEdge& e, double tolerance) {
  dvec2 p[4];
  const int n = controlPoints(e, p);
  double bend = 0.0;
  for (int k = 0; k + 2 <= n; ++k)
    bend = std::max(bend, glm::length(p[k] - 2.0 * p[k + 1] + p[k + 2]));
  const double steps = std::ceil(std::sqrt(n * (n - 1) * bend / (8.0 * tolerance)));
  return std::clamp(int(std::min(steps, 1e6)), 1, 1000000);
}

double nearestBezierParameter(const BezierPolynomial& b, const dvec2& u) {
  constexpr int kSamples = 16;
  double best = 0.0, bestDistance = 1e300;
  for (int k = 0; k <= kSamples; ++k) {
    const double s = double(k) / kSamples;
    const dvec2 d = b.at(s) - u;
    const double distance = glm::dot(d, d);
    if (distance < bestDistance) bestDistance = distance, best = s;
  }
  double s = best;
  for (int i = 0; i < 12; ++i) {
    const dvec2 d = b.at(s) - u, v = b.slope(s);
    dvec2 a = 2.0 * b.c[2];
    if (b.degree == 3) a += 6.0 * b.c[3] * s;
    const double g = glm::dot(d, v), slope = glm::dot(v, v) + glm::dot(d, a);
    if (!(slope > 0.0)) break;
    const double next = std::clamp(s - g / slope, 0.0, 1.0);
    if (next == s) break;
    s = next;
  }
  return s;
}

Profile bezierEdgesFlattened(const Profile& profile, double tolerance) {
  Profile out;
  for (const ProfileLoop& loop : profile.loops) {
    ProfileLoop& l = out.loops.emplace_back();
    for (const ProfileEdge& e : loop.edges) {
      if (!e.bezier()) {
        l.edges.push_back(e);
        continue;
      }
      const int steps = bezierSteps(e, tolerance);
      dvec2 a = e.from;
      for (int k = 1; k <= steps; ++k) {
        const dvec2 b = k == steps ? e.to : bezierPoint(e, double(k) / steps);
        l.edges.push_back(ProfileEdge::segment(a, b));
        a = b;
      }
    }
  }
  return out;
}

}  // namespace csgray::detail
