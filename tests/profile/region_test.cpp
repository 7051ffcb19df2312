// The plane's layer: regions evaluated exactly into loops of segments and
// arcs (areas against their formulas, containment against the tree's), the
// polygons of their outlines, and the refusals of bad input.
#include "profile/region.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>

#include "profile/pinch_points.h"
#include "profile/region_evaluation.h"
#include "tessellation/tessellation.h"

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

TEST(Region, ATinyArcHasATinyCap) {
  // A square whose top edge has a dent along a billionth of a radian of a
  // circle (as a disc grazing a line leaves in a boolean): points well
  // inside stay inside, whichever side of the arc's chord rounding puts
  // them.
  for (const double h : {1e-6, 1e-9, 1e-10}) {
    const ProfileEdge dent =
        ProfileEdge::arc({0.5, 1.3}, dmat2(0.3), -0.5 * kPi + h, -0.5 * kPi - h);
    Profile p;
    p.loops.push_back(
        {{ProfileEdge::segment({0, 0}, {1, 0}), ProfileEdge::segment({1, 0}, {1, 1}),
          ProfileEdge::segment({1, 1}, dent.from), dent, ProfileEdge::segment(dent.to, {0, 1}),
          ProfileEdge::segment({0, 1}, {0, 0})}});
    for (const dvec2 q : {dvec2(0.5, 0.5), dvec2(0.5, 0.99), dvec2(0.5, 0.9999), dvec2(0.2, 0.5),
                          dvec2(0.45, 0.95)})
      EXPECT_TRUE(p.contains(q)) << h << ": " << q.x << ", " << q.y;
    EXPECT_FALSE(p.contains({0.5, 1.0001})) << h;
  }
}

