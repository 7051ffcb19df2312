// The shapes of the plane: where they are, what they hold, and the
// messages for what they refuse.
#include "profile/shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>

namespace csgray::detail {
namespace {

void expectRefused(const std::function<void()>& make, const std::string& message) {
  try {
    make();
    ADD_FAILURE() << "accepted; expected: " << message;
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind(message, 0), 0u) << e.what();
  }
}

// The signed area of a loop of segments (the shoelace formula).
double polygonArea(const ProfileLoop& loop) {
  double twice = 0.0;
  for (const ProfileEdge& e : loop.edges) twice += e.from.x * e.to.y - e.to.x * e.from.y;
  return twice / 2.0;
}

void expectBox(const ProfileBounds& b, dvec2 lo, dvec2 hi) {
  EXPECT_NEAR(b.lo.x, lo.x, 1e-12);
  EXPECT_NEAR(b.lo.y, lo.y, 1e-12);
  EXPECT_NEAR(b.hi.x, hi.x, 1e-12);
  EXPECT_NEAR(b.hi.y, hi.y, 1e-12);
}

TEST(Shapes, RectanglesFromTheOriginOrCentred) {
  RegionPtr r = rectangleRegion("rectangle", 4, 2, false);
  expectBox(r->bounds(), {0, 0}, {4, 2});
  ASSERT_EQ(r->profile().loops.size(), 1u);
  EXPECT_DOUBLE_EQ(polygonArea(r->profile().loops[0]), 8.0);  // counterclockwise
  EXPECT_TRUE(r->contains({3.9, 1.9}));
  EXPECT_FALSE(r->contains({4.1, 1}));
  RegionPtr c = rectangleRegion("square", 3, 3, true);
  expectBox(c->bounds(), {-1.5, -1.5}, {1.5, 1.5});
  EXPECT_TRUE(c->contains({-1.4, 1.4}));
}

TEST(Shapes, CirclesAndEllipsesAreWholeArcs) {
  RegionPtr c = circleRegion(2.0, std::nullopt);
  ASSERT_EQ(c->profile().loops.size(), 1u);
  ASSERT_EQ(c->profile().loops[0].edges.size(), 1u);
  const ProfileEdge& arc = c->profile().loops[0].edges[0];
  EXPECT_EQ(arc.kind, ProfileEdge::Kind::Arc);
  EXPECT_TRUE(arc.circular());
  EXPECT_DOUBLE_EQ(arc.angle1 - arc.angle0, 2 * std::numbers::pi);  // counterclockwise
  expectBox(c->bounds(), {-2, -2}, {2, 2});
  // Points just inside and outside the circle at 45°.
  const double s = std::sqrt(0.5);
  EXPECT_TRUE(c->contains(1.999 * dvec2(s, s)));
  EXPECT_FALSE(c->contains(2.001 * dvec2(s, s)));
  expectBox(circleRegion(std::nullopt, 5.0)->bounds(), {-2.5, -2.5}, {2.5, 2.5});
  RegionPtr e = ellipseRegion(3, 1);
  expectBox(e->bounds(), {-3, -1}, {3, 1});
  EXPECT_FALSE(e->profile().loops[0].edges[0].circular());
  EXPECT_TRUE(e->contains({2.9, 0}));
  EXPECT_FALSE(e->contains({0, 1.1}));
  EXPECT_FALSE(e->contains({2.5, 0.6}));  // (2.5/3)² + 0.6² = 1.054 > 1
}

TEST(Shapes, PolygonsFillByTheEvenOddRule) {
  // A square with a square hole given by paths (the hole runs either way).
  std::vector<dvec2> points = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {3, 3}, {7, 3}, {7, 7}, {3, 7}};
  RegionPtr holed = polygonRegion(points, {{0, 1, 2, 3}, {4, 5, 6, 7}});
  ASSERT_EQ(holed->profile().loops.size(), 2u);
  EXPECT_TRUE(holed->contains({1, 1}));
  EXPECT_FALSE(holed->contains({5, 5}));
  // Without paths, all points make one loop.
  RegionPtr tri = polygonRegion({{0, 0}, {4, 0}, {0, 3}}, {});
  EXPECT_DOUBLE_EQ(polygonArea(tri->profile().loops[0]), 6.0);
  // A bow tie: its crossing halves are both inside (even-odd).
  RegionPtr bow = polygonRegion({{0, 0}, {2, 2}, {2, 0}, {0, 2}}, {});
  EXPECT_TRUE(bow->contains({1.9, 1}));
  EXPECT_TRUE(bow->contains({0.1, 1}));
  EXPECT_FALSE(bow->contains({1, 0.1}));
  // A star drawn in one stroke (the pentagram) leaves its centre out.
  std::vector<dvec2> star;
  for (int i = 0; i < 5; ++i) {
    double a = std::numbers::pi / 2 + i * 4 * std::numbers::pi / 5;
    star.push_back({std::cos(a), std::sin(a)});
  }
  RegionPtr pentagram = polygonRegion(star, {});
  EXPECT_FALSE(pentagram->contains({0, 0}));
  EXPECT_TRUE(pentagram->contains({0, 0.8}));
  // Repeated points and a closing point are dropped.
  RegionPtr closed = polygonRegion({{0, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 0}}, {});
  EXPECT_EQ(closed->profile().loops[0].edges.size(), 3u);
}

