// The plane's layer: regions evaluated exactly into loops of segments and
// arcs (areas against their formulas, containment against the tree's), the
// polygons of their outlines, and the refusals of bad input.
#include "profile/region.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <random>
#include <stdexcept>

#include "profile/region_evaluation.h"

namespace csgray::detail {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTolerance = 1e-4;

ProfileLoop polygonLoop(const std::vector<dvec2>& points) {
  ProfileLoop loop;
  for (std::size_t i = 0; i < points.size(); ++i)
    loop.edges.push_back(ProfileEdge::segment(points[i], points[(i + 1) % points.size()]));
  return loop;
}

RegionPtr polygon(const std::vector<std::vector<dvec2>>& loops) {
  Profile p;
  for (const auto& points : loops) p.loops.push_back(polygonLoop(points));
  return Region::leaf(std::move(p));
}

RegionPtr rect(double x0, double y0, double x1, double y1) {
  return polygon({{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}});
}

RegionPtr disc(dvec2 center, double r) {
  Profile p;
  p.loops.push_back({{ProfileEdge::arc(center, dmat2(r), 0.0, 2.0 * kPi)}});
  return Region::leaf(std::move(p));
}

RegionPtr unite(RegionPtr a, RegionPtr b) { return Region::boolean(Region::Op::Union, {a, b}); }
RegionPtr subtract(RegionPtr a, RegionPtr b) {
  return Region::boolean(Region::Op::Difference, {a, b});
}
RegionPtr intersect(RegionPtr a, RegionPtr b) {
  return Region::boolean(Region::Op::Intersection, {a, b});
}

double loopArea(const ProfileLoop& loop) { return area(Profile{{loop}}); }

// Each loop closes exactly, edge to edge.
void expectClosed(const Profile& p) {
  for (const ProfileLoop& loop : p.loops) {
    ASSERT_FALSE(loop.edges.empty());
    for (std::size_t i = 0; i < loop.edges.size(); ++i)
      EXPECT_EQ(loop.edges[i].to, loop.edges[(i + 1) % loop.edges.size()].from);
  }
}

// The evaluated profile holds the points the tree holds, on random points
// of the region's box and a margin around it.
void expectSameContainment(const RegionPtr& region, const Profile& evaluated) {
  std::mt19937 random(7);
  const ProfileBounds b = region->bounds();
  const dvec2 margin = 0.2 * (b.hi - b.lo);
  std::uniform_real_distribution<double> x(b.lo.x - margin.x, b.hi.x + margin.x);
  std::uniform_real_distribution<double> y(b.lo.y - margin.y, b.hi.y + margin.y);
  for (int i = 0; i < 4000; ++i) {
    const dvec2 p(x(random), y(random));
    ASSERT_EQ(region->contains(p), evaluated.contains(p)) << p.x << ", " << p.y;
  }
}

TEST(Region, ASquareIsOneCounterclockwiseLoop) {
  // Given clockwise.
  const Profile p = evaluate(*polygon({{{0, 0}, {0, 2}, {3, 2}, {3, 0}}}), kTolerance);
  ASSERT_EQ(p.loops.size(), 1u);
  EXPECT_EQ(p.loops[0].edges.size(), 4u);
  EXPECT_DOUBLE_EQ(area(p), 6.0);
  expectClosed(p);
}

TEST(Region, ACircleStaysOneArc) {
  const Profile p = evaluate(*disc({1, 2}, 3), kTolerance);
  ASSERT_EQ(p.loops.size(), 1u);
  ASSERT_EQ(p.loops[0].edges.size(), 1u);
  const ProfileEdge& e = p.loops[0].edges[0];
  EXPECT_EQ(e.kind, ProfileEdge::Kind::Arc);
  EXPECT_NEAR(e.center.x, 1.0, 1e-12);
  EXPECT_NEAR(e.center.y, 2.0, 1e-12);
  EXPECT_NEAR(std::abs(glm::determinant(e.axes)), 9.0, 1e-12);
  EXPECT_NEAR(area(p), 9.0 * kPi, 1e-12);
}

TEST(Region, AnnulusHasItsHoleClockwise) {
  const RegionPtr ring = subtract(disc({0, 0}, 2), disc({0, 0}, 1));
  const Profile p = evaluate(*ring, kTolerance);
  ASSERT_EQ(p.loops.size(), 2u);
  EXPECT_NEAR(area(p), 3.0 * kPi, 1e-12);
  EXPECT_NEAR(loopArea(p.loops[0]), 4.0 * kPi, 1e-12);
  EXPECT_NEAR(loopArea(p.loops[1]), -kPi, 1e-12);
  expectSameContainment(ring, p);
}

TEST(Region, SquaresSharingAnEdgeUniteIntoOneLoop) {
  const Profile p = evaluate(*unite(rect(0, 0, 1, 1), rect(1, 0, 2, 1)), kTolerance);
  ASSERT_EQ(p.loops.size(), 1u);
  EXPECT_EQ(p.loops[0].edges.size(), 4u);
  EXPECT_DOUBLE_EQ(area(p), 2.0);
}

TEST(Region, EvenOddPolygonWithAHole) {
  const RegionPtr r = polygon({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{1, 1}, {3, 1}, {3, 3}, {1, 3}}});
  const Profile p = evaluate(*r, kTolerance);
  ASSERT_EQ(p.loops.size(), 2u);
  EXPECT_DOUBLE_EQ(area(p), 12.0);
  expectSameContainment(r, p);
}