// The non-zero rule over directed segments: loops that wind the same way
// unite, a loop inside one that winds the other way is a hole, and a
// segment run both ways cancels.
TEST(Region, NonZeroFillCountsDirections) {
  using Segments = std::vector<std::array<dvec2, 2>>;
  const auto square = [](double x0, double y0, double side, bool counterclockwise) {
    std::array<dvec2, 4> c = {dvec2(x0, y0), dvec2(x0 + side, y0), dvec2(x0 + side, y0 + side),
                              dvec2(x0, y0 + side)};
    if (!counterclockwise) std::reverse(c.begin(), c.end());
    Segments out;
    for (int i = 0; i < 4; ++i) out.push_back({c[i], c[(i + 1) % 4]});
    return out;
  };
  const auto joined = [](Segments a, const Segments& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  // Overlapping, both counterclockwise: 4 + 4 - 1, where even-odd would
  // leave the overlap out; the overlap and the rest are one outline of
  // eight sides, not three faces.
  const Profile overlapping = nonZeroFill(joined(square(0, 0, 2, true), square(1, 1, 2, true)));
  EXPECT_NEAR(area(overlapping), 7.0, 1e-12);
  ASSERT_EQ(overlapping.loops.size(), 1u);
  EXPECT_EQ(overlapping.loops[0].edges.size(), 8u);
  // Nested, the inner one clockwise: a hole, one outer loop and one inner.
  const Profile nested = nonZeroFill(joined(square(0, 0, 4, true), square(1, 1, 2, false)));
  EXPECT_NEAR(area(nested), 12.0, 1e-12);
  EXPECT_EQ(nested.loops.size(), 2u);
  // Nested, both counterclockwise: the inner square winds twice, and is
  // filled with the rest, one square.
  const Profile twice = nonZeroFill(joined(square(0, 0, 4, true), square(1, 1, 2, true)));
  EXPECT_NEAR(area(twice), 16.0, 1e-12);
  ASSERT_EQ(twice.loops.size(), 1u);
  EXPECT_EQ(twice.loops[0].edges.size(), 4u);
  // Two squares side by side, their shared side run both ways: one loop.
  const Profile pair = nonZeroFill(joined(square(0, 0, 1, true), square(1, 0, 1, true)));
  EXPECT_EQ(pair.loops.size(), 1u);
  EXPECT_NEAR(area(pair), 2.0, 1e-12);
  EXPECT_TRUE(nonZeroFill(Segments{}).loops.empty());
}

TEST(Region, ASquareIsOneCounterclockwiseLoop) {
  // Given clockwise.
  const Profile p = evaluate(*polygon({{{0, 0}, {0, 2}, {3, 2}, {3, 0}}}), kTolerance);
  ASSERT_EQ(p.loops.size(), 1u);
  EXPECT_EQ(p.loops[0].edges.size(), 4u);
  EXPECT_DOUBLE_EQ(area(p), 6.0);
  expectClosed(p);
}

// A half disc whose arc's ends come from cos and sin (x = 6e-17, not 0)
// and whose straight side runs along x = 0: the loop misses closing by a
// rounding error, and is still one region.
TEST(Region, ALoopThatMissesClosingByARoundingErrorIsKept) {
  Profile half;
  half.loops.push_back({{ProfileEdge::arc({0, 0}, dmat2(2.0), -kPi / 2, kPi / 2),
                         ProfileEdge::segment({0, 2}, {0, -2})}});
  ASSERT_NE(half.loops[0].edges[0].to.x, 0.0);  // the rounding error is there
  const Profile p = evaluate(*Region::leaf(half), kTolerance);
  ASSERT_EQ(p.loops.size(), 1u);
  EXPECT_NEAR(area(p), 2.0 * kPi, 1e-12);
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

TEST(Region, CellsPlacedSideBySideInDoublesShareTheirEdges) {
  // A honeycomb of 4 × 4 hexagons of radius 2, their corners at
  // (2 cos 60k°, 2 sin 60k°) about centres 3 apart: neighbours' corners
  // meet only to rounding (2 cos 60° is 1.0000000000000002, the next
  // cell's corner 3 − 2 = 1). Welded, the union is one loop with no slit
  // between the cells, its area 16 cells'.
  std::vector<RegionPtr> cells;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const dvec2 centre(3.0 * i, std::sqrt(3.0) * (2 * j + i % 2));
      std::vector<dvec2> corners;
      for (int k = 0; k < 6; ++k)
        corners.push_back(centre + 2.0 * dvec2(std::cos(k * kPi / 3.0), std::sin(k * kPi / 3.0)));
      cells.push_back(polygon({corners}));
    }
  const RegionPtr honeycomb = Region::boolean(Region::Op::Union, cells);
  const Profile p = evaluate(*honeycomb, kTolerance);
  ASSERT_EQ(p.loops.size(), 1u);
  expectClosed(p);
  EXPECT_NEAR(area(p), 16.0 * 6.0 * std::sqrt(3.0), 1e-9);
  // Every edge is at least a cell's edge long: no sliver edges.
  for (const ProfileEdge& e : p.loops[0].edges) EXPECT_GT(glm::length(e.to - e.from), 1.9);
  expectSameContainment(honeycomb, p);
}

TEST(Region, PointsWhereARegionTouchesItself) {
  const auto touches = [](const RegionPtr& r) { return touchesItself(evaluate(*r, kTolerance)); };
  EXPECT_TRUE(touches(unite(rect(0, 0, 1, 1), rect(1, 1, 2, 2))));  // corner to corner
  EXPECT_TRUE(
      touches(subtract(disc({0, 0}, 2), disc({1.5, 0}, 0.5))));   // a hole tangent to the rim
  EXPECT_TRUE(touches(unite(disc({0, 0}, 1), disc({2, 0}, 1))));  // tangent discs
  EXPECT_TRUE(touches(
      subtract(rect(0, 0, 4, 4), polygon({{{1, 1}, {3, 1}, {2, 4}}}))));  // a corner on an edge
  EXPECT_FALSE(touches(unite(rect(0, 0, 1, 1), rect(1, 0, 2, 1))));       // an edge shared
  EXPECT_FALSE(touches(subtract(disc({0, 0}, 2), disc({1, 0}, 0.5))));    // a hole inside
  EXPECT_FALSE(touches(unite(disc({0, 0}, 1), disc({3, 0}, 1))));         // apart
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

TEST(Region, FlattenedCirclesTakeACylindersRimPolygon) {
  // On a rim, a hole of radius 5 is the rim of a cylinder of radius 5 at
  // the rim's tolerance, point for point (the points of
  // primitives/cylinder_tessellation.cpp), so that a swept plate with the
  // hole meets a pin through it on the same points.
  const double tolerance = 0.01;
  const Profile p = evaluate(*subtract(rect(-8, -8, 8, 8), disc({0, 0}, 5)), kTolerance);
  const CircleRim rims[] = {{{0, 0}, 5.0}};
  const auto polygons = flatten(p, 0.5 * tolerance, rims, tolerance);
  ASSERT_EQ(polygons.size(), 2u);
  const CirclePolygon rim = circlePolygon(5.0, tolerance);
  std::vector<dvec2> expected;
  for (std::uint32_t s = 0; s < std::uint32_t(rim.segments); ++s) {
    const double theta = 2.0 * std::numbers::pi * s / rim.segments;
    const double rho = rim.radiusAt(5.0, s);
    expected.emplace_back(rho * std::cos(theta), rho * std::sin(theta));
  }
  auto lexicographic = [](const dvec2& a, const dvec2& b) {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
  };
  std::vector<dvec2> hole = polygons[1];
  std::sort(hole.begin(), hole.end(), lexicographic);
  std::sort(expected.begin(), expected.end(), lexicographic);
  EXPECT_EQ(hole, expected);

  // A cylinder turned 17° about its axis (a pin on a bolt circle): its
  // points, placed through its axes, the circle about (3, 4).
  const double c = std::cos(17.0 * kPi / 180.0), s = std::sin(17.0 * kPi / 180.0);
  const dmat2 axes(c, s, -s, c);
  const dvec2 center(3.0, 4.0);
  const Profile moved = evaluate(*subtract(rect(-8, -8, 14, 16), disc(center, 5)), kTolerance);
  const CircleRim turned[] = {{center, 5.0, axes}};
  const auto turnedPolygons = flatten(moved, 0.5 * tolerance, turned, tolerance);
  ASSERT_EQ(turnedPolygons.size(), 2u);
  std::vector<dvec2> turnedHole = turnedPolygons[1], turnedExpected;
  for (std::uint32_t step = 0; step < std::uint32_t(rim.segments); ++step)
    turnedExpected.push_back(center + axes * rim.pointAt(5.0, step));
  std::sort(turnedHole.begin(), turnedHole.end(), lexicographic);
  std::sort(turnedExpected.begin(), turnedExpected.end(), lexicographic);
  EXPECT_EQ(turnedHole, turnedExpected);
}

TEST(Region, FlattenedArcsBetweenCornersKeepTheirCornersAndTheTolerance) {
  // Half a ring: two arcs (radii 5 and 8) between corners on y = 0, which
  // stay where they are, exactly; every point and every edge's middle
  // lies within the tolerance of the exact outline, also where a corner
  // falls between the rim's steps (the ring turned by 1°).
  const double tolerance = 0.01;
  for (const double turn : {0.0, 1.0}) {
    SCOPED_TRACE(turn);
    const double c = std::cos(turn * kPi / 180.0), s = std::sin(turn * kPi / 180.0);
    auto turned = [&](const dvec2& q) { return dvec2(c * q.x - s * q.y, s * q.x + c * q.y); };
    const dvec2 corners[4] = {turned({-8, 0}), turned({-5, 0}), turned({5, 0}), turned({8, 0})};
    const RegionPtr half = polygon({{corners[3], turned({8, 9}), turned({-8, 9}), corners[0]}});
    const Profile p =
        evaluate(*intersect(subtract(disc({0, 0}, 8), disc({0, 0}, 5)), half), kTolerance);
    const CircleRim rims[] = {{{0, 0}, 5.0}, {{0, 0}, 8.0}};
    const auto polygons = flatten(p, 0.5 * tolerance, rims, tolerance);
    ASSERT_EQ(polygons.size(), 1u);
    const std::vector<dvec2>& loop = polygons[0];
    for (const dvec2& corner : corners) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const dvec2& q : loop) nearest = std::min(nearest, glm::length(q - corner));
      EXPECT_LE(nearest, 1e-12 * 8.0) << corner.x << ", " << corner.y;
    }
    // Distance from the exact outline: the two arcs above the cut and the
    // cut's two pieces.
    auto away = [&](const dvec2& q) {
      const double along = c * q.x + s * q.y, across = -s * q.x + c * q.y;
      const double r = glm::length(q);
      double d = std::abs(across) + (std::abs(along) < 5 || std::abs(along) > 8 ? 1.0 : 0.0);
      if (across >= -1e-12) d = std::min({d, std::abs(r - 5.0), std::abs(r - 8.0)});
      return d;
    };
    for (std::size_t i = 0; i < loop.size(); ++i) {
      EXPECT_LE(away(loop[i]), tolerance) << loop[i].x << ", " << loop[i].y;
      const dvec2 middle = 0.5 * (loop[i] + loop[(i + 1) % loop.size()]);
      EXPECT_LE(away(middle), tolerance) << middle.x << ", " << middle.y;
    }
  }
}

