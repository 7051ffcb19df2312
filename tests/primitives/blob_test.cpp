// The blob: a lone ball's surface where its field meets the threshold,
// spans against contains() and the first boundary against the whole spans
// for balls that melt and one that takes away, boundaries on the surface,
// outward normals, its mesh, the script function and a silhouette.
#include "primitives/blob.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "primitives/sweep_checks.h"
#include "raytrace/renderer.h"
#include "scene/camera.h"
#include "tessellation/triangle_mesh.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

using test::expectFirstBoundaryAgreesWithTheWholeSpans;
using test::expectOutwardUnitNormals;
using test::expectSpansAgreeWithContainsOnRandomLines;
using test::randomDirection;
using test::randomPoint;
using test::scriptError;
using test::spansOf;

constexpr double kPi = std::numbers::pi;

std::shared_ptr<Blob> blob(std::vector<BlobBall> balls, double threshold) {
  return Primitive::create<Blob>(std::move(balls), threshold);
}

// A lone ball of radius r and strength s is the ball where
// s·(1 − d²/r²)² >= t: d <= r·√(1 − √(t/s)).
double loneRadius(double r, double s, double t) { return r * std::sqrt(1.0 - std::sqrt(t / s)); }

// Three balls that melt into one another and a fourth that takes a bite.
std::shared_ptr<Blob> cluster() {
  return blob({{{0, 0, 0}, 2.0, 1.0},
               {{1.6, 0, 0}, 2.0, 1.0},
               {{0.8, 1.3, 0.4}, 1.5, 1.2},
               {{0.8, 0, 1.2}, 1.0, -1.0}},
              0.5);
}

TEST(BlobPrimitive, ALoneBallIsABallOfTheRadiusItsFieldGives) {
  for (auto [r, s, t] : {std::tuple{2.0, 1.0, 0.5}, {1.0, 3.0, 0.2}, {5.0, 0.9, 0.8}}) {
    const dvec3 c(1.0, -2.0, 0.5);
    auto b = blob({{c, r, s}}, t);
    const double want = loneRadius(r, s, t);
    std::mt19937_64 rng(3);
    for (int i = 0; i < 200; ++i) {
      const dvec3 u = randomDirection(rng);
      SpanList spans = spansOf(*b, Ray(c - 10.0 * u, u));
      ASSERT_EQ(spans.size(), 1u);
      EXPECT_NEAR(spans[0].in.t, 10.0 - want, 1e-12 * 10.0);
      EXPECT_NEAR(spans[0].out.t, 10.0 + want, 1e-12 * 10.0);
    }
    EXPECT_NEAR(test::gridVolume(*b, b->bounds(), 300), 4.0 / 3.0 * kPi * std::pow(want, 3),
                2e-3 * std::pow(want, 3));
  }
}

// Two balls of strength 1 and radius r at distance D: the midpoint's field
// is 2(1 − (D/2)²/r²)², so they join there iff that reaches the threshold.
TEST(BlobPrimitive, TwoBallsMeltWhereTheirFieldsAddUp) {
  const double r = 1.0, t = 0.5;
  for (double D : {1.0, 1.2, 1.3, 1.4}) {
    auto b = blob({{{-D / 2, 0, 0}, r, 1.0}, {{D / 2, 0, 0}, r, 1.0}}, t);
    const double middle = 2.0 * std::pow(1.0 - D * D / 4.0, 2.0);
    EXPECT_EQ(b->contains(dvec3(0.0)), middle >= t) << D;
    SpanList along = spansOf(*b, Ray(dvec3(-5, 0, 0), dvec3(1, 0, 0)));
    EXPECT_EQ(along.size(), middle >= t ? 1u : 2u) << D;
  }
}

TEST(BlobPrimitive, SpansAgreeWithContainsAndBoundariesLieOnTheSurface) {
  auto b = cluster();
  expectSpansAgreeWithContainsOnRandomLines(*b, 3000, 5);
  std::mt19937_64 rng(8);
  int boundaries = 0;
  for (int i = 0; i < 1000; ++i) {
    Ray line(randomPoint(rng, b->bounds()), randomDirection(rng), -kInfinity, kInfinity);
    for (const Span& span : spansOf(*b, line))
      for (double t : {span.in.t, span.out.t}) {
        const dvec3 p = line.at(t);
        // The distance to the surface to first order.
        EXPECT_LT(std::abs(b->excess(p)) / glm::length(b->fieldGradient(p)), 1e-9);
        ++boundaries;
      }
  }
  EXPECT_GT(boundaries, 500);
}

TEST(BlobPrimitive, FirstBoundaryAgreesWithTheWholeSpans) {
  const test::FirstBoundaryCounts counts =
      expectFirstBoundaryAgreesWithTheWholeSpans(*cluster(), 3000, 4);
  EXPECT_GT(counts.entries, 300);
  EXPECT_GT(counts.hits - counts.entries, 150);
}

TEST(BlobPrimitive, NormalsFaceOutward) { expectOutwardUnitNormals(*cluster(), 1e-9, 1000, 7); }

