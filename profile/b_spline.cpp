#include "profile/b_spline.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <stdexcept>
#include <string>

namespace csgray::detail {

using glm::dvec3;

namespace {

void check(const BSpline& s) {
  if (s.degree < 1 || s.degree > 3)
    throw std::invalid_argument("a spline of degree " + std::to_string(s.degree) +
                                " (degrees 1 to 3 are read)");
  const std::size_t n = s.controls.size(), p = std::size_t(s.degree);
  if (n < p + 1)
    throw std::invalid_argument("a spline of degree " + std::to_string(p) + " needs at least " +
                                std::to_string(p + 1) + " control points, not " +
                                std::to_string(n));
  if (s.knots.size() != n + p + 1)
    throw std::invalid_argument(
        "a spline with " + std::to_string(n) + " control points of degree " + std::to_string(p) +
        " needs " + std::to_string(n + p + 1) + " knots, not " + std::to_string(s.knots.size()));
  for (std::size_t i = 0; i < s.knots.size(); ++i) {
    if (!std::isfinite(s.knots[i])) throw std::invalid_argument("a spline's knot is not a number");
    if (i > 0 && s.knots[i] < s.knots[i - 1])
      throw std::invalid_argument("a spline's knots decrease");
  }
  if (!(s.knots[p] < s.knots[n]))
    throw std::invalid_argument("a spline's knots leave its curve no length");
  if (!s.weights.empty() && s.weights.size() != n)
    throw std::invalid_argument("a spline with " + std::to_string(n) + " control points needs " +
                                std::to_string(n) + " weights, not " +
                                std::to_string(s.weights.size()));
  for (double w : s.weights)
    if (!(w > 0.0 && std::isfinite(w)))
      throw std::invalid_argument("a spline's weights must be > 0");
}

bool rational(const BSpline& s) {
  return std::adjacent_find(s.weights.begin(), s.weights.end(), std::not_equal_to<>()) !=
         s.weights.end();
}

// Inserts u once (Boehm): the curve stays the same, with one more control
// point. k is the knot span the new knot goes into: knots[k] <= u <
// knots[k + 1], or knots[k] < u = knots[k + 1] at the domain's end.
// Points are dvec2, or dvec3 (x·w, y·w, w) for a rational spline, whose
// homogeneous control points a knot is inserted into as a plain spline's
// (Piegl and Tiller, section 5.2).
template <class Point>
void insertKnot(std::vector<double>& knots, std::vector<Point>& controls, int p, double u,
                bool atEnd) {
  std::size_t k = 0;
  for (std::size_t i = 0; i < knots.size(); ++i)
    if (atEnd ? knots[i] < u : knots[i] <= u) k = i;
  std::vector<Point> out(controls.size() + 1);
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (i + std::size_t(p) <= k) {
      out[i] = controls[i];
    } else if (i > k) {
      out[i] = controls[i - 1];
    } else {
      const double a = (u - knots[i]) / (knots[i + std::size_t(p)] - knots[i]);
      out[i] = (1.0 - a) * controls[i - 1] + a * controls[i];
    }
  }
  controls = std::move(out);
  knots.insert(knots.begin() + std::ptrdiff_t(k) + 1, u);
}

// The control points of the Bézier curve that the spline is over its span
// [knots[i], knots[i + 1]]: the span depends on p + 1 control points and
// 2p + 2 knots only, whose ends are inserted until each is repeated p
// times, so that each span costs the same however long the spline.
template <class Point>
std::vector<Point> spanBezier(const BSpline& s, const std::vector<Point>& points, std::size_t i) {
  const std::size_t p = std::size_t(s.degree);
  std::vector<double> knots(s.knots.begin() + std::ptrdiff_t(i - p),
                            s.knots.begin() + std::ptrdiff_t(i + p + 2));
  std::vector<Point> controls(points.begin() + std::ptrdiff_t(i - p),
                              points.begin() + std::ptrdiff_t(i + 1));
  const double lo = s.knots[i], hi = s.knots[i + 1];
  for (auto count = std::count(knots.begin(), knots.end(), lo); count < s.degree; ++count)
    insertKnot(knots, controls, s.degree, lo, false);
  for (auto count = std::count(knots.begin(), knots.end(), hi); count < s.degree; ++count)
    insertKnot(knots, controls, s.degree, hi, true);
  // The span is now [knots[k], knots[k + 1]] with k the last copy of lo.
  std::size_t k = 0;
  while (knots[k + 1] <= lo) ++k;
  return {controls.begin() + std::ptrdiff_t(k - p), controls.begin() + std::ptrdiff_t(k + 1)};
}

// A rational quadratic Bézier curve from a to b pulled towards control
// with weights 1, w, 1 (the standard form, to which any end weights w₀, w₂
// come with w = w₁ / √(w₀·w₂): Piegl and Tiller, "The NURBS Book", 2nd
// ed., section 7.3): for w < 1 an arc of an ellipse, less than half of
// it, from a to b; for w = 1 a parabola; for w > 1 a hyperbola. The
// ellipse's centre c is (m − w²·control) / (1 − w²), m the middle of a and
// b: for an arc of a circle of radius R and half-angle α, w = cos α (section
// 7.5), and m and control lie on one ray from c at R·cos α and R / cos α,
// so m − c = w²·(control − c); an ellipse is a circle under an affine map,
// which keeps that ratio along the ray. Its conjugate half-diameters are
// the one to a and the one along the curve's tangent at a (towards
// control): with those as axes, the arc runs from angle 0 to the angle of b.
ProfileEdge conicEdge(const dvec2& a, const dvec2& control, const dvec2& b, double w) {
  if (std::abs(w - 1.0) <= 1e-12) return ProfileEdge::quadratic(a, control, b);
  if (w > 1.0)
    throw std::invalid_argument(
        "a rational spline with a piece of a hyperbola (only arcs of circles, ellipses and "
        "parabolas are read)");
  const dvec2 tangent = control - a, chord = b - a;
  const double turn = tangent.x * chord.y - tangent.y * chord.x;
  // A straight piece: its control point between its ends.
  if (turn == 0.0) {
    if (glm::dot(tangent, chord) < 0.0 || glm::dot(control - b, chord) > 0.0)
      throw std::invalid_argument("a rational spline's piece doubles back on itself");
    return ProfileEdge::segment(a, b);
  }
  const dvec2 centre = (0.5 * (a + b) - w * w * control) / (1.0 - w * w);
  const dvec2 toA = a - centre, along = glm::normalize(tangent);
  // b − centre = cos θ · toA + (|half-diameter| · sin θ) · along.
  const dvec2 toB = b - centre;
  const double det = toA.x * along.y - toA.y * along.x;
  const double cosine = (toB.x * along.y - toB.y * along.x) / det;
  const double alongB = (toA.x * toB.y - toA.y * toB.x) / det;
  const double sine = std::sqrt(std::max(0.0, 1.0 - cosine * cosine));
  if (!(sine > 0.0 && alongB > 0.0))
    throw std::invalid_argument("a rational spline's piece is not an arc of an ellipse");
  const dmat2 axes(toA, (alongB / sine) * along);
  ProfileEdge arc = ProfileEdge::arc(centre, axes, 0.0, std::atan2(sine, cosine));
  arc.from = a;
  arc.to = b;
  return arc;
}

// The edges of a rational spline: each span's homogeneous Bézier points
// back in the plane, with their weights.
std::vector<ProfileEdge> rationalEdges(const BSpline& spline) {
  if (spline.degree == 3)
    throw std::invalid_argument(
        "a rational spline of degree 3 (only degrees 1 and 2 are read when the weights differ)");
  std::vector<dvec3> homogeneous;
  for (std::size_t i = 0; i < spline.controls.size(); ++i)
    homogeneous.push_back(dvec3(spline.weights[i] * spline.controls[i], spline.weights[i]));
  std::vector<ProfileEdge> edges;
  for (std::size_t i = std::size_t(spline.degree); i < spline.controls.size(); ++i) {
    if (!(spline.knots[i] < spline.knots[i + 1])) continue;
    const std::vector<dvec3> h = spanBezier(spline, homogeneous, i);
    std::vector<dvec2> c;
    for (const dvec3& q : h) c.push_back(dvec2(q) / q.z);
    // As for a plain spline, below: the pieces join to the bit.
    if (!edges.empty()) c.front() = edges.back().to;
    if (spline.degree == 1) {
      if (c[0] != c[1]) edges.push_back(ProfileEdge::segment(c[0], c[1]));
    } else {
      edges.push_back(conicEdge(c[0], c[1], c[2], h[1].z / std::sqrt(h[0].z * h[2].z)));
    }
  }
  return edges;
}

}  // namespace

std::vector<ProfileEdge> bSplineEdges(const BSpline& spline) {
  check(spline);
  if (rational(spline)) return rationalEdges(spline);
  std::vector<ProfileEdge> edges;
  for (std::size_t i = std::size_t(spline.degree); i < spline.controls.size(); ++i) {
    if (!(spline.knots[i] < spline.knots[i + 1])) continue;
    std::vector<dvec2> c = spanBezier(spline, spline.controls, i);
    // Neighbouring spans are worked out apart: the one's start is the
    // last one's end to the bit, so that the edges join.
    if (!edges.empty()) c.front() = edges.back().to;
    if (spline.degree == 1) {
      if (c[0] != c[1]) edges.push_back(ProfileEdge::segment(c[0], c[1]));
    } else if (spline.degree == 2) {
      edges.push_back(ProfileEdge::quadratic(c[0], c[1], c[2]));
    } else {
      edges.push_back(ProfileEdge::cubic(c[0], c[1], c[2], c[3]));
    }
  }
  return edges;
}

}  // namespace csgray::detail