TEST(Region, AnOffsetsCornersAreArcsOfTheCircleOfItsRadius) {
  // A 40 × 30 rectangle grown by 5 has quarter circles of radius 5 about
  // its corners, whose ends (the moved edges' ends) lie on the axes
  // through the corners exactly; less a circle of radius 5 about each
  // corner, it is one loop of area 1900 + 25π − 4·25π. The ends were a
  // hair off (tan(π/4) in doubles), each arc became the circle through
  // its ends and middle, a hair from circle(5), and the difference kept
  // slivers between the two: three loops, and a sweep of it that could
  // not be meshed.
  Profile grown = offsetRounded(*rect(0, 0, 40, 30), 5.0, kTolerance);
  RegionPtr plate = Region::leaf(std::move(grown));
  for (const dvec2 corner : {dvec2(0, 0), dvec2(40, 0), dvec2(40, 30), dvec2(0, 30)})
    plate = subtract(plate, disc(corner, 5.0));
  const Profile p = evaluate(*plate, kTolerance);
  ASSERT_EQ(p.loops.size(), 1u);
  EXPECT_NEAR(area(p), 1900.0 - 75.0 * kPi, 1e-9);
  for (const ProfileEdge& e : p.loops[0].edges)
    if (e.kind == ProfileEdge::Kind::Arc) {
      EXPECT_EQ(glm::length(e.axes[0]), 5.0);
    }
}

TEST(Region, NonFiniteInputIsRefused) {
  const double nan = std::nan("");
  EXPECT_THROW(evaluate(*polygon({{{0, 0}, {1, nan}, {1, 1}}}), kTolerance), std::invalid_argument);
  EXPECT_THROW(evaluate(*disc({0, 0}, nan), kTolerance), std::invalid_argument);
  EXPECT_THROW(evaluate(*rect(0, 0, 1, 1), nan), std::invalid_argument);
  EXPECT_THROW(Region::boolean(Region::Op::Union, {}), std::invalid_argument);
}

// ---- Offsets ------------------------------------------------------------------

TEST(RegionOffset, RoundedSquareHasQuarterCircleCorners) {
  const double a = 2.0, r = 0.3;
  const Profile p = offsetRounded(*rect(0, 0, a, a), r, kTolerance);
  ASSERT_EQ(p.loops.size(), 1u);
  EXPECT_NEAR(area(p), a * a + 4.0 * a * r + kPi * r * r, 1e-12);
  int arcs = 0;
  for (const ProfileEdge& e : p.loops[0].edges)
    if (e.kind == ProfileEdge::Kind::Arc) {
      ++arcs;
      EXPECT_NEAR(std::abs(e.angle1 - e.angle0), 0.5 * kPi, 1e-9);
    }
  EXPECT_EQ(arcs, 4);
  EXPECT_EQ(p.loops[0].edges.size(), 8u);
  expectClosed(p);
}

TEST(RegionOffset, OffsetsOfArcsMeetTheirNeighboursCleanly) {
  // Offsets of a rounded square: its quarter circles grow or shrink, and
  // each stays one arc between two segments.
  const Profile rounded = offsetRounded(*rect(0, 0, 2, 2), 0.3, kTolerance);
  const RegionPtr r = Region::leaf(rounded);
  const struct {
    Profile p;
    double radius;
  } cases[] = {{offsetRounded(*r, 0.2, kTolerance), 0.5},
               {offsetRounded(*r, -0.1, kTolerance), 0.2},
               {offsetDelta(*r, 0.1, false, kTolerance), 0.4},
               {offsetDelta(*r, -0.2, true, kTolerance), 0.1}};
  for (const auto& [p, radius] : cases) {
    ASSERT_EQ(p.loops.size(), 1u);
    EXPECT_EQ(p.loops[0].edges.size(), 8u);
    const double side = 2.0 + 2.0 * radius;
    EXPECT_NEAR(area(p), side * side - (4.0 - kPi) * radius * radius, 1e-12);
    expectClosed(p);
  }
}

TEST(RegionOffset, InsetOfADiscIsTheSmallerDisc) {
  const Profile p = offsetRounded(*disc({1, 1}, 2.0), -0.5, kTolerance);
  ASSERT_EQ(p.loops.size(), 1u);
  ASSERT_EQ(p.loops[0].edges.size(), 1u);
  EXPECT_NEAR(area(p), kPi * 1.5 * 1.5, 1e-12);
  EXPECT_TRUE(offsetRounded(*disc({1, 1}, 2.0), -2.5, kTolerance).loops.empty());
}

TEST(RegionOffset, RoundedInsetKeepsSharpCorners) {
  const Profile p = offsetRounded(*rect(0, 0, 3, 2), -0.5, kTolerance);
  EXPECT_NEAR(area(p), 2.0 * 1.0, 1e-12);
  // An inset of an L rounds its inner corner: the square 1×1 at the
  // corner loses a quarter disc's complement, (1 − π/4)·r².
  const RegionPtr l = subtract(rect(0, 0, 2, 2), rect(1, 1, 3, 3));
  const double r = 0.25;
  const Profile q = offsetRounded(*l, -r, kTolerance);
  EXPECT_NEAR(area(q), 1.5 * 1.5 - 1.0 + (1.0 - kPi / 4.0) * r * r, 1e-12);
}

