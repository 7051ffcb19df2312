// The point test of a swept region, which a ray that enters an extrusion
// through its cap asks: it answers from a grid of cells that no edge
// passes through, and from the edges elsewhere. Both must agree with the
// region's own test everywhere: far from the edges, where the grid
// answers, and a hair off them, where the edges do.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <optional>
#include <random>
#include <string>

#include "primitives/profile_sweep.h"
#include "profile/glyph_outlines.h"
#include "profile/region.h"
#include "profile/shapes.h"

namespace csgray::detail {
namespace {

RegionPtr text(const std::string& s) {
  TextLayout layout;
  layout.text = s;
  layout.size = 10.0;
  return textRegion(layout);
}

// A leaf of cubic and quadratic Bézier curves: a lens and a droplet.
RegionPtr curves() {
  ProfileLoop lens;
  lens.edges = {ProfileEdge::cubic({0, 0}, {1, 3}, {5, 3}, {6, 0}),
                ProfileEdge::cubic({6, 0}, {5, -2}, {1, -2}, {0, 0})};
  ProfileLoop drop;
  drop.edges = {ProfileEdge::quadratic({8, 0}, {11, 4}, {14, 0}),
                ProfileEdge::quadratic({14, 0}, {11, -1}, {8, 0})};
  return Region::leaf(Profile{{lens, drop}});
}

// Points a ray might ask about: anywhere in the region's box (grown a
// little), and (nearEdges) next to the boundary, a millionth of the
// region's size off each edge's middle across it, and off its start in two
// slanted directions (not along an edge: a point on one is neither in nor
// out).
std::vector<dvec2> probes(const Region& region, unsigned seed, bool nearEdges) {
  const ProfileBounds box = region.bounds();
  const dvec2 size = box.hi - box.lo;
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(-0.05, 1.05);
  std::vector<dvec2> points;
  for (int i = 0; i < 20000; ++i)
    points.push_back(box.lo + dvec2(unit(random), unit(random)) * size);
  const double hair = 1e-6 * std::max(size.x, size.y);
  if (!nearEdges) return points;
  std::vector<const Region*> leaves{&region};
  for (std::size_t i = 0; i < leaves.size(); ++i) {
    if (leaves[i]->op() != Region::Op::Leaf) {
      for (const RegionPtr& r : leaves[i]->operands()) leaves.push_back(r.get());
      continue;
    }
    for (const ProfileLoop& loop : leaves[i]->profile().loops)
      for (const ProfileEdge& e : loop.edges) {
        // The middle, and the curve's direction there (from nearby points).
        const auto at = [&](double f) {
          return e.kind == ProfileEdge::Kind::Arc ? e.arcPoint(e.angle0 + f * (e.angle1 - e.angle0))
                 : e.bezier()                     ? bezierPoint(e, f)
                                                  : e.from + f * (e.to - e.from);
        };
        const dvec2 along = glm::normalize(at(0.501) - at(0.499));
        const dvec2 across(-along.y, along.x);
        for (const dvec2& d : {across, -across}) points.push_back(at(0.5) + hair * d);
        for (const double angle : {1.0, 2.5}) {
          const dvec2 d(std::cos(angle), std::sin(angle));
          points.push_back(e.from + hair * d);
          points.push_back(e.from - hair * d);
        }
      }
  }
  return points;
}

void expectAgreement(const RegionPtr& region, const std::string& what, bool exactCurves = true) {
  const SweptRegion swept(region, "test", exactCurves);
  int disagree = 0, inside = 0;
  const std::vector<dvec2> points = probes(*region, 7, exactCurves);
  for (const dvec2& p : points) {
    const bool expected = region->contains(p);
    inside += expected;
    if (swept.contains(p) != expected && ++disagree <= 5)
      ADD_FAILURE() << what << ": (" << p.x << ", " << p.y << ") is "
                    << (expected ? "inside" : "outside") << " the region";
  }
  EXPECT_EQ(disagree, 0) << what;
  // Both sides were asked about.
  EXPECT_GT(inside, 1000) << what;
  EXPECT_LT(inside, int(points.size()) - 1000) << what;
}

TEST(SweptRegion, ContainsAgreesWithTheRegion) {
  expectAgreement(text("M3 &@g%"), "text");
  expectAgreement(curves(), "Bezier curves");
  // Arcs, and leaves combined: a ring less a slot, a slanted star.
  expectAgreement(Region::boolean(Region::Op::Difference,
                                  {circleRegion(5.0, std::nullopt), circleRegion(2.0, std::nullopt),
                                   rectangleRegion("square", 12.0, 1.0, true)}),
                  "ring less a slot");
  expectAgreement(ellipseRegion(7.0, 0.5), "a flat ellipse");
  std::vector<dvec2> star;
  for (int k = 0; k < 14; ++k) {
    const double angle = k * std::numbers::pi / 7.0, r = k % 2 ? 1.5 : 6.0;
    star.push_back({r * std::cos(angle), r * std::sin(angle)});
  }
  expectAgreement(polygonRegion(star, {}), "star");
}

// Paths that are not straight lines meet polygons for the curves: the
// flattened text must agree too, but for points within the flattening's
// tolerance of a curve (so the probes are the random ones only).
TEST(SweptRegion, FlattenedCurvesAgreeToo) { expectAgreement(text("S@"), "text", false); }

}  // namespace
}  // namespace csgray::detail