TEST(BlobPrimitive, FarAwayRaysStillHit) {
  auto b = blob({{{0, 0, 0}, 2.0, 1.0}}, 0.5);
  const dvec3 u = glm::normalize(dvec3(1, 0.2, -0.3));
  SpanList spans = spansOf(*b, Ray(-1e6 * u, u));
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_NEAR(spans[0].in.t, 1e6 - loneRadius(2, 1, 0.5), 1e-8);
}

TEST(BlobPrimitive, RefusesBadParameters) {
  EXPECT_THROW(blob({}, 0.5), std::invalid_argument);
  EXPECT_THROW(blob({{{0, 0, 0}, 1.0, 1.0}}, 0.0), std::invalid_argument);
  EXPECT_THROW(blob({{{0, 0, 0}, -1.0, 1.0}}, 0.5), std::invalid_argument);
  EXPECT_THROW(blob({{{0, 0, 0}, 1.0, 0.0}}, 0.5), std::invalid_argument);
  EXPECT_THROW(blob({{{0, 0, 0}, 1.0, -1.0}}, 0.5), std::invalid_argument);
  EXPECT_THROW(blob({{{0, std::nan(""), 0}, 1.0, 1.0}}, 0.5), std::invalid_argument);
}

// Closed, oriented, no crossings; within the tolerance of the surface at
// many points of every triangle; and the volume of the rays' within
// tolerance × area.
TEST(BlobTessellation, ClosedAndWithinTolerance) {
  auto b = cluster();
  const double exact = test::gridVolume(*b, b->bounds(), 400);
  for (double tolerance : {0.05, 0.01}) {
    SCOPED_TRACE(tolerance);
    TriangleMesh mesh = b->tessellate(tolerance, Bounds::everything());
    test::expectClosedMesh(mesh);
    EXPECT_NEAR(mesh.volume(), exact, tolerance * mesh.area());
    double worst = 0.0;
    for (const auto& t : mesh.triangles) {
      const dvec3 &p0 = mesh.points[t[0]], &p1 = mesh.points[t[1]], &p2 = mesh.points[t[2]];
      for (int i = 0; i <= 4; ++i)
        for (int j = 0; i + j <= 4; ++j) {
          const dvec3 p = p0 + (p1 - p0) * (i / 4.0) + (p2 - p0) * (j / 4.0);
          worst = std::max(worst, std::abs(b->excess(p)) / glm::length(b->fieldGradient(p)));
        }
    }
    EXPECT_LE(worst, tolerance);
  }
}

TEST(BlobScript, MakesOneAndNamesItsMistakes) {
  SolidPtr s = test::solidOf(
      "return blob{threshold=0.5, balls={{center={0, 0, 0}, r=2}, {center={1, 0, 0}, r=2, "
      "strength=1}}}");
  EXPECT_EQ(s->kind(), "blob");
  EXPECT_TRUE(s->contains(dvec3(0.5, 0, 0)));
  // The default threshold is 0.5, the strength 1.
  SolidPtr lone = test::solidOf("return blob{balls={{r=2}}}");
  EXPECT_TRUE(lone->contains(dvec3(loneRadius(2, 1, 0.5) - 1e-9, 0, 0)));
  EXPECT_FALSE(lone->contains(dvec3(loneRadius(2, 1, 0.5) + 1e-9, 0, 0)));
  EXPECT_NE(scriptError("return blob{}").find("blob: needs balls="), std::string::npos);
  EXPECT_NE(scriptError("return blob{balls={{center={0, 0, 0}}}}").find("ball 1: needs r"),
            std::string::npos);
  EXPECT_NE(scriptError("return blob{balls={{r=1, strength=0}}}").find("strength must not be 0"),
            std::string::npos);
  EXPECT_NE(scriptError("return blob{balls={{r=1, strength=-1}}}").find("positive strength"),
            std::string::npos);
  EXPECT_NE(scriptError("return blob{balls={{r=1, radius=2}}}").find("radius"), std::string::npos);
  EXPECT_NE(scriptError("return blob{balls={5}}").find("ball 1 must be a table"),
            std::string::npos);
}

// Seen from above, orthographic, a lone ball's silhouette is its circle.
TEST(BlobRender, ALoneBallsSilhouetteIsItsCircle) {
  Scene scene;
  scene.objects.push_back(blob({{{0, 0, 0}, 3.0, 1.0}}, 0.5));
  scene.camera = CameraSpec{dvec3(0, 0, 20), dvec3(0), dvec3(0, 1, 0), 45.0, true, 6.0};
  scene.background = dvec3(0.0);
  const int w = 200, h = 200;
  Image image = Renderer(scene, {w, h, 0}).render();
  Camera camera(*scene.camera, w, h);
  const double radius = loneRadius(3, 1, 0.5);
  int in = 0, out = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const dvec3 p = camera.ray(x + 0.5, y + 0.5).origin;
      const double d = std::hypot(p.x, p.y);
      if (std::abs(d - radius) < 0.02) continue;
      EXPECT_EQ(image.at(x, y) != dvec3(0.0), d < radius) << x << ", " << y;
      (d < radius ? in : out)++;
    }
  EXPECT_GT(in, 5000);
  EXPECT_GT(out, 5000);
}

}  // namespace
}  // namespace csgray::detail