TEST(RegionOffset, AnLGrowsByStripsAndCornersLessTheOverlapAtItsInnerCorner) {
  // A polygon grown by r less than its features: its area, r times its
  // perimeter, a sector of the disc of radius r at each outer corner (five
  // quarter discs), less the square r² where the strips of the inner
  // corner's edges overlap.
  const RegionPtr l = subtract(rect(0, 0, 2, 2), rect(1, 1, 3, 3));
  const double r = 0.25;
  const Profile p = offsetRounded(*l, r, kTolerance);
  ASSERT_EQ(p.loops.size(), 1u);
  EXPECT_EQ(p.loops[0].edges.size(), 11u);  // 6 sides, 5 arcs, the inner corner sharp
  EXPECT_NEAR(area(p), 3.0 + 8.0 * r + (1.25 * kPi - 1.0) * r * r, 1e-12);
  expectClosed(p);
}

TEST(RegionOffset, AHoleNarrowerThanTwiceTheOffsetCloses) {
  const RegionPtr framed = subtract(rect(0, 0, 2, 2), rect(0.8, 0.8, 1.2, 1.2));
  const Profile open = offsetRounded(*framed, 0.1, kTolerance);
  ASSERT_EQ(open.loops.size(), 2u);
  // The hole shrinks to a square of side 0.2, its corners kept sharp.
  EXPECT_NEAR(area(open), 4.0 + 8.0 * 0.1 + kPi * 0.01 - 0.2 * 0.2, 1e-12);
  const Profile closed = offsetRounded(*framed, 0.3, kTolerance);
  ASSERT_EQ(closed.loops.size(), 1u);
  EXPECT_NEAR(area(closed), 4.0 + 8.0 * 0.3 + kPi * 0.09, 1e-12);
  // A hole 0.5 wide (its corners 0.35 from its centre) closes at 0.3 too.
  const RegionPtr wider = subtract(rect(0, 0, 2, 2), rect(0.75, 0.75, 1.25, 1.25));
  const Profile filled = offsetRounded(*wider, 0.3, kTolerance);
  ASSERT_EQ(filled.loops.size(), 1u);
  EXPECT_NEAR(area(filled), 4.0 + 8.0 * 0.3 + kPi * 0.09, 1e-12);
}

TEST(RegionOffset, AnIslandNarrowerThanTwiceTheInsetVanishes) {
  // Its square's corners are 0.28 or 0.35 from its centre, within 0.4 or
  // not: either way no point of it is 0.3 from the outside.
  for (const double side : {0.4, 0.5}) {
    const RegionPtr islands =
        Region::boolean(Region::Op::Union, {rect(0, 0, 3, 3), rect(5, 5, 5 + side, 5 + side)});
    const Profile p = offsetRounded(*islands, -0.3, kTolerance);
    ASSERT_EQ(p.loops.size(), 1u) << side;
    EXPECT_NEAR(area(p), 2.4 * 2.4, 1e-12) << side;
  }
}

TEST(RegionOffset, RoundedOffsetOfAHoleAndAnArc) {
  // A washer grown by r: the outer circle grows, the hole shrinks.
  const RegionPtr washer = subtract(disc({0, 0}, 3), disc({0, 0}, 1));
  const Profile p = offsetRounded(*washer, 0.5, kTolerance);
  ASSERT_EQ(p.loops.size(), 2u);
  EXPECT_NEAR(area(p), kPi * (3.5 * 3.5 - 0.5 * 0.5), 1e-12);
  // Grown further, the hole closes.
  EXPECT_EQ(offsetRounded(*washer, 1.5, kTolerance).loops.size(), 1u);
  // A half disc grown by r: (π/2)(R + r)² for the arc side, plus the
  // strip along the diameter and two quarter discs at its ends.
  Profile half;
  half.loops.push_back(
      {{ProfileEdge::segment({-1, 0}, {1, 0}), ProfileEdge::arc({0, 0}, dmat2(1), 0.0, kPi)}});
  half.loops[0].edges[1].from = {1, 0};
  half.loops[0].edges[1].to = {-1, 0};
  const double r = 0.25;
  const Profile q = offsetRounded(*Region::leaf(half), r, kTolerance);
  EXPECT_NEAR(area(q), 0.5 * kPi * (1 + r) * (1 + r) + 2.0 * r + 0.5 * kPi * r * r, 1e-12);
}

TEST(RegionOffset, DeltaOffsetsMitreOrChamfer) {
  const double a = 2.0, d = 0.25;
  EXPECT_NEAR(area(offsetDelta(*rect(0, 0, a, a), d, false, kTolerance)), (a + 2 * d) * (a + 2 * d),
              1e-12);
  // The chamfer cuts each corner at distance d from it: a right triangle
  // with legs d(2 − √2), (3 − 2√2)·d² each.
  const double cut = (3.0 - 2.0 * std::sqrt(2.0)) * d * d;
  const Profile chamfered = offsetDelta(*rect(0, 0, a, a), d, true, kTolerance);
  EXPECT_NEAR(area(chamfered), (a + 2 * d) * (a + 2 * d) - 4.0 * cut, 1e-12);
  EXPECT_EQ(chamfered.loops.at(0).edges.size(), 8u);
  EXPECT_NEAR(area(offsetDelta(*rect(0, 0, a, a), -d, true, kTolerance)), (a - 2 * d) * (a - 2 * d),
              1e-12);
  // An L: its inner corner stays sharp when grown, and is mitred (or
  // chamfered) when shrunk.
  const RegionPtr l = subtract(rect(0, 0, 2, 2), rect(1, 1, 3, 3));
  EXPECT_NEAR(area(offsetDelta(*l, d, false, kTolerance)), (2 + 2 * d) * (2 + 2 * d) - 1.0, 1e-12);
  EXPECT_NEAR(area(offsetDelta(*l, -d, false, kTolerance)), (2 - 2 * d) * (2 - 2 * d) - 1.0, 1e-12);
  EXPECT_NEAR(area(offsetDelta(*l, -d, true, kTolerance)), (2 - 2 * d) * (2 - 2 * d) - 1.0 + cut,
              1e-12);
  // Arcs become concentric arcs.
  const Profile grown = offsetDelta(*disc({0, 0}, 1), d, false, kTolerance);
  ASSERT_EQ(grown.loops.size(), 1u);
  EXPECT_EQ(grown.loops[0].edges.size(), 1u);
  EXPECT_NEAR(area(grown), kPi * (1 + d) * (1 + d), 1e-12);
}