TEST(Region, AHoleTouchingTheOutlineAtAPoint) {
  const RegionPtr r = polygon({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{2, 0}, {3, 1}, {2, 2}, {1, 1}}});
  const Profile p = evaluate(*r, kTolerance);
  EXPECT_DOUBLE_EQ(area(p), 14.0);
  expectClosed(p);
  expectSameContainment(r, p);
}

TEST(Region, SelfIntersectingPolygonIsEvenOdd) {
  // A bow tie: two triangles of area 1 (one loop through the point where
  // they touch, or two).
  const RegionPtr bowTie = polygon({{{0, 0}, {2, 2}, {2, 0}, {0, 2}}});
  const Profile p = evaluate(*bowTie, kTolerance);
  expectClosed(p);
  EXPECT_DOUBLE_EQ(area(p), 2.0);
  expectSameContainment(bowTie, p);
  // A pentagram: the middle pentagon is enclosed twice and left out; the
  // five tips touching at its corners are the star's outline with the
  // pentagon as a hole.
  std::vector<dvec2> star;
  for (int i = 0; i < 5; ++i)
    star.emplace_back(std::cos(4 * kPi * i / 5), std::sin(4 * kPi * i / 5));
  const RegionPtr pentagram = polygon({star});
  const Profile q = evaluate(*pentagram, kTolerance);
  EXPECT_EQ(q.loops.size(), 2u);
  const double inner = std::cos(0.4 * kPi) / std::cos(0.2 * kPi);  // the pentagon's circumradius
  const double tip =
      0.5 * (2.0 * inner * std::sin(0.2 * kPi)) * (1.0 - inner * std::cos(0.2 * kPi));
  EXPECT_NEAR(area(q), 5.0 * tip, 1e-12);
  expectSameContainment(pentagram, q);
}

TEST(Region, CoincidentLoopsCancel) {
  const std::vector<dvec2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_TRUE(evaluate(*polygon({square, square}), kTolerance).loops.empty());
  // Two loops overlapping along parts of edges: what both enclose is out.
  const RegionPtr r = polygon({square, {{0.5, 0}, {2, 0}, {2, 1}, {0.5, 1}}});
  const Profile p = evaluate(*r, kTolerance);
  EXPECT_EQ(p.loops.size(), 2u);
  EXPECT_DOUBLE_EQ(area(p), 1.5);
  expectSameContainment(r, p);
}

TEST(Region, DegenerateInputGivesEmptyRegions) {
  EXPECT_TRUE(evaluate(*polygon({{{0, 0}, {1, 1}, {2, 2}}}), kTolerance).loops.empty());
  EXPECT_TRUE(evaluate(*polygon({{{0, 0}, {0, 0}, {0, 0}}}), kTolerance).loops.empty());
  EXPECT_TRUE(evaluate(*Region::leaf(Profile{}), kTolerance).loops.empty());
  EXPECT_TRUE(evaluate(*intersect(rect(0, 0, 1, 1), rect(2, 2, 3, 3)), kTolerance).loops.empty());
  EXPECT_TRUE(evaluate(*subtract(rect(0, 0, 1, 1), rect(-1, -1, 2, 2)), kTolerance).loops.empty());
  EXPECT_TRUE(evaluate(*disc({0, 0}, 0), kTolerance).loops.empty());
}

TEST(Region, LensOfTwoDiscs) {
  const double r = 1.0, d = 1.2;
  const RegionPtr lens = intersect(disc({0, 0}, r), disc({d, 0}, r));
  const Profile p = evaluate(*lens, kTolerance);
  ASSERT_EQ(p.loops.size(), 1u);
  EXPECT_EQ(p.loops[0].edges.size(), 2u);
  // The area of two circular segments (Weisstein, "Circle-Circle
  // Intersection", MathWorld).
  const double expected =
      2.0 * r * r * std::acos(d / (2.0 * r)) - 0.5 * d * std::sqrt(4.0 * r * r - d * d);
  EXPECT_NEAR(area(p), expected, 1e-12);
  expectSameContainment(lens, p);
}

