// Bézier edges in profiles and their extrusions: exact areas by Green's
// theorem, even-odd containment, rays that meet an extruded parabola or
// cubic where the curve's polynomial vanishes, outward normals from the
// tangent, volumes, valid meshes, and an edge-on view whose rays graze
// the parabola's apex with no pixel lost.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <tuple>

#include "meshio/outline_writer.h"
#include "primitives/linear_extrusion.h"
#include "primitives/revolution.h"
#include "primitives/sweep_checks.h"
#include "primitives/sweep_shapes.h"
#include "profile/bezier.h"
#include "profile/region_evaluation.h"
#include "raytrace/renderer.h"
#include "scene/camera.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

// The parabolic cap 0 <= y <= 1 − x²: the quadratic from (−1, 0) pulled
// towards (0, 2) to (1, 0) is x = 2s − 1, y = 4s(1 − s) = 1 − x²; its area
// is 4/3.
Profile parabolicCap() {
  Profile p;
  p.loops.push_back(ProfileLoop{
      {ProfileEdge::quadratic({-1, 0}, {0, 2}, {1, 0}), ProfileEdge::segment({1, 0}, {-1, 0})}});
  return p;
}

// Under the cubic from (0, 0) via (0, 1) and (1, 1) to (1, 0): x = 3s² − 2s³,
// y = 3s(1 − s); its area ∫ y dx = 18 ∫ s²(1 − s)² ds = 0.6.
Profile cubicCap() {
  Profile p;
  p.loops.push_back(ProfileLoop{
      {ProfileEdge::cubic({0, 0}, {0, 1}, {1, 1}, {1, 0}), ProfileEdge::segment({1, 0}, {0, 0})}});
  return p;
}

std::shared_ptr<LinearExtrusion> extrude(const Profile& p, double h, double twist = 0.0) {
  return Primitive::create<LinearExtrusion>(Region::leaf(p), h, false, twist, dvec2(1.0));
}

TEST(BezierProfile, AreasAreExact) {
  // Both caps run clockwise (over the top from left to right).
  EXPECT_NEAR(area(parabolicCap()), -4.0 / 3.0, 1e-15);
  EXPECT_NEAR(area(cubicCap()), -0.6, 1e-15);
  // Evaluated (flattened within the tolerance, counterclockwise): the
  // polygon is inscribed.
  const double flat = area(evaluate(*Region::leaf(parabolicCap()), 1e-6));
  EXPECT_LT(flat, 4.0 / 3.0);
  EXPECT_GT(flat, 4.0 / 3.0 - 2.0 * 1e-6 * 2.0);
}

TEST(BezierProfile, BoundsReachTheCurveNotItsControlPoints) {
  const ProfileBounds b = parabolicCap().bounds();
  EXPECT_NEAR(b.hi.y, 1.0, 1e-15);
  EXPECT_EQ(b.lo, dvec2(-1, 0));
  const ProfileBounds c = cubicCap().bounds();
  EXPECT_NEAR(c.hi.y, 0.75, 1e-15);
}

TEST(BezierProfile, ContainsIsUnderTheCurve) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> x(-1.2, 1.2), y(-0.2, 1.2), s(0.0, 1.0);
  const Profile p = parabolicCap();
  for (int i = 0; i < 20000; ++i) {
    const dvec2 u(x(rng), y(rng));
    const double top = 1.0 - u.x * u.x;
    if (std::abs(u.y - top) < 1e-12 || std::abs(u.y) < 1e-12) continue;
    ASSERT_EQ(p.contains(u), u.y > 0.0 && u.y < top) << u.x << " " << u.y;
  }
  // The cubic: inside below the curve's height at that x.
  const Profile c = cubicCap();
  for (int i = 0; i < 2000; ++i) {
    const double q = s(rng), px = 3 * q * q - 2 * q * q * q, py = 3 * q * (1 - q);
    EXPECT_TRUE(c.contains({px, 0.999 * py}));
    EXPECT_FALSE(c.contains({px, 1.001 * py + 1e-9}));
  }
  // A point level with an end: the end counts once.
  EXPECT_TRUE(p.contains({0.0, 0.5}));
  EXPECT_FALSE(p.contains({-2.0, 0.0}) && p.contains({2.0, 0.0}));
}

TEST(BezierExtrusion, RaysMeetTheParabolaWhereItsQuadraticVanishes) {
  auto cap = extrude(parabolicCap(), 2.0);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> height(0.05, 0.95), slope(-0.4, 0.4), z(0.1, 1.9);
  for (int i = 0; i < 200; ++i) {
    // The line y = y0 + m·τ, x = −3 + τ in the plane z = z0 meets y = 1 − x²
    // where (−3 + τ)² + m·τ + y0 − 1 = 0.
    const double y0 = height(rng), m = slope(rng), z0 = z(rng);
    const double b = m - 6.0, c = 9.0 + y0 - 1.0, disc = b * b - 4 * c;
    if (disc <= 0) continue;
    const double tau0 = (-b - std::sqrt(disc)) / 2, tau1 = (-b + std::sqrt(disc)) / 2;
    if (y0 + m * tau0 < 1e-3) continue;  // it would pass below the cap
    const dvec3 dir = glm::normalize(dvec3(1, m, 0));
    const double speed = glm::length(dvec3(1, m, 0));
    SpanList spans = test::spansOf(*cap, Ray(dvec3(-3, y0, z0), dir));
    // Out through the chord y = 0 when the line leaves the cap downwards.
    ASSERT_EQ(spans.size(), 1u);
    EXPECT_NEAR(spans[0].in.t, tau0 * speed, 1e-9);
    const double down = -y0 / m;  // where it crosses y = 0
    const double out = m < 0 && down < tau1 ? down : tau1;
    EXPECT_NEAR(spans[0].out.t, out * speed, 1e-9);
    // The normal: the gradient of y + x² − 1, outward.
    const dvec3 p = dvec3(-3, y0, z0) + spans[0].in.t * dir;
    test::expectVecNear(cap->normal(p, spans[0].in.face), glm::normalize(dvec3(2 * p.x, 1, 0)),
                        1e-9);
  }
}