TEST(RegionOffset, OffsetsAgreeWithDistances) {
  // A point is in offset(r) exactly when it is within r of the region:
  // for a square that distance is known in closed form.
  const double r = 0.4;
  const RegionPtr square = rect(0, 0, 1, 1);
  const Profile grown = offsetRounded(*square, r, kTolerance);
  const Profile shrunk = offsetRounded(*square, -r, kTolerance);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-1.0, 2.0);
  for (int i = 0; i < 4000; ++i) {
    const dvec2 p(u(random), u(random));
    const dvec2 nearest = glm::clamp(p, dvec2(0.0), dvec2(1.0));
    const double outside = glm::length(p - nearest);
    const double inside = std::min(std::min(p.x, 1.0 - p.x), std::min(p.y, 1.0 - p.y));
    if (std::abs(outside - r) > 1e-9) {
      EXPECT_EQ(grown.contains(p), outside < r) << p.x << ", " << p.y;
    }
    if (std::abs(inside - r) > 1e-9) {
      EXPECT_EQ(shrunk.contains(p), inside > r) << p.x << ", " << p.y;
    }
  }
}

TEST(RegionOffset, AGearKeepsOneLoopAndItsDistances) {
  // 30 teeth of 8 points: many short edges and corners both ways, where
  // strips and wedges of neighbours overlap.
  std::vector<dvec2> points;
  const int n = 240;
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * kPi * i / n;
    const double r = 10.0 + 0.8 * std::tanh(3.0 * std::sin(30.0 * t));
    points.emplace_back(r * std::cos(t), r * std::sin(t));
  }
  const RegionPtr gear = polygon({points});
  const auto distance = [&](const dvec2& p) {
    double best = INFINITY;
    for (int i = 0; i < n; ++i) {
      const dvec2 a = points[i], ab = points[(i + 1) % n] - a;
      const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
      best = std::min(best, glm::length(p - a - t * ab));
    }
    return best;
  };
  const double d = 0.3;
  const Profile grown = offsetRounded(*gear, d, kTolerance),
                shrunk = offsetRounded(*gear, -d, kTolerance);
  const Profile mitreOut = offsetDelta(*gear, d, false, kTolerance),
                mitreIn = offsetDelta(*gear, -d, false, kTolerance);
  const Profile chamferOut = offsetDelta(*gear, d, true, kTolerance),
                chamferIn = offsetDelta(*gear, -d, true, kTolerance);
  for (const Profile* p : {&grown, &shrunk, &mitreOut, &mitreIn, &chamferOut, &chamferIn}) {
    EXPECT_EQ(p->loops.size(), 1u);
    expectClosed(*p);
  }
  std::mt19937 random(9);
  std::uniform_real_distribution<double> u(-11.5, 11.5);
  for (int i = 0; i < 3000; ++i) {
    const dvec2 p(u(random), u(random));
    const double e = distance(p);
    if (std::abs(e - d) < 1e-9) continue;
    const bool in = gear->contains(p);
    EXPECT_EQ(grown.contains(p), in || e < d) << p.x << ", " << p.y;
    EXPECT_EQ(shrunk.contains(p), in && e > d) << p.x << ", " << p.y;
    // A mitre reaches further than the rounding, a chamfer between.
    if (grown.contains(p)) {
      EXPECT_TRUE(chamferOut.contains(p)) << p.x << ", " << p.y;
    }
    if (chamferOut.contains(p)) {
      EXPECT_TRUE(mitreOut.contains(p)) << p.x << ", " << p.y;
    }
    if (mitreIn.contains(p)) {
      EXPECT_TRUE(chamferIn.contains(p)) << p.x << ", " << p.y;
    }
    if (chamferIn.contains(p)) {
      EXPECT_TRUE(shrunk.contains(p)) << p.x << ", " << p.y;
    }
  }
}

TEST(RegionOffset, GrownUnionsOfDiscsAndBoxesHoldWhatIsNear) {
  // The distance to a union is the least distance to its parts: a point is
  // in offset(r) exactly when some part is nearer than r.
  std::mt19937 random(17);
  std::uniform_real_distribution<double> u(-2.0, 2.0), size(0.1, 1.0), grow(0.02, 0.6);
  for (int round = 0; round < 12; ++round) {
    std::vector<RegionPtr> parts;
    std::vector<std::function<double(dvec2)>> distances;
    for (int i = 0; i < 2 + round % 4; ++i) {
      const dvec2 c(u(random), u(random));
      const double s = size(random);
      if (i % 2 == 0) {
        parts.push_back(disc(c, s));
        distances.push_back([=](dvec2 p) { return std::max(0.0, glm::length(p - c) - s); });
      } else {
        parts.push_back(rect(c.x, c.y, c.x + s, c.y + 0.7 * s));
        distances.push_back(
            [=](dvec2 p) { return glm::length(p - glm::clamp(p, c, c + dvec2(s, 0.7 * s))); });
      }
    }
    const RegionPtr all = Region::boolean(Region::Op::Union, parts);
    const double r = grow(random);
    const Profile grown = offsetRounded(*all, r, kTolerance);
    expectClosed(grown);
    std::uniform_real_distribution<double> w(-3.5, 3.5);
    for (int i = 0; i < 1500; ++i) {
      const dvec2 p(w(random), w(random));
      double e = INFINITY;
      for (const auto& distance : distances) e = std::min(e, distance(p));
      if (std::abs(e - r) < 1e-9) continue;
      ASSERT_EQ(grown.contains(p), e < r)
          << round << ": " << p.x << ", " << p.y << " at " << e << " of " << r;
    }
  }
}

