// The superellipsoid: hits along axes and diagonals where the implicit
// equation puts them, the ellipsoid it is at e = n = 1, spans against
// contains() and the first boundary against the whole spans over the range
// of exponents, normals against the equation's gradient, the volume of the
// closed form, its mesh, the script function and a silhouette in an image.
#include "primitives/superellipsoid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <random>
#include <string>
#include <vector>

#include "primitives/sphere.h"
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

std::shared_ptr<Superellipsoid> superellipsoid(dvec3 radii, double e, double n) {
  return Primitive::create<Superellipsoid>(radii, e, n);
}

// The implicit function of the surface as Barr writes it, straight from
// the definition: (|x/a|^(2/e) + |y/b|^(2/e))^(e/n) + |z/c|^(2/n).
double implicit(const dvec3& p, const dvec3& radii, double e, double n) {
  const double across =
      std::pow(std::abs(p.x / radii.x), 2.0 / e) + std::pow(std::abs(p.y / radii.y), 2.0 / e);
  return std::pow(across, e / n) + std::pow(std::abs(p.z / radii.z), 2.0 / n);
}

// The volume 2abc·e·n·B(e/2, e/2)·B(n/2 + 1, n) (Jaklič, Leonardis and
// Solina, "Segmentation and Recovery of Superquadrics", Springer 2000,
// §2.3.4, with their ε₂ = e across z and ε₁ = n along it).
double closedFormVolume(const dvec3& r, double e, double n) {
  return 2.0 * r.x * r.y * r.z * e * n * std::beta(e / 2.0, e / 2.0) * std::beta(n / 2.0 + 1.0, n);
}

const std::vector<std::pair<double, double>> kExponents = {
    {1.0, 1.0}, {0.5, 0.5},   {0.2, 1.0},   {1.0, 0.2}, {2.0, 2.0}, {2.0, 0.5},
    {0.5, 2.0}, {0.05, 0.05}, {1e-3, 1e-3}, {1.7, 0.3}, {1.0, 2.0}, {2.0, 1.0}};

TEST(SuperellipsoidPrimitive, HitsAlongTheAxesAtTheRadii) {
  const dvec3 r(2.0, 3.0, 0.5);
  for (auto [e, n] : kExponents) {
    auto s = superellipsoid(r, e, n);
    for (int axis = 0; axis < 3; ++axis) {
      dvec3 d(0.0);
      d[axis] = 1.0;
      SpanList spans = spansOf(*s, Ray(-10.0 * d, d));
      ASSERT_EQ(spans.size(), 1u) << e << " " << n;
      EXPECT_NEAR(spans[0].in.t, 10.0 - r[axis], 1e-12);
      EXPECT_NEAR(spans[0].out.t, 10.0 + r[axis], 1e-12);
    }
  }
}

// Along (1, 1, 0) the surface is where 2·x^(2/e) = 1; along (1, 0, 1)
// where 2·x^(2/n) = 1; along (1, 1, 1) where (2^(e/n) + 1)·x^(2/n) = 1.
TEST(SuperellipsoidPrimitive, HitsAlongTheDiagonalsWhereTheEquationSays) {
  for (auto [e, n] : kExponents) {
    SCOPED_TRACE(testing::Message() << "e " << e << " n " << n);
    auto s = superellipsoid(dvec3(1.0), e, n);
    const double xy = std::pow(0.5, e / 2.0), xz = std::pow(0.5, n / 2.0);
    const double xyz = std::pow(std::pow(2.0, e / n) + 1.0, -n / 2.0);
    for (auto [dir, x] :
         {std::pair{dvec3(1, 1, 0), xy}, {dvec3(1, 0, 1), xz}, {dvec3(1, 1, 1), xyz}}) {
      SpanList spans = spansOf(*s, Ray(dvec3(0.0), dir, -kInfinity, kInfinity));
      ASSERT_EQ(spans.size(), 1u);
      EXPECT_NEAR(spans[0].out.t, x, 1e-12 * std::max(1.0, 1.0 / x));
      EXPECT_NEAR(spans[0].in.t, -x, 1e-12 * std::max(1.0, 1.0 / x));
    }
  }
}