TEST(Region, ArcsOfLeavesStayArcs) {
  // A stadium: two half circles joined by segments, area 2rL + πr².
  const double r = 0.5, l = 3.0;
  Profile stadium;
  stadium.loops.push_back({{ProfileEdge::segment({0, -r}, {l, -r}),
                            ProfileEdge::arc({l, 0}, dmat2(r), -0.5 * kPi, 0.5 * kPi),
                            ProfileEdge::segment({l, r}, {0, r}),
                            ProfileEdge::arc({0, 0}, dmat2(r), 0.5 * kPi, 1.5 * kPi)}});
  // The arcs' ends are computed; join them to the segments exactly.
  auto& edges = stadium.loops[0].edges;
  for (std::size_t i = 0; i < edges.size(); ++i) edges[(i + 1) % edges.size()].from = edges[i].to;
  const RegionPtr region = Region::leaf(stadium);
  const Profile p = evaluate(*region, kTolerance);
  ASSERT_EQ(p.loops.size(), 1u);
  EXPECT_EQ(p.loops[0].edges.size(), 4u);
  EXPECT_NEAR(area(p), 2.0 * r * l + kPi * r * r, 1e-12);
  expectSameContainment(region, p);
}

TEST(Region, BooleansAgreeWithTheTree) {
  const RegionPtr part = subtract(unite(rect(0, 0, 4, 2), disc({4, 1}, 1.5)),
                                  unite(disc({1, 1}, 0.5), rect(3.5, 0.5, 6, 1.5)));
  const RegionPtr turned = part->transformed(
      {glm::dmat2(std::cos(0.3), std::sin(0.3), -std::sin(0.3), std::cos(0.3)), dvec2(0.25, -1.0)});
  for (const RegionPtr& r : {part, turned}) {
    const Profile p = evaluate(*r, kTolerance);
    expectClosed(p);
    expectSameContainment(r, p);
  }
}

TEST(Region, EllipsesBecomePolygonsWithinTheTolerance) {
  Profile ellipse;
  ellipse.loops.push_back(
      {{ProfileEdge::arc({0, 0}, dmat2(dvec2(2, 0), dvec2(0, 1)), 0.0, 2.0 * kPi)}});
  const double tolerance = 1e-3;
  const Profile p = evaluate(*Region::leaf(ellipse), tolerance);
  ASSERT_EQ(p.loops.size(), 1u);
  // Inscribed: at most the perimeter times the tolerance short.
  EXPECT_LT(area(p), 2.0 * kPi);
  EXPECT_GT(area(p), 2.0 * kPi - 10.0 * tolerance);
}

TEST(Region, FlattenedArcsKeepTheTolerance) {
  const Profile p = evaluate(*subtract(rect(-2, -2, 2, 2), disc({0, 0}, 1)), kTolerance);
  const double tolerance = 1e-3;
  const auto polygons = flatten(p, tolerance);
  ASSERT_EQ(polygons.size(), 2u);
  EXPECT_EQ(polygons[0].size(), 4u);
  const auto& circle = polygons[1];
  // The sagitta rule: a chord over angle φ strays r(1 − cos(φ/2)).
  const double step = 2.0 * std::acos(1.0 - tolerance);
  EXPECT_GE(circle.size(), std::ceil(2.0 * kPi / step));
  for (std::size_t i = 0; i < circle.size(); ++i) {
    EXPECT_NEAR(glm::length(circle[i]), 1.0, 1e-12);
    const dvec2 middle = 0.5 * (circle[i] + circle[(i + 1) % circle.size()]);
    EXPECT_GE(glm::length(middle), 1.0 - tolerance);
  }
  EXPECT_THROW(flatten(p, 0.0), std::invalid_argument);
}

TEST(Region, NonFiniteInputIsRefused) {
  const double nan = std::nan("");
  EXPECT_THROW(evaluate(*polygon({{{0, 0}, {1, nan}, {1, 1}}}), kTolerance), std::invalid_argument);
  EXPECT_THROW(evaluate(*disc({0, 0}, nan), kTolerance), std::invalid_argument);
  EXPECT_THROW(evaluate(*rect(0, 0, 1, 1), nan), std::invalid_argument);
  EXPECT_THROW(Region::boolean(Region::Op::Union, {}), std::invalid_argument);
}

}  // namespace
}  // namespace csgray::detail