// The distance from p to an evaluated profile's boundary: its segments and
// circular arcs.
double distanceToBoundary(const Profile& profile, const dvec2& p) {
  double best = INFINITY;
  for (const ProfileLoop& loop : profile.loops)
    for (const ProfileEdge& e : loop.edges) {
      best = std::min({best, glm::length(p - e.from), glm::length(p - e.to)});
      if (e.kind == ProfileEdge::Kind::Segment) {
        const dvec2 ab = e.to - e.from;
        const double t = std::clamp(glm::dot(p - e.from, ab) / glm::dot(ab, ab), 0.0, 1.0);
        best = std::min(best, glm::length(p - e.from - t * ab));
        continue;
      }
      // An arc: the radius through p, where it meets the arc.
      const double radius = std::sqrt(std::abs(glm::determinant(e.axes)));
      const dvec2 v = p - e.center;
      const double lo = std::min(e.angle0, e.angle1), hi = std::max(e.angle0, e.angle1);
      double theta = std::atan2(v.y, v.x);  // brought into [lo, lo + 2π)
      theta = lo + std::fmod(std::fmod(theta - lo, 2.0 * kPi) + 2.0 * kPi, 2.0 * kPi);
      if (theta <= hi) best = std::min(best, std::abs(glm::length(v) - radius));
    }
  return best;
}

TEST(RegionOffset, OffsetsOfDiscsAndBoxesLessDiscsHoldWhatIsNear) {
  // As below, with arcs: unions of discs and boxes less discs, grown and
  // shrunk, then opened and closed (the second offset meets arcs whose
  // radius is its own).
  std::mt19937 random(53);
  std::uniform_real_distribution<double> u(-2.0, 2.0), size(0.1, 1.2), amount(0.02, 0.5);
  for (int round = 0; round < 16; ++round) {
    std::vector<RegionPtr> parts, cuts;
    for (int i = 0; i < 2 + round % 3; ++i) {
      const dvec2 c(u(random), u(random));
      const double s = size(random);
      parts.push_back(i % 2 ? rect(c.x, c.y, c.x + s, c.y + 0.7 * s) : disc(c, s));
    }
    for (int i = 0; i < round % 3; ++i)
      cuts.push_back(disc({u(random), u(random)}, 0.4 * size(random)));
    RegionPtr region = Region::boolean(Region::Op::Union, parts);
    if (!cuts.empty()) region = subtract(region, Region::boolean(Region::Op::Union, cuts));
    const double r = amount(random);
    for (const RegionPtr& shape : {region, Region::leaf(offsetRounded(*region, r, kTolerance)),
                                   Region::leaf(offsetRounded(*region, -r, kTolerance))}) {
      const Profile exact = evaluate(*shape, kTolerance);
      const Profile grown = offsetRounded(*shape, r, kTolerance);
      const Profile shrunk = offsetRounded(*shape, -r, kTolerance);
      expectClosed(grown);
      expectClosed(shrunk);
      std::uniform_real_distribution<double> w(-3.5, 3.5);
      for (int i = 0; i < 1000; ++i) {
        const dvec2 p(w(random), w(random));
        const double e = distanceToBoundary(exact, p);
        if (std::abs(e - r) < 1e-9) continue;
        const bool in = exact.contains(p);
        ASSERT_EQ(grown.contains(p), in || e < r)
            << round << ": " << p.x << ", " << p.y << " at " << e << " of " << r;
        ASSERT_EQ(shrunk.contains(p), in && e > r)
            << round << ": " << p.x << ", " << p.y << " at " << e << " of " << r;
      }
    }
  }
}

TEST(RegionOffset, OffsetsOfFramesAndNotchesHoldWhatIsNear) {
  // Unions of boxes less boxes (holes, notches, islands of every size
  // against the offset), grown and shrunk: a point is in offset(r) exactly
  // when it is within r of the region, and in offset(−r) exactly when it is
  // in the region more than r from its boundary.
  std::mt19937 random(29);
  std::uniform_real_distribution<double> u(-2.0, 2.0), size(0.1, 1.5), amount(0.02, 0.6);
  for (int round = 0; round < 16; ++round) {
    std::vector<RegionPtr> parts, cuts;
    for (int i = 0; i < 2 + round % 3; ++i) {
      const dvec2 c(u(random), u(random));
      parts.push_back(rect(c.x, c.y, c.x + size(random), c.y + size(random)));
    }
    for (int i = 0; i < 1 + round % 3; ++i) {
      const dvec2 c(u(random), u(random));
      cuts.push_back(rect(c.x, c.y, c.x + 0.5 * size(random), c.y + 0.5 * size(random)));
    }
    const RegionPtr region = subtract(Region::boolean(Region::Op::Union, parts),
                                      Region::boolean(Region::Op::Union, cuts));
    const Profile exact = evaluate(*region, kTolerance);
    const auto toBoundary = [&](const dvec2& p) { return distanceToBoundary(exact, p); };
    // Every edge is axis-parallel and every corner square, so the mitred
    // offset is the points within r of the region in the largest of the
    // axes' distances (the Minkowski sum with a square), and the chamfer
    // lies between the rounding and the mitre.
    const auto toBoundaryAlongAxes = [&](const dvec2& p) {
      double best = INFINITY;
      for (const ProfileLoop& loop : exact.loops)
        for (const ProfileEdge& e : loop.edges) {
          const dvec2 lo = glm::min(e.from, e.to), hi = glm::max(e.from, e.to);
          const dvec2 gap = glm::max(glm::max(lo - p, p - hi), dvec2(0.0));
          best = std::min(best, std::max(gap.x, gap.y));
        }
      return best;
    };
    const double r = amount(random);
    const Profile grown = offsetRounded(*region, r, kTolerance);
    const Profile shrunk = offsetRounded(*region, -r, kTolerance);
    const Profile mitreOut = offsetDelta(*region, r, false, kTolerance);
    const Profile mitreIn = offsetDelta(*region, -r, false, kTolerance);
    const Profile chamferOut = offsetDelta(*region, r, true, kTolerance);
    const Profile chamferIn = offsetDelta(*region, -r, true, kTolerance);
    for (const Profile* q : {&grown, &shrunk, &mitreOut, &mitreIn, &chamferOut, &chamferIn})
      expectClosed(*q);
    std::uniform_real_distribution<double> w(-3.0, 4.0);
    for (int i = 0; i < 1500; ++i) {
      const dvec2 p(w(random), w(random));
      const double e = toBoundary(p), square = toBoundaryAlongAxes(p);
      if (std::abs(e - r) < 1e-9 || std::abs(square - r) < 1e-9) continue;
      const bool in = exact.contains(p);
      ASSERT_EQ(grown.contains(p), in || e < r)
          << round << ": " << p.x << ", " << p.y << " at " << e << " of " << r;
      ASSERT_EQ(shrunk.contains(p), in && e > r)
          << round << ": " << p.x << ", " << p.y << " at " << e << " of " << r;
      ASSERT_EQ(mitreOut.contains(p), in || square < r)
          << round << ": " << p.x << ", " << p.y << " at " << square << " of " << r;
      ASSERT_EQ(mitreIn.contains(p), in && square > r)
          << round << ": " << p.x << ", " << p.y << " at " << square << " of " << r;
      if (grown.contains(p)) {
        ASSERT_TRUE(chamferOut.contains(p)) << p.x << ", " << p.y;
      }
      if (chamferOut.contains(p)) {
        ASSERT_TRUE(mitreOut.contains(p)) << p.x << ", " << p.y;
      }
      if (mitreIn.contains(p)) {
        ASSERT_TRUE(chamferIn.contains(p)) << p.x << ", " << p.y;
      }
      if (chamferIn.contains(p)) {
        ASSERT_TRUE(shrunk.contains(p)) << p.x << ", " << p.y;
      }
    }
  }
}