TEST(BezierExtrusion, RaysMeetTheCubicWhereItsCubicVanishes) {
  auto cap = extrude(cubicCap(), 1.0);
  // Along +x at height y: 3s(1 − s) = y, s = (3 ∓ √(9 − 12y))/6.
  for (double y : {0.1, 0.3, 0.5, 0.7, 0.74}) {
    const double r = std::sqrt(9 - 12 * y);
    const double s0 = (3 - r) / 6, s1 = (3 + r) / 6;
    const auto xOf = [](double s) { return 3 * s * s - 2 * s * s * s; };
    SpanList spans = test::spansOf(*cap, Ray(dvec3(-1, y, 0.5), dvec3(1, 0, 0)));
    ASSERT_EQ(spans.size(), 1u) << y;
    EXPECT_NEAR(spans[0].in.t, 1 + xOf(s0), 1e-9);
    EXPECT_NEAR(spans[0].out.t, 1 + xOf(s1), 1e-9);
  }
  // Above the top (y = 3/4): nothing.
  EXPECT_TRUE(test::spansOf(*cap, Ray(dvec3(-1, 0.7501, 0.5), dvec3(1, 0, 0))).empty());
}

TEST(BezierExtrusion, VolumesSpansAndNormals) {
  const double h = 1.5;
  for (const auto& [name, profile, exact] :
       {std::tuple{"parabola", parabolicCap(), 4.0 / 3.0}, std::tuple{"cubic", cubicCap(), 0.6}}) {
    SCOPED_TRACE(name);
    auto solid = extrude(profile, h);
    test::expectVolume(solid, exact * h);
    test::expectValidMesh(*solid, 1e-3, exact * h);
    test::expectSpansAgreeWithContainsOnRandomLines(*solid, 2000, 11);
    test::expectOutwardUnitNormals(*solid, 1e-9, 500, 13);
    // Twisted, the curves are polygons within 10⁻⁶ of the size.
    auto twisted = extrude(profile, h, 90.0);
    test::expectVolume(twisted, exact * h);
    test::expectSpansAgreeWithContainsOnRandomLines(*twisted, 500, 17);
  }
  // A revolution of the cubic cap moved off the axis: Pappus, V = 2π·x̄·A.
  Profile moved = cubicCap().transformed(Affine2{dmat2(1.0), dvec2(2.0, 0.0)});
  auto turned = Primitive::create<Revolution>(Region::leaf(moved), 360.0);
  // x̄ of the cap: 2 + 1/2 by its symmetry about x = 1/2.
  test::expectVolume(turned, 2 * std::numbers::pi * 2.5 * 0.6);
}

// Rays along x graze the parabola's apex (y = 1) tangentially: every pixel
// below it is solid, every one above empty.
TEST(BezierExtrusionRender, GrazingTheApexLosesNoPixel) {
  auto cap = extrude(parabolicCap(), 2.0);
  Scene scene;
  scene.objects.push_back(cap);
  // Looking along +x, orthographic, 2.4 wide: y across, z up.
  scene.camera = CameraSpec{dvec3(-10, 0.5, 1), dvec3(0, 0.5, 1), dvec3(0, 0, 1), 45.0, true, 2.4};
  scene.background = dvec3(0.0);
  const int w = 240, hgt = 240;
  Image image = Renderer(scene, {w, hgt, 1}).render();
  Camera camera(*scene.camera, w, hgt);
  int hits = 0, wrong = 0;
  for (int row = 0; row < hgt; ++row)
    for (int col = 0; col < w; ++col) {
      const Ray ray = camera.ray(col + 0.5, row + 0.5);
      const double y = ray.origin.y, z = ray.origin.z;
      if (std::abs(y - 1) < 1e-9 || std::abs(y) < 1e-9 || std::abs(z) < 1e-9 ||
          std::abs(z - 2) < 1e-9)
        continue;
      const bool hit = y > 0 && y < 1 && z > 0 && z < 2;
      hits += hit;
      if (hit != (image.at(col, row) != dvec3(0.0)) && ++wrong <= 5)
        ADD_FAILURE() << "y = " << y << ", z = " << z << ": " << (hit ? "missed" : "extra");
    }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(hits, 10000);
}

TEST(BezierOutline, SvgKeepsTheCurves) {
  Profile both = parabolicCap();
  both.loops.push_back(cubicCap().loops[0]);
  const std::string svg = svgOutline(both);
  EXPECT_NE(svg.find(" Q 0 -2 1 0"), std::string::npos) << svg;
  EXPECT_NE(svg.find(" C 0 -1 1 -1 1 0"), std::string::npos) << svg;
  const std::string dxf = dxfOutline(both, 1e-3);
  int lines = 0;
  for (std::size_t at = dxf.find("LINE"); at != std::string::npos; at = dxf.find("LINE", at + 1))
    ++lines;
  EXPECT_GT(lines, 20);  // the curves as polygons, and the two chords
}

}  // namespace
}  // namespace csgray::detail
