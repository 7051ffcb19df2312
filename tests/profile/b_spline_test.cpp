// B-splines as Bézier edges: the edges trace the same curve as the
// Cox–de Boor definition of the spline, evaluated here independently of
// the knot insertion that made them, and bad splines are refused.
#include "profile/b_spline.h"

#include <gtest/gtest.h>

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

// Each edge is the spline over one span of distinct knots of its domain,
// in order, and the edges join end to end.
void expectSameCurve(const BSpline& s) {
  const std::vector<ProfileEdge> edges = bSplineEdges(s);
  std::vector<std::pair<double, double>> spans;
  for (std::size_t i = std::size_t(s.degree); i < s.controls.size(); ++i)
    if (s.knots[i] < s.knots[i + 1]) spans.push_back({s.knots[i], s.knots[i + 1]});
  ASSERT_EQ(edges.size(), spans.size());
  for (std::size_t k = 0; k < edges.size(); ++k) {
    if (k > 0) {
      EXPECT_EQ(edges[k - 1].to, edges[k].from);
    }
    for (double t : {0.1, 0.3, 0.5, 0.7, 0.9}) {
      const double u = spans[k].first + t * (spans[k].second - spans[k].first);
      const dvec2 expected = splinePoint(s, u);
      const dvec2 got =
          s.degree == 1 ? glm::mix(edges[k].from, edges[k].to, t) : bezierPoint(edges[k], t);
      EXPECT_NEAR(got.x, expected.x, 1e-12) << "edge " << k << " at " << t;
      EXPECT_NEAR(got.y, expected.y, 1e-12) << "edge " << k << " at " << t;
    }
  }
}

const std::vector<dvec2> kControls = {{0, 0}, {1, 2}, {3, 3}, {4, 0}, {6, -1}, {7, 2}, {5, 4}};

TEST(BSpline, ClampedCubicWithADoubleKnot) {
  expectSameCurve({3, {0, 0, 0, 0, 1, 2, 2, 3, 3, 3, 3}, kControls});
}

TEST(BSpline, UniformCubicUnclampedAtBothEnds) {
  expectSameCurve({3, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, kControls});
}

TEST(BSpline, QuadraticWithUnevenKnots) {
  expectSameCurve({2, {0, 0, 0.5, 0.7, 2, 2.5, 4, 5, 5, 5}, kControls});
}

TEST(BSpline, DegreeOneIsTheControlPolygon) {
  const BSpline s{1, {0, 0, 1, 2, 3, 4, 5, 6, 6}, kControls};
  expectSameCurve(s);
  const std::vector<ProfileEdge> edges = bSplineEdges(s);
  for (std::size_t i = 0; i < edges.size(); ++i) {
    EXPECT_EQ(edges[i].from, kControls[i]);
    EXPECT_EQ(edges[i].to, kControls[i + 1]);
  }
}

TEST(BSpline, AClampedCubicOfFourPointsIsOneBezier) {
  const std::vector<ProfileEdge> edges =
      bSplineEdges({3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0}, {1, 2}, {3, 3}, {4, 0}}});
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
  EXPECT_EQ(error({4, {0, 0, 0, 0, 0, 1, 1, 1, 1, 1}, {{0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0}}}),
            "a spline of degree 4 (degrees 1 to 3 are read)");
  EXPECT_EQ(error({3, {0, 0, 0, 1, 1, 1}, {{0, 0}, {1, 1}, {2, 0}, {3, 1}}}),
            "a spline with 4 control points of degree 3 needs 8 knots, not 6");
  EXPECT_EQ(error({2, {0, 0, 0, 1}, {{0, 0}}}),
            "a spline of degree 2 needs at least 3 control points, not 1");
  EXPECT_EQ(error({2, {0, 0, 1, 0.5, 1, 1}, {{0, 0}, {1, 1}, {2, 0}}}),
            "a spline's knots decrease");
  EXPECT_EQ(error({2, {0, 1, 1, 1, 1, 2}, {{0, 0}, {1, 1}, {2, 0}}}),
            "a spline's knots leave its curve no length");
}

}  // namespace
}  // namespace csgray::detail