TEST(RegionOffset, AnOpeningRoundsTheOuterCornersOnly) {
  // An L shrunk by r and grown by r again: each of its five outer corners
  // loses the square r² less a quarter disc; the inner corner, which the
  // inset rounds with an arc about it, comes back sharp (that arc moves
  // onto its centre, the corner).
  const RegionPtr l = subtract(rect(0, 0, 2, 2), rect(1, 1, 3, 3));
  for (const double r : {0.25, 0.125}) {
    const RegionPtr shrunk = Region::leaf(offsetRounded(*l, -r, kTolerance));
    const Profile opened = offsetRounded(*shrunk, r, kTolerance);
    ASSERT_EQ(opened.loops.size(), 1u);
    EXPECT_NEAR(area(opened), 3.0 - 5.0 * (1.0 - kPi / 4.0) * r * r, 1e-12) << r;
    expectClosed(opened);
  }
}

TEST(RegionOffset, AGrowthShrunkAgainKeepsItsArcs) {
  // A bar and a disc that touch at one point (wall_hook.lua's plate and
  // cup), grown by 2 and shrunk by 2 again: the disc's far side comes back
  // to its radius, rounded or mitred, and the rounded closing holds the
  // region (the mitre may cut into the cusp it filled). Offsets made of
  // a band of pieces once left a ring 14 to 16 from the centre there.
  const RegionPtr s = Region::boolean(Region::Op::Union, {rect(0, 0, 6, 60), disc({20, 14}, 14)});
  const RegionPtr grown = Region::leaf(offsetRounded(*s, 2.0, kTolerance));
  const Profile region = evaluate(*s, kTolerance), outer = evaluate(*grown, kTolerance);
  const Profile rounded = offsetRounded(*grown, -2.0, kTolerance);
  const Profile mitred = offsetDelta(*grown, -2.0, false, kTolerance);
  for (int i = 0; i <= 60; ++i) {
    const double a = (i - 30) * kPi / 60.0;  // the side away from the bar
    for (const double radius : {13.9, 14.1, 15.0, 15.9}) {
      const dvec2 p = dvec2(20, 14) + radius * dvec2(std::cos(a), std::sin(a));
      EXPECT_EQ(rounded.contains(p), radius < 14.0) << radius << " at " << a;
      EXPECT_EQ(mitred.contains(p), radius < 14.0) << radius << " at " << a;
    }
  }
  std::mt19937 random(41);
  std::uniform_real_distribution<double> x(-3.0, 37.0), y(-3.0, 63.0);
  for (int i = 0; i < 3000; ++i) {
    const dvec2 p(x(random), y(random));
    if (region.contains(p)) {
      EXPECT_TRUE(rounded.contains(p)) << p.x << ", " << p.y;
    }
    if (rounded.contains(p) || mitred.contains(p)) {
      EXPECT_TRUE(outer.contains(p)) << p.x << ", " << p.y;
    }
  }
}

TEST(RegionOffset, BadOffsetsAreRefused) {
  EXPECT_THROW(offsetRounded(*rect(0, 0, 1, 1), std::nan(""), kTolerance), std::invalid_argument);
  EXPECT_THROW(offsetDelta(*rect(0, 0, 1, 1), INFINITY, false, kTolerance), std::invalid_argument);
  EXPECT_TRUE(offsetRounded(*rect(0, 0, 1, 1), -0.5, kTolerance).loops.empty());
  EXPECT_NEAR(area(offsetRounded(*rect(0, 0, 1, 1), 0.0, kTolerance)), 1.0, 1e-15);
}

// ---- Hulls --------------------------------------------------------------------

