// B-splines as Bézier edges: the edges trace the same curve as the
// Cox–de Boor definition of the spline, evaluated here independently of
// the knot insertion that made them, and bad splines are refused.
#include "profile/b_spline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "profile/bezier.h"

namespace csgray::detail {
namespace {

// N_{i,p}(u) by the Cox–de Boor recursion (Piegl and Tiller, "The NURBS
// Book", eq. 2.5), over half-open spans.
double basis(const std::vector<double>& knots, std::size_t i, int p, double u) {
  if (p == 0) return knots[i] <= u && u < knots[i + 1] ? 1.0 : 0.0;
  double value = 0.0;
  const double left = knots[i + std::size_t(p)] - knots[i];
  const double right = knots[i + std::size_t(p) + 1] - knots[i + 1];
  if (left > 0.0) value += (u - knots[i]) / left * basis(knots, i, p - 1, u);
  if (right > 0.0)
    value += (knots[i + std::size_t(p) + 1] - u) / right * basis(knots, i + 1, p - 1, u);
  return value;
}

dvec2 splinePoint(const BSpline& s, double u) {
  dvec2 p(0.0);
  for (std::size_t i = 0; i < s.controls.size(); ++i)
    p += basis(s.knots, i, s.degree, u) * s.controls[i];
  return p;
}

// The spline's edges, one for each span of distinct knots of its domain,
// in order and joined end to end; check(edge, lo, hi, k) looks at the
// edge over the span from knot lo to knot hi.
template <class Check>
void forEachSpanEdge(const BSpline& s, Check check) {
  const std::vector<ProfileEdge> edges = bSplineEdges(s);
  std::vector<std::pair<double, double>> spans;
  for (std::size_t i = std::size_t(s.degree); i < s.controls.size(); ++i)
    if (s.knots[i] < s.knots[i + 1]) spans.push_back({s.knots[i], s.knots[i + 1]});
  ASSERT_EQ(edges.size(), spans.size());
  for (std::size_t k = 0; k < edges.size(); ++k) {
    if (k > 0) {
      EXPECT_EQ(edges[k - 1].to, edges[k].from);
    }
    check(edges[k], spans[k].first, spans[k].second, k);
  }
}

// Each edge is the spline over its span.
void expectSameCurve(const BSpline& s) {
  forEachSpanEdge(s, [&](const ProfileEdge& e, double lo, double hi, std::size_t k) {
    for (double t : {0.1, 0.3, 0.5, 0.7, 0.9}) {
      const dvec2 expected = splinePoint(s, lo + t * (hi - lo));
      const dvec2 got = s.degree == 1 ? glm::mix(e.from, e.to, t) : bezierPoint(e, t);
      EXPECT_NEAR(got.x, expected.x, 1e-12) << "edge " << k << " at " << t;
      EXPECT_NEAR(got.y, expected.y, 1e-12) << "edge " << k << " at " << t;
    }
  });
}

const std::vector<dvec2> kControls = {{0, 0}, {1, 2}, {3, 3}, {4, 0}, {6, -1}, {7, 2}, {5, 4}};

TEST(BSpline, ClampedCubicWithADoubleKnot) {
  expectSameCurve({3, {0, 0, 0, 0, 1, 2, 2, 3, 3, 3, 3}, kControls, {}});
}

TEST(BSpline, UniformCubicUnclampedAtBothEnds) {
  expectSameCurve({3, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, kControls, {}});
}

TEST(BSpline, QuadraticWithUnevenKnots) {
  expectSameCurve({2, {0, 0, 0.5, 0.7, 2, 2.5, 4, 5, 5, 5}, kControls, {}});
}

TEST(BSpline, DegreeOneIsTheControlPolygon) {
  const BSpline s{1, {0, 0, 1, 2, 3, 4, 5, 6, 6}, kControls, {}};
  expectSameCurve(s);
  const std::vector<ProfileEdge> edges = bSplineEdges(s);
  for (std::size_t i = 0; i < edges.size(); ++i) {
    EXPECT_EQ(edges[i].from, kControls[i]);
    EXPECT_EQ(edges[i].to, kControls[i + 1]);
  }
}

TEST(BSpline, AClampedCubicOfFourPointsIsOneBezier) {
  const std::vector<ProfileEdge> edges =
      bSplineEdges({3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0}, {1, 2}, {3, 3}, {4, 0}}, {}});
  ASSERT_EQ(edges.size(), 1u);
  EXPECT_EQ(edges[0].kind, ProfileEdge::Kind::Cubic);
  EXPECT_EQ(edges[0].from, dvec2(0, 0));
  EXPECT_EQ(edges[0].control1, dvec2(1, 2));
  EXPECT_EQ(edges[0].control2, dvec2(3, 3));
  EXPECT_EQ(edges[0].to, dvec2(4, 0));
}

