// Edge lines (raytrace/edge_lines.h): the rule between two neighbouring
// pixels, and lines on a rendered box exactly along its outline and its
// creases, nowhere else.
#include "raytrace/edge_lines.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <string>

#include "raytrace/renderer.h"
#include "script/script.h"

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

// A box from a script, rendered with and without lines: a pixel changes
// exactly when it is on the box and a neighbour is off it, or on another
// face of it (the normals the renderer gives differ).
TEST(EdgeLines, OnABoxAlongItsOutlineAndCreases) {
  Scene scene = runScript("return box(10)", "part.lua");
  const int w = 160, h = 120;
  RenderOptions options(w, h, 2);
  options.depthAov = options.normalAov = true;
  RenderResult plain = Renderer(scene, options).renderAll();
  options.edges = true;
  RenderResult lined = Renderer(scene, options).renderAll();
  auto hit = [&](int x, int y) { return !std::isinf(plain.depth.at(x, y).x); };
  int outline = 0, crease = 0;
  for (int y = 1; y < h - 1; ++y)
    for (int x = 1; x < w - 1; ++x) {
      const bool changed = plain.color.at(x, y) != lined.color.at(x, y);
      if (!hit(x, y)) {
        EXPECT_FALSE(changed) << x << "," << y;
        continue;
      }
      bool offNext = false, otherFace = false;
      for (auto [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        if (!hit(x + dx, y + dy))
          offNext = true;
        else if (plain.normal.at(x, y) != plain.normal.at(x + dx, y + dy))
          otherFace = true;
      }
      if (offNext) {
        EXPECT_TRUE(changed) << x << "," << y;
        outline += changed;
      } else if (!otherFace) {
        EXPECT_FALSE(changed) << x << "," << y;
      } else {
        crease += changed;
      }
      if (changed)
        for (int i = 0; i < 3; ++i)
          EXPECT_EQ(float(lined.color.at(x, y)[i]), float(withEdge(plain.color.at(x, y))[i]));
    }
  EXPECT_GT(outline, 200);
  EXPECT_GT(crease, 50);
}

}  // namespace
}  // namespace csgray::detail
