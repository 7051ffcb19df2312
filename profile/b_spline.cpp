#include "profile/b_spline.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace csgray::detail {

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
}

// Inserts u once (Boehm): the curve stays the same, with one more control
// point. k is the knot span the new knot goes into: knots[k] <= u <
// knots[k + 1], or knots[k] < u = knots[k + 1] at the domain's end.
void insertKnot(std::vector<double>& knots, std::vector<dvec2>& controls, int p, double u,
                bool atEnd) {
  std::size_t k = 0;
  for (std::size_t i = 0; i < knots.size(); ++i)
    if (atEnd ? knots[i] < u : knots[i] <= u) k = i;
  std::vector<dvec2> out(controls.size() + 1);
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
std::vector<dvec2> spanBezier(const BSpline& s, std::size_t i) {
  const std::size_t p = std::size_t(s.degree);
  std::vector<double> knots(s.knots.begin() + std::ptrdiff_t(i - p),
                            s.knots.begin() + std::ptrdiff_t(i + p + 2));
  std::vector<dvec2> controls(s.controls.begin() + std::ptrdiff_t(i - p),
                              s.controls.begin() + std::ptrdiff_t(i + 1));
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

}  // namespace

std::vector<ProfileEdge> bSplineEdges(const BSpline& spline) {
  check(spline);
  std::vector<ProfileEdge> edges;
  for (std::size_t i = std::size_t(spline.degree); i < spline.controls.size(); ++i) {
    if (!(spline.knots[i] < spline.knots[i + 1])) continue;
    std::vector<dvec2> c = spanBezier(spline, i);
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