TEST(SuperellipsoidPrimitive, IsTheEllipsoidAtOneAndOne) {
  const dvec3 r(1.5, 0.7, 2.2);
  auto s = superellipsoid(r, 1.0, 1.0);
  auto ellipsoid = Primitive::create<Sphere>(1.0)->transformed(Affine::scaling(r));
  std::mt19937_64 rng(5);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    Ray line(randomPoint(rng, Bounds{-2.0 * r, 2.0 * r}), randomDirection(rng), -kInfinity,
             kInfinity);
    SpanList a = spansOf(*s, line), b = spansOf(*ellipsoid, line);
    ASSERT_EQ(a.size(), b.size()) << i;
    for (std::uint32_t k = 0; k < a.size(); ++k) {
      EXPECT_NEAR(a[k].in.t, b[k].in.t, 1e-9) << i;
      EXPECT_NEAR(a[k].out.t, b[k].out.t, 1e-9) << i;
    }
    hits += !a.empty();
  }
  EXPECT_GT(hits, 300);
}

TEST(SuperellipsoidPrimitive, BoundariesLieOnTheSurfaceAndAgreeWithContains) {
  const dvec3 r(2.0, 1.0, 1.5);
  for (auto [e, n] : kExponents) {
    SCOPED_TRACE(testing::Message() << "e " << e << " n " << n);
    auto s = superellipsoid(r, e, n);
    expectSpansAgreeWithContainsOnRandomLines(*s, 2000, 11);
    std::mt19937_64 rng(3);
    for (int i = 0; i < 500; ++i) {
      Ray line(randomPoint(rng, Bounds{-1.2 * r, 1.2 * r}), randomDirection(rng), -kInfinity,
               kInfinity);
      for (const Span& span : spansOf(*s, line))
        for (double t : {span.in.t, span.out.t}) {
          // F^n... written as the gauge: F = implicit^(n/2), off by ≈ the
          // distance over the radius; 1e-9 of it.
          const double gauge = std::pow(implicit(line.at(t), r, e, n), n / 2.0);
          EXPECT_NEAR(gauge, 1.0, 1e-9) << "t " << t;
        }
    }
  }
}

TEST(SuperellipsoidPrimitive, FirstBoundaryAgreesWithTheWholeSpans) {
  for (auto [e, n] : kExponents) {
    SCOPED_TRACE(testing::Message() << "e " << e << " n " << n);
    auto s = superellipsoid(dvec3(1.0, 2.0, 0.8), e, n);
    const test::FirstBoundaryCounts counts =
        expectFirstBoundaryAgreesWithTheWholeSpans(*s, 3000, 9);
    EXPECT_GT(counts.entries, 300);
    EXPECT_GT(counts.hits - counts.entries, 150);  // the octahedron fills a sixth of its box
  }
}