// The area of the convex hull of points (Andrew's monotone chain).
double convexHullArea(std::vector<dvec2> points) {
  std::sort(points.begin(), points.end(),
            [](dvec2 a, dvec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  std::vector<dvec2> h(2 * points.size());
  std::size_t k = 0;
  const auto turn = [](dvec2 o, dvec2 a, dvec2 b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && turn(h[k - 2], h[k - 1], points[i]) <= 0) --k;
    h[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && turn(h[k - 2], h[k - 1], points[i]) <= 0) --k;
    h[k++] = points[i];
  }
  double a = 0.0;
  for (std::size_t i = 0; i + 1 < k; ++i) a += h[i].x * h[i + 1].y - h[i + 1].x * h[i].y;
  return 0.5 * a;
}

TEST(RegionHull, TwoDiscs) {
  const double r = 0.75, d = 3.0;
  const std::vector<RegionPtr> discs{disc({0, 0}, r), disc({d, 0}, r)};
  const Profile p = hull(discs, kTolerance);
  ASSERT_EQ(p.loops.size(), 1u);
  EXPECT_EQ(p.loops[0].edges.size(), 4u);
  EXPECT_NEAR(area(p), kPi * r * r + 2.0 * r * d, 1e-12);
  expectClosed(p);
  // Discs of different radii, along a diagonal.
  const std::vector<RegionPtr> unequal{disc({0, 0}, 1.0), disc({2, 2}, 0.5)};
  const Profile q = hull(unequal, kTolerance);
  EXPECT_EQ(q.loops.at(0).edges.size(), 4u);
  // The belt: the tangent segments' length is √(D² − Δr²) each, and the
  // arcs take π ± 2·asin(Δr/D) of their circles.
  const double distance = std::sqrt(8.0), dr = 0.5, beta = std::asin(dr / distance);
  const double expected = std::sqrt(distance * distance - dr * dr) * (1.0 + 0.5) +
                          0.5 * (kPi + 2.0 * beta) * 1.0 + 0.5 * (kPi - 2.0 * beta) * 0.25;
  EXPECT_NEAR(area(q), expected, 1e-12);
}

TEST(RegionHull, OfPointsIsTheirConvexPolygon) {
  std::mt19937 random(11);
  std::normal_distribution<double> u(0.0, 1.0);
  std::vector<dvec2> points;
  for (int i = 0; i < 300; ++i) points.emplace_back(u(random), u(random));
  // A polygon through all of them (even-odd, self-crossing): its hull is
  // the points'.
  const std::vector<RegionPtr> regions{polygon({points})};
  const Profile p = hull(regions, kTolerance);
  ASSERT_EQ(p.loops.size(), 1u);
  EXPECT_NEAR(area(p), convexHullArea(points), 1e-9);
  expectClosed(p);
  // Squares on a grid, corners collinear along the hull's sides.
  std::vector<RegionPtr> squares;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 3; ++j) squares.push_back(rect(2 * i, 2 * j, 2 * i + 1, 2 * j + 1));
  const Profile grid = hull(squares, kTolerance);
  EXPECT_EQ(grid.loops.at(0).edges.size(), 4u);
  EXPECT_NEAR(area(grid), 7.0 * 5.0, 1e-12);
}

TEST(RegionHull, ArcsOnlyWhereTheyBulge) {
  // An L has a pentagon for a hull; a rounded square is its own hull; a
  // washer's is its outer disc.
  const RegionPtr l = subtract(rect(0, 0, 2, 2), rect(1, 1, 3, 3));
  EXPECT_NEAR(area(hull(std::vector{l}, kTolerance)), 3.5, 1e-12);
  const Profile rounded = offsetRounded(*rect(0, 0, 2, 1), 0.25, kTolerance);
  const Profile h = hull(std::vector{Region::leaf(rounded)}, kTolerance);
  EXPECT_NEAR(area(h), area(rounded), 1e-12);
  EXPECT_EQ(h.loops.at(0).edges.size(), 8u);
  const Profile w = hull(std::vector{subtract(disc({1, 1}, 2), disc({1.5, 1}, 1))}, kTolerance);
  EXPECT_EQ(w.loops.at(0).edges.size(), 1u);
  EXPECT_NEAR(area(w), 4.0 * kPi, 1e-12);
  // A disc and a point: two tangents and the far arc of the circle.
  const double r = 1.0, d = 3.0;
  const Profile cone =
      hull(std::vector{disc({0, 0}, r), polygon({{{d, 0}, {d, 1e-9}, {d + 1e-9, 0}}})}, kTolerance);
  EXPECT_NEAR(area(cone), r * std::sqrt(d * d - r * r) + r * r * (kPi - std::acos(r / d)), 1e-8);
  // A crescent of a disc bulges only on its outer arc.
  const RegionPtr crescent = subtract(disc({0, 0}, 1), disc({0.5, 0}, 0.8));
  const Profile c = hull(std::vector{crescent}, kTolerance);
  const Profile e = evaluate(*crescent, kTolerance);
  EXPECT_GT(area(c), area(e));
  for (const ProfileEdge& edge : c.loops.at(0).edges)
    if (edge.kind == ProfileEdge::Kind::Arc) {
      EXPECT_NEAR(glm::length(edge.center), 0.0, 1e-12);
    }
}

TEST(RegionHull, RandomDiscsAndBoxesAgreeWithAFinePolygon) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> u(-3.0, 3.0), size(0.05, 1.5);
  for (int round = 0; round < 40; ++round) {
    std::vector<RegionPtr> regions;
    const int n = 1 + round % 6;
    for (int i = 0; i < n; ++i) {
      const dvec2 c(u(random), u(random));
      const double s = size(random);
      if (i % 3 == 2)
        regions.push_back(rect(c.x, c.y, c.x + s, c.y + 0.5 * s));
      else if (i % 3 == 1)
        regions.push_back(subtract(disc(c, s), disc(c + dvec2(0.5 * s, 0.0), 0.8 * s)));
      else
        regions.push_back(disc(c, s));
    }
    const Profile h = hull(regions, kTolerance);
    ASSERT_EQ(h.loops.size(), 1u) << round;
    expectClosed(h);
    // The hull of a fine inscribed polygon of every outline is inside it,
    // and short of it by at most the tolerance along its perimeter (< 50).
    const double fine = 1e-7;
    std::vector<dvec2> points;
    for (const RegionPtr& r : regions)
      for (const auto& loop : flatten(evaluate(*r, kTolerance), fine))
        points.insert(points.end(), loop.begin(), loop.end());
    const double polygonArea = convexHullArea(points);
    EXPECT_GE(area(h), polygonArea - 1e-9) << round;
    EXPECT_LE(area(h), polygonArea + 50.0 * fine) << round;
    // Convex: it never turns right.
    const auto polygon = flatten(h, 1e-3).front();
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const dvec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()],
                  c = polygon[(i + 2) % polygon.size()];
      EXPECT_GE((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x), -1e-9) << round;
    }
  }
}

TEST(RegionHull, EmptyInput) {
  EXPECT_TRUE(hull({}, kTolerance).loops.empty());
  EXPECT_TRUE(
      hull(std::vector{intersect(rect(0, 0, 1, 1), rect(2, 2, 3, 3))}, kTolerance).loops.empty());
}

}  // namespace
}  // namespace csgray::detail
