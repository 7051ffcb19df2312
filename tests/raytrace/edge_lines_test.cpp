// Edge lines (raytrace/edge_lines.h): the rule between two neighbouring
// pixels, and smooth lines on a rendered box along its outline and its
// creases, nowhere else, centred on the exact edge.
#include "raytrace/edge_lines.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <string>

#include "engine/solid.h"
#include "raytrace/renderer.h"
#include "script/script.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

// Seen along +y from y = -10: t is the distance from y = -10.
SurfaceSample sampleOn(const void* surface, int face, const dvec3& p, const dvec3& normal) {
  SurfaceSample s;
  s.surface = surface;
  s.face = face;
  s.t = float(p.y + 10.0);
  s.normal = glm::vec3(glm::normalize(normal));
  return s;
}

const int kA = 0, kB = 0;  // stand-ins for two primitives
const void* const a = &kA;
const void* const b = &kB;

TEST(EdgeLines, OutlineAgainstNothing) {
  SurfaceSample none;
  SurfaceSample hit = sampleOn(a, 0, dvec3(0), dvec3(0, -1, 0));
  EXPECT_EQ(edgeBetween(none, dvec3(0), hit, dvec3(0), 0.01), EdgeSide::Second);
  EXPECT_EQ(edgeBetween(hit, dvec3(0), none, dvec3(0), 0.01), EdgeSide::First);
  EXPECT_EQ(edgeBetween(none, dvec3(0), none, dvec3(0), 0.01), EdgeSide::None);
}

TEST(EdgeLines, FlushFacesAndSmoothSurfacesHaveNone) {
  // One plane, one face; and two primitives flush in one plane.
  const dvec3 p(0, 0, 0), q(0.01, 0, 0), n(0, -1, 0);
  EXPECT_EQ(edgeBetween(sampleOn(a, 0, p, n), p, sampleOn(a, 0, q, n), q, 0.01), EdgeSide::None);
  EXPECT_EQ(edgeBetween(sampleOn(a, 0, p, n), p, sampleOn(b, 3, q, n), q, 0.01), EdgeSide::None);
  // Neighbouring points of one sphere, even near its outline.
  for (double angle : {0.0, 1.0, 1.5}) {
    const dvec3 u(std::sin(angle), -std::cos(angle), 0),
        v(std::sin(angle + 0.01), -std::cos(angle + 0.01), 0);
    EXPECT_EQ(edgeBetween(sampleOn(a, 0, u, u), u, sampleOn(a, 0, v, v), v, 0.01), EdgeSide::None)
        << angle;
  }
  // Two faces that meet at 20°, under the crease angle of 30°.
  const double r = 20.0 * std::acos(-1.0) / 180.0;
  EXPECT_EQ(edgeBetween(sampleOn(a, 0, p, n), p,
                        sampleOn(b, 0, q, dvec3(std::sin(r), -std::cos(r), 0)), q, 0.01),
            EdgeSide::None);
}

TEST(EdgeLines, CreasesAndStepsGoToTheNearerSide) {
  // A box's corner seen edge-on: front face and side face at 90°.
  const dvec3 front(0, 0, 0), side(0.01, 0.01, 0);
  EXPECT_EQ(edgeBetween(sampleOn(a, 0, front, dvec3(0, -1, 0)), front,
                        sampleOn(a, 1, side, dvec3(1, 0, 0)), side, 0.01),
            EdgeSide::First);
  EXPECT_EQ(edgeBetween(sampleOn(a, 1, side, dvec3(1, 0, 0)), side,
                        sampleOn(a, 0, front, dvec3(0, -1, 0)), front, 0.01),
            EdgeSide::Second);
  // One face of one primitive over another part of itself, far behind
  // (the outline of a torus over its own far side).
  const dvec3 near(0, 0, 0), far(0.01, 5, 0), n(0, -1, 0);
  EXPECT_EQ(edgeBetween(sampleOn(a, 0, far, n), far, sampleOn(a, 0, near, n), near, 0.01),
            EdgeSide::Second);
}

TEST(EdgeLines, TwoUsesOfOnePrimitiveMeetAtACrease) {
  // Two places of one shared box (instances): the same primitive and face,
  // turned 90° apart, get a line; the same use does not.
  const dvec3 p(0, 0, 0), q(0.01, 0.01, 0);
  SurfaceSample first = sampleOn(a, 0, p, dvec3(0, -1, 0));
  SurfaceSample second = sampleOn(a, 0, q, dvec3(1, 0, 0));
  first.use = 11;
  second.use = 12;
  EXPECT_EQ(edgeBetween(first, p, second, q, 0.01), EdgeSide::First);
  second.use = 11;
  EXPECT_EQ(edgeBetween(first, p, second, q, 0.01), EdgeSide::None);
}

// The share of the line in a pixel: 0 for the plain colour, 1 for the
// line's full colour over it, from the channel that differs most.
double coverageOf(const dvec3& plain, const dvec3& lined) {
  const dvec3 full = withEdge(plain) - plain;
  int i = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(full[k]) > std::abs(full[i])) i = k;
  return (lined[i] - plain[i]) / full[i];
}