// The normal is the gradient of the implicit function (any positive
// multiple): compared with central differences of it, away from the
// creases at e or n = 2.
TEST(SuperellipsoidPrimitive, NormalsAreTheEquationsGradient) {
  const dvec3 r(2.0, 1.0, 1.5);
  for (auto [e, n] : kExponents) {
    SCOPED_TRACE(testing::Message() << "e " << e << " n " << n);
    auto s = superellipsoid(r, e, n);
    expectOutwardUnitNormals(*s, 1e-9, 500, 7);
    if (e < 0.1 || n < 0.1) continue;  // the differences see the rounding's curvature
    std::mt19937_64 rng(17);
    int compared = 0;
    for (int i = 0; i < 300; ++i) {
      Ray line(dvec3(0.0), randomDirection(rng), 0.0, kInfinity);
      SpanList spans = spansOf(*s, line);
      ASSERT_EQ(spans.size(), 1u);
      const dvec3 p = line.at(spans[0].out.t);
      if (std::min({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) < 0.05) continue;
      dvec3 g;
      const double h = 1e-6;
      for (int k = 0; k < 3; ++k) {
        dvec3 step(0.0);
        step[k] = h;
        g[k] = (implicit(p + step, r, e, n) - implicit(p - step, r, e, n)) / (2.0 * h);
      }
      const dvec3 normal = s->normal(p, 0);
      EXPECT_NEAR(glm::dot(normal, glm::normalize(g)), 1.0, 1e-6)
          << p.x << " " << p.y << " " << p.z;
      ++compared;
    }
    EXPECT_GT(compared, 100);
  }
}

TEST(SuperellipsoidPrimitive, VolumeByRaysIsTheClosedForm) {
  const dvec3 r(2.0, 1.5, 1.0);
  for (auto [e, n] : kExponents) {
    SCOPED_TRACE(testing::Message() << "e " << e << " n " << n);
    auto s = superellipsoid(r, e, n);
    const double want = closedFormVolume(r, e, n);
    const double got = test::gridVolume(*s, s->bounds(), 400);
    EXPECT_NEAR(got, want, 2e-3 * want);
  }
  // The limits: a box at small exponents, the octahedron at 2 and 2.
  EXPECT_NEAR(closedFormVolume(dvec3(1.0), 1e-3, 1e-3), 8.0, 0.03);
  EXPECT_NEAR(closedFormVolume(dvec3(1.0), 2.0, 2.0), 4.0 / 3.0, 1e-12);
}

TEST(SuperellipsoidPrimitive, FarAwayRaysStillHit) {
  auto s = superellipsoid(dvec3(1.0, 2.0, 3.0), 0.3, 0.6);
  const dvec3 dir = glm::normalize(dvec3(-1.0, -0.3, -0.2));
  const dvec3 from = -1e6 * dir;
  SpanList spans = spansOf(*s, Ray(from, dir));
  ASSERT_EQ(spans.size(), 1u);
  for (double t : {spans[0].in.t, spans[0].out.t})
    EXPECT_NEAR(std::pow(implicit(from + t * dir, s->radii(), 0.3, 0.6), 0.3), 1.0, 1e-8);
}

TEST(SuperellipsoidPrimitive, MissesAndGrazes) {
  auto s = superellipsoid(dvec3(1.0), 0.5, 0.5);
  // Past the rounded corner of the section z = 0: the surface is at
  // x = y = 2^(−1/4) ≈ 0.8409 along the diagonal; a line x + y = 2·0.85
  // misses, x + y = 2·0.83 crosses.
  for (auto [offset, meets] : {std::pair{0.85, false}, {0.83, true}}) {
    SpanList spans = spansOf(
        *s, Ray(dvec3(offset, offset, 0.0) + dvec3(-5, 5, 0), glm::normalize(dvec3(1, -1, 0))));
    EXPECT_EQ(spans.empty(), !meets) << offset;
  }
  // Along a face of the bounding cube: touches at its centre only, where
  // the gauge is 1 + y⁴/4, within rounding of 1 for |y| up to about 10⁻⁴:
  // a span there, if any, lies on the surface to rounding.
  SpanList along = spansOf(*s, Ray(dvec3(1.0, -5.0, 0.0), dvec3(0, 1, 0)));
  for (const Span& span : along) {
    EXPECT_LT(span.length(), 1e-3);
    for (double y : {span.in.t - 5.0, span.out.t - 5.0})
      EXPECT_NEAR(implicit(dvec3(1.0, y, 0.0), dvec3(1.0), 0.5, 0.5), 1.0, 1e-14);
  }
  EXPECT_TRUE(spansOf(*s, Ray(dvec3(1.0 + 1e-9, -5.0, 0.0), dvec3(0, 1, 0))).empty());
}

TEST(SuperellipsoidPrimitive, RefusesBadParameters) {
  EXPECT_THROW(superellipsoid(dvec3(1.0), 2.5, 1.0), std::invalid_argument);
  EXPECT_THROW(superellipsoid(dvec3(1.0), 1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(superellipsoid(dvec3(1.0), 1.0, 1e-4), std::invalid_argument);
  EXPECT_THROW(superellipsoid(dvec3(1.0, -1.0, 1.0), 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(superellipsoid(dvec3(1.0), std::nan(""), 1.0), std::invalid_argument);
}

// Closed, outward, within the tolerance of the surface (sampled inside
// every triangle, measured along the ray from the centre, an upper bound),
// and its volume within tolerance × area of the closed form.
TEST(SuperellipsoidTessellation, ClosedOutwardAndWithinTolerance) {
  const dvec3 r(2.0, 1.5, 1.0);
  for (auto [e, n] : kExponents) {
    for (double tolerance : {0.02, 0.002}) {
      SCOPED_TRACE(testing::Message() << "e " << e << " n " << n << " tolerance " << tolerance);
      auto s = superellipsoid(r, e, n);
      TriangleMesh mesh = s->tessellate(tolerance, Bounds::everything());
      test::expectClosedMesh(mesh);
      const double area = 8.0 * (r.x * r.y + r.y * r.z + r.z * r.x);  // the box's: more
      const double want = closedFormVolume(r, e, n);
      EXPECT_NEAR(mesh.volume(), want, tolerance * area);
      EXPECT_LE(mesh.volume(), want * (1.0 + 1e-12)) << "its points are on the convex surface";
      double worst = 0.0;
      for (const auto& t : mesh.triangles) {
        const dvec3 &a = mesh.points[t[0]], &b = mesh.points[t[1]], &c = mesh.points[t[2]];
        for (int i = 0; i <= 6; ++i)
          for (int j = 0; i + j <= 6; ++j) {
            const dvec3 p = a + (b - a) * (i / 6.0) + (c - a) * (j / 6.0);
            const double f = s->unitGauge(p / r).value;
            worst = std::max(worst, glm::length(p) * (1.0 / f - 1.0));
          }
      }
      EXPECT_LE(worst, tolerance);
      EXPECT_LT(mesh.size(), 400000u);
    }
  }
}

TEST(SuperellipsoidScript, MakesOneAndNamesItsMistakes) {
  SolidPtr s = test::solidOf("return superellipsoid{radii={2, 3, 1}, e=0.5, n=0.25}");
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->kind(), "superellipsoid");
  EXPECT_NEAR(test::gridVolume(*s, s->bounds(), 300), closedFormVolume(dvec3(2, 3, 1), 0.5, 0.25),
              0.01);
  EXPECT_TRUE(
      test::solidOf("return superellipsoid{radii=2, e=1, n=1}")->contains(dvec3(1.9, 0, 0)));
  EXPECT_NE(scriptError("return superellipsoid{radii=1, e=3, n=1}").find("pinches"),
            std::string::npos);
  EXPECT_NE(scriptError("return superellipsoid{radii=1, e=1}").find("needs e and n"),
            std::string::npos);
  EXPECT_NE(scriptError("return superellipsoid{e=1, n=1}").find("needs radii"), std::string::npos);
  EXPECT_NE(
      scriptError("return superellipsoid{0.5, 0.5}").find("superellipsoid{radii=1, e=..., n=...}"),
      std::string::npos);
  EXPECT_NE(scriptError("return superellipsoid{radii=1, e=1, n=1, exponents=2}").find("exponents"),
            std::string::npos);
}

// Seen from above, orthographic, the silhouette is the section at z = 0:
// |x/a|^(2/e) + |y/b|^(2/e) <= 1. Every pixel whose centre is clearly in
// or out is checked.
TEST(SuperellipsoidRender, SilhouetteFromAboveIsTheSection) {
  const dvec3 r(3.0, 2.0, 1.0);
  const double e = 0.4;
  Scene scene;
  scene.objects.push_back(superellipsoid(r, e, 0.7));
  scene.camera = CameraSpec{dvec3(0, 0, 20), dvec3(0), dvec3(0, 1, 0), 45.0, true, 8.0};
  scene.background = dvec3(0.0);
  const int w = 200, h = 200;
  Image image = Renderer(scene, {w, h, 0}).render();
  Camera camera(*scene.camera, w, h);
  int in = 0, out = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const dvec3 p = camera.ray(x + 0.5, y + 0.5).origin;
      const double f =
          std::pow(std::abs(p.x / r.x), 2.0 / e) + std::pow(std::abs(p.y / r.y), 2.0 / e);
      if (std::abs(f - 1.0) < 0.02) continue;
      const bool shown = image.at(x, y) != dvec3(0.0);
      EXPECT_EQ(shown, f < 1.0) << x << ", " << y;
      (f < 1.0 ? in : out)++;
    }
  EXPECT_GT(in, 5000);
  EXPECT_GT(out, 5000);
}

}  // namespace
}  // namespace csgray::detail