std::string error(const BSpline& s) {
  try {
    bSplineEdges(s);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(BSpline, BadSplinesAreRefused) {
  EXPECT_EQ(
      error({4, {0, 0, 0, 0, 0, 1, 1, 1, 1, 1}, {{0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0}}, {}}),
      "a spline of degree 4 (degrees 1 to 3 are read)");
  EXPECT_EQ(error({3, {0, 0, 0, 1, 1, 1}, {{0, 0}, {1, 1}, {2, 0}, {3, 1}}, {}}),
            "a spline with 4 control points of degree 3 needs 8 knots, not 6");
  EXPECT_EQ(error({2, {0, 0, 0, 1}, {{0, 0}}, {}}),
            "a spline of degree 2 needs at least 3 control points, not 1");
  EXPECT_EQ(error({2, {0, 0, 1, 0.5, 1, 1}, {{0, 0}, {1, 1}, {2, 0}}, {}}),
            "a spline's knots decrease");
  EXPECT_EQ(error({2, {0, 1, 1, 1, 1, 2}, {{0, 0}, {1, 1}, {2, 0}}, {}}),
            "a spline's knots leave its curve no length");
}

// ---------------------------------------------------------------- rational

// A rational spline's point: Σ N·w·P / Σ N·w (Piegl and Tiller, eq. 4.2).
dvec2 rationalPoint(const BSpline& s, double u) {
  dvec2 sum(0.0);
  double weight = 0.0;
  for (std::size_t i = 0; i < s.controls.size(); ++i) {
    const double n = basis(s.knots, i, s.degree, u) * s.weights[i];
    sum += n * s.controls[i];
    weight += n;
  }
  return sum / weight;
}

// Where an arc edge's ellipse passes p, the angle of p, and how far p is
// off the ellipse (relative: |axes⁻¹ · (p − centre)| − 1).
std::pair<double, double> onArc(const ProfileEdge& arc, const dvec2& p) {
  const dvec2 q = glm::inverse(arc.axes) * (p - arc.center);
  return {std::atan2(q.y, q.x), glm::length(q) - 1.0};
}

// The rational spline's points lie on its edges, each span's on its own
// arc between the arc's ends.
void expectSameRationalCurve(const BSpline& s) {
  forEachSpanEdge(s, [&](const ProfileEdge& e, double lo, double hi, std::size_t k) {
    EXPECT_NEAR(glm::distance(e.from, rationalPoint(s, lo)), 0.0, 1e-12);
    EXPECT_NEAR(glm::distance(e.to, rationalPoint(s, hi - 1e-15)), 0.0, 1e-9);
    ASSERT_EQ(e.kind, ProfileEdge::Kind::Arc) << "edge " << k;
    EXPECT_NEAR(glm::distance(e.arcPoint(e.angle0), e.from), 0.0, 1e-12);
    EXPECT_NEAR(glm::distance(e.arcPoint(e.angle1), e.to), 0.0, 1e-12);
    for (double t : {0.1, 0.3, 0.5, 0.7, 0.9}) {
      const auto [angle, off] = onArc(e, rationalPoint(s, lo + t * (hi - lo)));
      EXPECT_NEAR(off, 0.0, 1e-12) << "edge " << k << " at " << t;
      EXPECT_GT(angle, std::min(e.angle0, e.angle1)) << "edge " << k << " at " << t;
      EXPECT_LT(angle, std::max(e.angle0, e.angle1)) << "edge " << k << " at " << t;
    }
  });
}

// A circle as drawing programs write it: four quarter arcs, each a
// rational quadratic with middle weight cos 45° (Piegl and Tiller,
// section 7.5), so a NURBS of 9 points with double inner knots.
BSpline circleSpline(const dvec2& centre, const dvec2& scale) {
  const double w = std::sqrt(0.5);
  BSpline s;
  s.degree = 2;
  s.knots = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
  const std::vector<dvec2> square = {{1, 0},   {1, 1},  {0, 1},  {-1, 1}, {-1, 0},
                                     {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
  for (std::size_t i = 0; i < square.size(); ++i) {
    s.controls.push_back(centre + scale * square[i]);
    s.weights.push_back(i % 2 ? w : 1.0);
  }
  return s;
}

TEST(BSpline, ARationalCircleIsFourCircularArcs) {
  const BSpline s = circleSpline({2, -1}, {3, 3});
  expectSameRationalCurve(s);
  const std::vector<ProfileEdge> edges = bSplineEdges(s);
  ASSERT_EQ(edges.size(), 4u);
  for (const ProfileEdge& e : edges) {
    EXPECT_TRUE(e.circular());
    EXPECT_NEAR(glm::distance(e.center, dvec2(2, -1)), 0.0, 1e-12);
    EXPECT_NEAR(std::abs(e.angle1 - e.angle0), 0.5 * std::numbers::pi, 1e-12);
    for (double t : {0.0, 0.25, 0.5, 0.75, 1.0})
      EXPECT_NEAR(glm::distance(e.arcPoint(e.angle0 + t * (e.angle1 - e.angle0)), e.center), 3.0,
                  1e-12);
  }
  // Closed: the last arc ends where the first begins.
  EXPECT_EQ(edges.back().to, edges.front().from);
}

TEST(BSpline, ARationalEllipseIsFourArcsOfIt) {
  // The circle stretched 4 × 1: an ellipse, arcs that are not circular.
  const BSpline s = circleSpline({0, 0}, {4, 1});
  expectSameRationalCurve(s);
  for (const ProfileEdge& e : bSplineEdges(s)) {
    EXPECT_FALSE(e.circular());
    for (double t : {0.2, 0.6}) {
      const dvec2 p = e.arcPoint(e.angle0 + t * (e.angle1 - e.angle0));
      EXPECT_NEAR(p.x * p.x / 16.0 + p.y * p.y, 1.0, 1e-12);
    }
  }
}

// Weights and knots of no drawing program's circle: knots inserted in
// homogeneous coordinates, pieces of whatever ellipses they are.
TEST(BSpline, RationalQuadraticWithUnevenKnotsAndWeights) {
  BSpline s;
  s.degree = 2;
  s.knots = {0, 0, 0, 0.3, 1.1, 2, 2, 2};
  s.controls = {{0, 0}, {1, 2}, {3, 3}, {5, 2}, {6, 0}};
  s.weights = {2.0, 0.8, 0.4, 0.9, 1.5};
  expectSameRationalCurve(s);
}

TEST(BSpline, RationalDegreeOneIsTheControlPolygon) {
  BSpline s;
  s.degree = 1;
  s.knots = {0, 0, 1, 2, 2};
  s.controls = {{0, 0}, {1, 2}, {3, 3}};
  s.weights = {1.0, 5.0, 0.5};
  const std::vector<ProfileEdge> edges = bSplineEdges(s);
  ASSERT_EQ(edges.size(), 2u);
  EXPECT_EQ(edges[0].kind, ProfileEdge::Kind::Segment);
  EXPECT_EQ(edges[0].from, dvec2(0, 0));
  EXPECT_EQ(edges[1].to, dvec2(3, 3));
  EXPECT_NEAR(glm::distance(edges[0].to, dvec2(1, 2)), 0.0, 1e-15);
}

TEST(BSpline, RationalSplinesProfilesCannotHoldAreRefused) {
  EXPECT_EQ(error({2, {0, 0, 0, 1, 1, 1}, {{0, 0}, {1, 1}, {2, 0}}, {1.0, 2.0, 1.0}}),
            "a rational spline with a piece of a hyperbola (only arcs of circles, ellipses and "
            "parabolas are read)");
  EXPECT_EQ(
      error({3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0}, {1, 1}, {2, 1}, {3, 0}}, {1.0, 0.5, 0.5, 1.0}}),
      "a rational spline of degree 3 (only degrees 1 and 2 are read when the weights "
      "differ)");
  EXPECT_EQ(error({2, {0, 0, 0, 1, 1, 1}, {{0, 0}, {1, 1}, {2, 0}}, {1.0, 0.5}}),
            "a spline with 3 control points needs 3 weights, not 2");
  EXPECT_EQ(error({2, {0, 0, 0, 1, 1, 1}, {{0, 0}, {1, 1}, {2, 0}}, {1.0, 0.0, 1.0}}),
            "a spline's weights must be > 0");
  // Equal weights other than 1 are a plain spline.
  EXPECT_EQ(
      error({3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0}, {1, 1}, {2, 1}, {3, 0}}, {2.0, 2.0, 2.0, 2.0}}),
      "(no error)");
}

}  // namespace
}  // namespace csgray::detail