TEST(Shapes, RegularPolygonsByCornersOrAcrossFlats) {
  RegionPtr hex = regularPolygonRegion(6, 2.0, std::nullopt);
  ASSERT_EQ(hex->profile().loops[0].edges.size(), 6u);
  EXPECT_EQ(hex->profile().loops[0].edges[0].from, dvec2(2, 0));
  // Area of a regular n-gon of circumradius r: n r² sin(2π/n) / 2.
  EXPECT_NEAR(polygonArea(hex->profile().loops[0]), 3 * 4 * std::sin(std::numbers::pi / 3), 1e-12);
  // An M8 nut is 13 across its flats: the flats are at y = ±6.5.
  RegionPtr nut = regularPolygonRegion(6, std::nullopt, 13.0);
  EXPECT_NEAR(nut->bounds().hi.y, 6.5, 1e-12);
  EXPECT_NEAR(nut->bounds().lo.y, -6.5, 1e-12);
  EXPECT_NEAR(nut->bounds().hi.x, 6.5 / std::cos(std::numbers::pi / 6), 1e-12);
}

TEST(Shapes, BadInputIsRefusedWithTheReason) {
  expectRefused([] { rectangleRegion("square", 0, 0, false); },
                "square: size must be > 0 (got 0, 0)");
  expectRefused([] { rectangleRegion("rectangle", 1, -1, false); },
                "rectangle: size must be > 0 (got 1, -1)");
  expectRefused([] { rectangleRegion("rectangle", NAN, 1, false); },
                "rectangle: size must be finite");
  expectRefused([] { rectangleRegion("rectangle", 1e200, 1, false); },
                "rectangle: size is too large");
  expectRefused([] { circleRegion(std::nullopt, std::nullopt); }, "circle: needs r");
  expectRefused([] { circleRegion(1.0, 2.0); }, "circle: give r or d, not both");
  expectRefused([] { circleRegion(-1.0, std::nullopt); }, "circle: the radius must be > 0");
  expectRefused([] { circleRegion(INFINITY, std::nullopt); }, "circle: the radius must be finite");
  expectRefused([] { ellipseRegion(1, 0); }, "ellipse: ry must be > 0");
  expectRefused(
      [] {
        polygonRegion({{0, 0}, {1, 0}}, {});
      },
      "polygon: needs at least 3 distinct points (got 2)");
  expectRefused(
      [] {
        polygonRegion({{0, 0}, {1, 0}, {1, 0}, {0, 0}}, {});
      },
      "polygon: needs at least 3 distinct points (got 2)");
  expectRefused(
      [] {
        polygonRegion({{0, 0}, {1, 1}, {3, 3}}, {});
      },
      "polygon: the points are collinear");
  expectRefused(
      [] {
        polygonRegion({{0, 0}, {1, NAN}, {0, 1}}, {});
      },
      "polygon: points[2] must be finite");
  expectRefused(
      [] {
        polygonRegion({{0, 0}, {1, 0}, {0, 1}}, {{0, 1, 3}});
      },
      "polygon: paths[1]: index 3 is not a point (there are 3, from 0)");
  expectRefused(
      [] {
        polygonRegion({{0, 0}, {1, 0}, {0, 1}, {2, 2}}, {{0, 1, 2}, {0, 3}});
      },
      "polygon: paths[2]: needs at least 3 distinct points");
  expectRefused([] { regularPolygonRegion(2, 1.0, std::nullopt); },
                "regular_polygon: n must be a whole number from 3");
  expectRefused([] { regularPolygonRegion(5.5, 1.0, std::nullopt); },
                "regular_polygon: n must be a whole number");
  expectRefused([] { regularPolygonRegion(NAN, 1.0, std::nullopt); },
                "regular_polygon: n must be a whole number");
  expectRefused([] { regularPolygonRegion(6, std::nullopt, std::nullopt); },
                "regular_polygon: needs r");
  expectRefused([] { regularPolygonRegion(6, 1.0, 1.0); }, "regular_polygon: give r or flats");
  expectRefused([] { regularPolygonRegion(6, std::nullopt, 0.0); },
                "regular_polygon: flats must be > 0");
}

}  // namespace
}  // namespace csgray::detail