// Two tilted uses of one bar, given by the Lua function bar(), shared
// (one tree placed by two instances) and made apart, rendered with lines:
// how many pixels differ between the two, and how many the lines change.
struct SharedAndApart {
  int differ = 0, lined = 0;
};
SharedAndApart sharedAndApart(const std::string& bar) {
  Scene shared = runScript(bar +
                               "local b = bar()\nreturn union(b:rotate(25, 0, 0), "
                               "b:rotate(-25, 0, 0))",
                           "part.lua");
  Scene apart =
      runScript(bar + "return union(bar():rotate(25, 0, 0), bar():rotate(-25, 0, 0))", "part.lua");
  EXPECT_EQ(treeStats(*shared.objects[0]).storedPrimitives, 2u);
  EXPECT_EQ(treeStats(*apart.objects[0]).storedPrimitives, 4u);
  RenderOptions options(200, 150, 1);
  options.edges = true;
  const Image a = Renderer(shared, options).render(), b = Renderer(apart, options).render();
  options.edges = false;
  const Image plain = Renderer(apart, options).render();
  SharedAndApart counts;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      counts.differ += glm::length(a.at(x, y) - b.at(x, y)) > 0.02;
      counts.lined += glm::length(b.at(x, y) - plain.at(x, y)) > 0.02;
    }
  return counts;
}

// The two bars (a union) meet in a valley where the same face of the same
// box meets itself turned by 50°: the valley gets its line as it does when
// the two bars are made apart, pixel for pixel.
TEST(EdgeLines, TwoPlacesOfOneSharedPartMeetAtALine) {
  const SharedAndApart counts = sharedAndApart(
      "local function bar() return union(box{size={10, 2, 2}}:translate(0, -1, -2), "
      "sphere{r=0.5}:translate(9, 0, -1)) end\n");
  EXPECT_EQ(counts.differ, 0);
  EXPECT_GT(counts.lined, 200);
}

// The same with a bar that is a difference (a notch cut from its far end):
// the renderer walks the two uses of it (only unions of uses are copied
// into place), so the valley is told from the face's two uses, not from
// two primitives.
TEST(EdgeLines, TwoPlacesOfOneSharedDifferenceMeetAtALine) {
  const SharedAndApart counts = sharedAndApart(
      "local function bar() return box{size={10, 2, 2}}:translate(0, -1, -2) - "
      "sphere{r=0.5}:translate(9, 0, 0) end\n");
  EXPECT_EQ(counts.differ, 0);
  EXPECT_GT(counts.lined, 200);
}

// A box from a script, rendered with and without lines: a pixel changes
// only beside the box's outline (on the box or off it) or beside a crease,
// always toward the line's colour by at most the full line; every pixel on
// the box beside its outline changes.
TEST(EdgeLines, OnABoxAlongItsOutlineAndCreases) {
  Scene scene = runScript("return box(10)", "part.lua");
  const int w = 160, h = 120;
  RenderOptions options(w, h, 2);
  options.depthAov = options.normalAov = true;
  RenderResult plain = Renderer(scene, options).renderAll();
  options.edges = true;
  RenderResult lined = Renderer(scene, options).renderAll();
  auto hit = [&](int x, int y) { return !std::isinf(plain.depth.at(x, y).x); };
  int outline = 0, crease = 0, partial = 0;
  for (int y = 1; y < h - 1; ++y)
    for (int x = 1; x < w - 1; ++x) {
      const bool changed = plain.color.at(x, y) != lined.color.at(x, y);
      bool offNext = false, otherFace = false;
      for (auto [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        if (hit(x, y) != hit(x + dx, y + dy))
          offNext = true;
        else if (hit(x, y) && plain.normal.at(x, y) != plain.normal.at(x + dx, y + dy))
          otherFace = true;
      }
      if (offNext) {
        if (hit(x, y)) {
          EXPECT_TRUE(changed) << x << "," << y;
        }
        outline += changed;
      } else if (!otherFace) {
        EXPECT_FALSE(changed) << x << "," << y;
      } else {
        crease += changed;
      }
      if (!changed) continue;
      const double c = coverageOf(plain.color.at(x, y), lined.color.at(x, y));
      EXPECT_GT(c, 0.0) << x << "," << y;
      EXPECT_LE(c, 1.0 + 1e-9) << x << "," << y;
      partial += c < 0.97;
    }
  EXPECT_GT(outline, 200);
  EXPECT_GT(crease, 50);
  EXPECT_GT(partial, 100);  // smooth: most edges cross pixels off their centres
}

// The right side of a box at x = 4.96, seen from the front on pixels of
// 0.2 whose centres are at x = 4.9 (pixel 74) and 5.1 (pixel 75): the edge
// is 0.3 of a pixel from 74's centre, so the line, one pixel wide and
// centred on it, covers 0.7 of pixel 74 and 0.3 of pixel 75.
TEST(EdgeLines, AntialiasedAndWhereTheEdgeIs) {
  Scene scene =
      runScript("return box{size={10, 10, 10}, center=true}:translate(-0.04, 0, 0)", "part.lua");
  scene.camera = test::frontOrthographicCamera(20.0);
  RenderOptions options(100, 100, 2);
  const Image plain = Renderer(scene, options).render();
  options.edges = true;
  const Image lined = Renderer(scene, options).render();
  const double inside = coverageOf(plain.at(74, 50), lined.at(74, 50));
  const double outside = coverageOf(plain.at(75, 50), lined.at(75, 50));
  EXPECT_NEAR(inside, 0.7, 1.0 / 32);
  EXPECT_NEAR(outside, 0.3, 1.0 / 32);
  // Between the surface's colour and the line's.
  EXPECT_LT(lined.at(74, 50).x, plain.at(74, 50).x);
  EXPECT_GT(lined.at(74, 50).x, withEdge(plain.at(74, 50)).x);
  // Further in and further out, nothing.
  EXPECT_EQ(lined.at(72, 50), plain.at(72, 50));
  EXPECT_EQ(lined.at(77, 50), plain.at(77, 50));
}

}  // namespace
}  // namespace csgray::detail
