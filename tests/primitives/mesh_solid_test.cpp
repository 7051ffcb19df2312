// polyhedron: closed triangle meshes from points and faces. Analytic ray
// hits on a cube, a tetrahedron and an octahedron, spans equal to those of
// box{} and of the analytic solids on random lines and on lines exactly
// through vertices and edges (watertightness), contains() against spans,
// volumes, a 20 000-triangle sphere, no allocation per ray, and every
// refusal, in C++ and through the script API.
#include "primitives/mesh_solid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <glm/geometric.hpp>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "allocation_counter.h"
#include "engine/boolean.h"
#include "primitives/box.h"
#include "primitives/sphere.h"
#include "primitives/triangle_crossing.h"
#include "script/script.h"
#include "tessellation/polygon_triangulation.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

using test::expectAgreementOnLinesThrough;
using test::expectOutwardUnitNormals;
using test::expectSpansAgreeWithContains;
using test::expectSpansAgreeWithContainsOnRandomLines;
using test::expectVecNear;
using test::randomDirection;
using test::scriptError;
using test::spansOf;

constexpr double kPi = std::numbers::pi;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using Faces = std::vector<std::vector<std::int64_t>>;

struct MeshSpec {
  std::vector<dvec3> points;
  Faces faces;
};

std::shared_ptr<MeshSolid> meshOf(const MeshSpec& m) {
  return Primitive::create<MeshSolid>(m.points, m.faces);
}

// The message a mesh is refused with, or "(accepted)".
std::string refusal(const MeshSpec& m) {
  try {
    MeshSolid mesh(m.points, m.faces);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(accepted)";
}

// OpenSCAD's own example (the polyhedron page of its manual): a 10 × 7 × 5
// cube with quadrilateral faces, clockwise seen from outside.
MeshSpec openScadCube() {
  return {
      {{0, 0, 0}, {10, 0, 0}, {10, 7, 0}, {0, 7, 0}, {0, 0, 5}, {10, 0, 5}, {10, 7, 5}, {0, 7, 5}},
      {{0, 1, 2, 3}, {4, 5, 1, 0}, {7, 6, 5, 4}, {5, 6, 2, 1}, {6, 7, 3, 2}, {7, 4, 0, 3}}};
}

// The same cube of size s, each face cut into two triangles along a
// diagonal, so that rays can go exactly through shared edges.
MeshSpec triangulatedCube(const dvec3& s, const dvec3& at = dvec3(0.0)) {
  MeshSpec quads = openScadCube();
  MeshSpec m;
  for (const dvec3& p : quads.points) m.points.push_back(at + p / dvec3(10, 7, 5) * s);
  for (const auto& f : quads.faces) {
    m.faces.push_back({f[0], f[1], f[2]});
    m.faces.push_back({f[0], f[2], f[3]});
  }
  return m;
}

// Faces of a convex solid turned to run clockwise seen from outside (the
// centroid of the points is inside).
Faces clockwise(const std::vector<dvec3>& points, Faces faces) {
  dvec3 c(0.0);
  for (const dvec3& p : points) c += p / double(points.size());
  for (auto& f : faces) {
    const dvec3 &a = points[f[0]], &b = points[f[1]], &d = points[f[2]];
    if (glm::dot(glm::cross(b - a, d - a), a - c) > 0.0) std::reverse(f.begin(), f.end());
  }
  return faces;
}

MeshSpec tetrahedron(double s) {
  std::vector<dvec3> p = {{0, 0, 0}, {s, 0, 0}, {0, s, 0}, {0, 0, s}};
  return {p, clockwise(p, {{0, 1, 2}, {0, 1, 3}, {1, 2, 3}, {0, 2, 3}})};
}

// |x| + |y| + |z| <= a.
MeshSpec octahedron(double a) {
  std::vector<dvec3> p = {{a, 0, 0}, {-a, 0, 0}, {0, a, 0}, {0, -a, 0}, {0, 0, a}, {0, 0, -a}};
  Faces f;
  for (int x : {0, 1})
    for (int y : {2, 3})
      for (int z : {4, 5}) f.push_back({x, y, z});
  return {p, clockwise(p, f)};
}

// A UV sphere inscribed in the ball of radius r: triangle fans at the poles,
// quadrilaterals between the rings (split into two triangles each).
MeshSpec uvSphere(double r, int rings, int segments) {
  MeshSpec m;
  m.points.push_back({0, 0, r});
  for (int i = 1; i < rings; ++i) {
    double theta = kPi * i / rings;
    for (int j = 0; j < segments; ++j) {
      double phi = 2 * kPi * j / segments;
      m.points.push_back({r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi),
                          r * std::cos(theta)});
    }
  }
  std::int64_t south = std::int64_t(m.points.size());
  m.points.push_back({0, 0, -r});
  auto at = [&](int i, int j) { return std::int64_t(1 + (i - 1) * segments + j % segments); };
  for (int j = 0; j < segments; ++j) m.faces.push_back({0, at(1, j), at(1, j + 1)});
  for (int i = 1; i + 1 < rings; ++i)
    for (int j = 0; j < segments; ++j)
      m.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
  for (int j = 0; j < segments; ++j)
    m.faces.push_back({south, at(rings - 1, j + 1), at(rings - 1, j)});
  m.faces = clockwise(m.points, m.faces);
  return m;
}

// a with b's points and faces added; b's faces reversed if inverted.
MeshSpec combined(MeshSpec a, const MeshSpec& b, bool inverted) {
  std::int64_t offset = std::int64_t(a.points.size());
  a.points.insert(a.points.end(), b.points.begin(), b.points.end());
  for (auto f : b.faces) {
    for (auto& i : f) i += offset;
    if (inverted) std::reverse(f.begin(), f.end());
    a.faces.push_back(f);
  }
  return a;
}

MeshSpec reversed(MeshSpec m) {
  for (auto& f : m.faces) std::reverse(f.begin(), f.end());
  return m;
}

// Spans of positive length as (in, out) pairs: a line that only touches a
// corner gives box{} a span of length 0 and the mesh none.
std::vector<std::pair<double, double>> properSpans(const Solid& s, const Ray& ray) {
  std::vector<std::pair<double, double>> out;
  for (const Span& span : spansOf(s, ray))
    if (span.length() > 1e-9) out.push_back({span.in.t, span.out.t});
  return out;
}

void expectSameSpans(const Solid& actual, const Solid& expected, const Ray& ray, double tol) {
  SpanList raw = spansOf(actual, ray);
  ASSERT_TRUE(raw.valid());
  auto a = properSpans(actual, ray), e = properSpans(expected, ray);
  ASSERT_EQ(a.size(), e.size()) << "origin (" << ray.origin.x << ", " << ray.origin.y << ", "
                                << ray.origin.z << ") dir (" << ray.dir.x << ", " << ray.dir.y
                                << ", " << ray.dir.z << ")";
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR(a[i].first, e[i].first, tol);
    EXPECT_NEAR(a[i].second, e[i].second, tol);
  }
}

// Volume by spans along z, x and y (as in volume_test.cpp).
void expectGridVolume(const SolidPtr& s, double exact, int grid = 300) {
  SolidPtr alongX = s->transformed(Affine::rotation(kPi / 2, dvec3(0, 1, 0)));
  SolidPtr alongY = s->transformed(Affine::rotation(kPi / 2, dvec3(1, 0, 0)));
  EXPECT_NEAR(test::gridVolume(*s, s->bounds(), grid), exact, 0.005 * exact) << "along z";
  EXPECT_NEAR(test::gridVolume(*alongX, alongX->bounds(), grid), exact, 0.005 * exact) << "along x";
  EXPECT_NEAR(test::gridVolume(*alongY, alongY->bounds(), grid), exact, 0.005 * exact) << "along y";
}

// ---------------------------------------------------------------- hits

// Faces to triangles: random star-shaped polygons (simple, with many
// reflex corners) in random planes become n − 2 triangles that all turn
// the polygon's way and together cover its area exactly once.
TEST(PolygonTriangulation, StarShapedPolygonsAreCoveredByTrianglesOfTheirOrientation) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> radius(0.2, 3.0);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 3 + trial % 150;
    // The plane (e1, e2), seen from normal = e1 × e2.
    const dvec3 normal = randomDirection(rng);
    const dvec3 e1 = glm::normalize(glm::cross(normal, randomDirection(rng)));
    const dvec3 e2 = glm::cross(normal, e1);
    // Corners at increasing angles, counter-clockwise about the normal; the
    // points are listed in reverse and from index 7, so that the polygon's
    // indices are neither 0 .. n − 1 nor in order.
    std::vector<dvec3> points(7 + n);
    std::vector<std::uint32_t> polygon;
    std::vector<glm::dvec2> flat;
    for (int i = 0; i < n; ++i) {
      const double a = 2.0 * kPi * i / n, r = radius(rng);
      flat.emplace_back(r * std::cos(a), r * std::sin(a));
      polygon.push_back(std::uint32_t(7 + n - 1 - i));
      points[polygon.back()] = dvec3(5, -2, 1) + flat.back().x * e1 + flat.back().y * e2;
    }
    double area = 0.0;  // the shoelace formula in the plane
    for (int i = 0; i < n; ++i)
      area += 0.5 * (flat[i].x * flat[(i + 1) % n].y - flat[(i + 1) % n].x * flat[i].y);
    int triangles = 0;
    double covered = 0.0;
    ASSERT_TRUE(
        triangulatePolygon(points, polygon, [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
          ++triangles;
          const double signedArea =
              0.5 * glm::dot(glm::cross(points[b] - points[a], points[c] - points[a]), normal);
          EXPECT_GT(signedArea, 0.0) << "trial " << trial;
          covered += signedArea;
        }));
    EXPECT_EQ(triangles, n - 2) << "trial " << trial;
    EXPECT_NEAR(covered, area, 1e-12 * n) << "trial " << trial;
  }
  // Collinear corners span no plane.
  std::vector<dvec3> line{dvec3(0), dvec3(1, 0, 0), dvec3(2, 0, 0), dvec3(3, 0, 0)};
  std::vector<std::uint32_t> corners{0, 1, 2, 3};
  EXPECT_FALSE(triangulatePolygon(line, corners, [](auto, auto, auto) { FAIL(); }));
}

// Ear clipping costs O(n²·r) at worst, so a non-convex polygon of more than
// kMaxEarClippedCorners is cut as a strip, in time linear in its corners:
// all n − 2 triangles, each joining a corner from one end to an edge at the
// other.
TEST(PolygonTriangulation, APolygonTooLargeToEarClipIsCutAsAStrip) {
  const std::size_t n = kMaxEarClippedCorners + 2;
  std::vector<dvec3> points;
  std::vector<std::uint32_t> polygon;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2 * kPi * double(i) / double(n), r = i % 2 ? 0.5 : 1.0;
    points.push_back(dvec3(r * std::cos(a), r * std::sin(a), 0.0));
    polygon.push_back(std::uint32_t(i));
  }
  std::vector<std::array<std::uint32_t, 3>> triangles;
  ASSERT_TRUE(
      triangulatePolygon(points, polygon, [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        triangles.push_back({a, b, c});
      }));
  ASSERT_EQ(triangles.size(), n - 2);
  // The strip's start: the first corner's edge, then the last one's, in turn.
  const std::uint32_t last = std::uint32_t(n - 1);
  EXPECT_EQ(triangles[0], (std::array<std::uint32_t, 3>{0, 1, last}));
  EXPECT_EQ(triangles[1], (std::array<std::uint32_t, 3>{1, last - 1, last}));
  EXPECT_EQ(triangles[2], (std::array<std::uint32_t, 3>{1, 2, last - 1}));
}

// A convex cap (a 2 000-sided circle) becomes triangles that lie side by
// side: each one's box overlaps a few others', where a fan's triangles all
// meet at one corner and every box overlaps every other (n²/2 pairs), which
// made mesh checks and BVHs over such caps slow.
TEST(PolygonTriangulation, AConvexCapBecomesTrianglesSideBySide) {
  const int n = 2000;
  std::vector<dvec3> points;
  std::vector<std::uint32_t> polygon;
  for (int i = 0; i < n; ++i) {
    points.push_back(dvec3(std::cos(2 * kPi * i / n), std::sin(2 * kPi * i / n), 0.0));
    polygon.push_back(std::uint32_t(i));
  }
  std::vector<Bounds> boxes;
  ASSERT_TRUE(
      triangulatePolygon(points, polygon, [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        Bounds box;
        for (std::uint32_t k : {a, b, c}) box.include(points[k]);
        boxes.push_back(box);
      }));
  ASSERT_EQ(boxes.size(), std::size_t(n - 2));
  std::size_t overlapping = 0;  // pairs whose boxes share some area
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j)
      overlapping += boxes[i].lo.x < boxes[j].hi.x && boxes[j].lo.x < boxes[i].hi.x &&
                     boxes[i].lo.y < boxes[j].hi.y && boxes[j].lo.y < boxes[i].hi.y;
  EXPECT_LT(overlapping, std::size_t(4 * n));
}

TEST(MeshSolid, OpenScadCubeAnalyticHits) {
  auto cube = meshOf(openScadCube());
  EXPECT_EQ(cube->kind(), "polyhedron");
  EXPECT_FALSE(cube->turned());
  EXPECT_EQ(cube->triangles().size(), 12u);
  EXPECT_NEAR(cube->volume(), 350.0, 1e-9);
  expectVecNear(cube->bounds().lo, dvec3(0, 0, 0), 0);
  expectVecNear(cube->bounds().hi, dvec3(10, 7, 5), 0);

  // Along +x through the middle: in at x = 0, out at x = 10.
  Ray ray(dvec3(-1, 3.5, 2.5), dvec3(1, 0, 0));
  SpanList spans = spansOf(*cube, ray);
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_DOUBLE_EQ(spans[0].in.t, 1.0);
  EXPECT_DOUBLE_EQ(spans[0].out.t, 11.0);
  expectVecNear(cube->normal(ray.at(1.0), int(spans[0].in.face)), dvec3(-1, 0, 0), 1e-15);
  expectVecNear(cube->normal(ray.at(11.0), int(spans[0].out.face)), dvec3(1, 0, 0), 1e-15);
  // The triangle that was hit came from the face x = 0 (face 5 of the input).
  EXPECT_EQ(cube->faceOf(spans[0].in.face), 5u);

  // Down along −z with a slanted direction of length 2: t in units of it.
  Ray down(dvec3(2, 3, 9), dvec3(0.5, 0, -2) / 1.0);
  spans = spansOf(*cube, down);
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_NEAR(spans[0].in.t, 2.0, 1e-15);
  EXPECT_NEAR(spans[0].out.t, 4.5, 1e-15);

  // tMin/tMax: spans are exact within the window. One that began before
  // it is reported from −∞ (no surface there), as for an unbounded solid.
  Ray window(dvec3(-1, 3.5, 2.5), dvec3(1, 0, 0), 5.0, 6.0);
  spans = spansOf(*cube, window);
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_EQ(spans[0].in.t, -kInfinity);
  EXPECT_EQ(spans[0].in.primitive, nullptr);
  EXPECT_DOUBLE_EQ(spans[0].out.t, 11.0);
  spans = spansOf(*cube, Ray(dvec3(-1, 3.5, 2.5), dvec3(1, 0, 0), 0.5, 6.0));
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_DOUBLE_EQ(spans[0].in.t, 1.0);
  EXPECT_DOUBLE_EQ(spans[0].out.t, 11.0);
  EXPECT_TRUE(spansOf(*cube, Ray(dvec3(-1, 3.5, 2.5), dvec3(1, 0, 0), 12.0, 20.0)).empty());
  EXPECT_TRUE(spansOf(*cube, Ray(dvec3(-1, 20, 2.5), dvec3(1, 0, 0))).empty());

  EXPECT_TRUE(cube->contains(dvec3(5, 3.5, 2.5)));
  EXPECT_TRUE(cube->contains(dvec3(9.999, 6.999, 4.999)));
  EXPECT_FALSE(cube->contains(dvec3(10.001, 3, 2)));
  EXPECT_FALSE(cube->contains(dvec3(-5, -5, -5)));
  // Rays without a usable direction or origin meet nothing.
  EXPECT_TRUE(spansOf(*cube, Ray(dvec3(5, 3, 2), dvec3(kNaN, 0, 1))).empty());
  EXPECT_TRUE(spansOf(*cube, Ray(dvec3(kNaN, 3, 2), dvec3(1, 0, 0))).empty());
  EXPECT_TRUE(spansOf(*cube, Ray(dvec3(5, 3, 2), dvec3(0.0))).empty());
  EXPECT_FALSE(cube->contains(dvec3(kNaN, 3, 2)));
}

// The pyramid of docs/script.md is listed clockwise, as the text says.
TEST(MeshSolid, DocumentedPyramid) {
  auto pyramid = meshOf({{{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}, {5, 5, 8}},
                         {{0, 4, 1}, {1, 4, 2}, {2, 4, 3}, {3, 4, 0}, {0, 1, 2, 3}}});
  EXPECT_FALSE(pyramid->turned());
  EXPECT_NEAR(pyramid->volume(), 100.0 * 8.0 / 3.0, 1e-9);
}

// Counter-clockwise faces (STL's convention) describe the same cube: the
// mesh is turned, with the same spans and outward normals.
TEST(MeshSolid, InsideOutMeshIsTurned) {
  auto cube = meshOf(reversed(openScadCube()));
  EXPECT_TRUE(cube->turned());
  EXPECT_NEAR(cube->volume(), 350.0, 1e-9);
  Ray ray(dvec3(-1, 3.5, 2.5), dvec3(1, 0, 0));
  SpanList spans = spansOf(*cube, ray);
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_DOUBLE_EQ(spans[0].in.t, 1.0);
  EXPECT_DOUBLE_EQ(spans[0].out.t, 11.0);
  expectVecNear(cube->normal(ray.at(1.0), int(spans[0].in.face)), dvec3(-1, 0, 0), 1e-15);
  expectOutwardUnitNormals(*cube, 1e-12);
}

TEST(MeshSolid, TetrahedronAndOctahedronHits) {
  auto tetra = meshOf(tetrahedron(3));
  EXPECT_NEAR(tetra->volume(), 27.0 / 6.0, 1e-12);
  // Along the diagonal through the origin vertex: out at x + y + z = 3.
  Ray diagonal(dvec3(-1, -1, -1), dvec3(1, 1, 1));
  SpanList spans = spansOf(*tetra, diagonal);
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_NEAR(spans[0].in.t, 1.0, 1e-15);
  EXPECT_NEAR(spans[0].out.t, 2.0, 1e-15);
  expectVecNear(tetra->normal(diagonal.at(2.0), int(spans[0].out.face)),
                glm::normalize(dvec3(1, 1, 1)), 1e-15);

  auto octa = meshOf(octahedron(2));
  EXPECT_NEAR(octa->volume(), 4.0 / 3.0 * 8.0, 1e-12);
  // Along z exactly through both apexes, where four faces meet.
  spans = spansOf(*octa, Ray(dvec3(0, 0, -5), dvec3(0, 0, 1)));
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_DOUBLE_EQ(spans[0].in.t, 3.0);
  EXPECT_DOUBLE_EQ(spans[0].out.t, 7.0);
  // Through the middle of edges: along x at y = 1, z = 0 crosses the edges
  // between (2, 0, 0), (0, 2, 0) and (−2, 0, 0), (0, 2, 0) at x = ±1.
  spans = spansOf(*octa, Ray(dvec3(-5, 1, 0), dvec3(1, 0, 0)));
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_DOUBLE_EQ(spans[0].in.t, 4.0);
  EXPECT_DOUBLE_EQ(spans[0].out.t, 6.0);
  // A ray through |x| + |y| + |z| = 2 at (1, 0.5, 0.5), inward normal.
  spans = spansOf(*octa, Ray(dvec3(5, 0.5, 0.5), dvec3(-1, 0, 0)));
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_DOUBLE_EQ(spans[0].in.t, 4.0);
  EXPECT_DOUBLE_EQ(spans[0].out.t, 6.0);
  expectVecNear(octa->normal(dvec3(1, 0.5, 0.5), int(spans[0].in.face)),
                glm::normalize(dvec3(1, 1, 1)), 1e-15);
}

// ---------------------------------------------------------------- watertight

// A ray exactly through the diagonal shared by the two triangles of a face
// crosses the surface once there: one span, not none and not two.
TEST(MeshSolid, RayThroughSharedDiagonalGivesOneSpan) {
  auto cube = meshOf(triangulatedCube(dvec3(10, 10, 10)));
  // Straight down through the bottom and top diagonals (x = y).
  for (double s : {5.0, 2.5, 0.1, 9.75}) {
    SpanList spans = spansOf(*cube, Ray(dvec3(s, s, -1), dvec3(0, 0, 1)));
    ASSERT_EQ(spans.size(), 1u) << s;
    EXPECT_DOUBLE_EQ(spans[0].in.t, 1.0);
    EXPECT_DOUBLE_EQ(spans[0].out.t, 11.0);
    spans = spansOf(*cube, Ray(dvec3(s, s, 11), dvec3(0, 0, -1)));
    ASSERT_EQ(spans.size(), 1u) << s;
    EXPECT_DOUBLE_EQ(spans[0].in.t, 1.0);
    EXPECT_DOUBLE_EQ(spans[0].out.t, 11.0);
  }
  // Slanted through the middle of the bottom diagonal.
  Ray slanted(dvec3(5, 5, 0) - 2.0 * dvec3(0.3, -0.2, 1), dvec3(0.3, -0.2, 1));
  SpanList spans = spansOf(*cube, slanted);
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_NEAR(spans[0].in.t, 2.0, 1e-14);
  EXPECT_NEAR(spans[0].out.t, 12.0, 1e-14);
  // The space diagonal, through two corners where three faces meet.
  spans = spansOf(*cube, Ray(dvec3(-1, -1, -1), dvec3(1, 1, 1)));
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_DOUBLE_EQ(spans[0].in.t, 1.0);
  EXPECT_DOUBLE_EQ(spans[0].out.t, 11.0);
}

// A lost or doubled crossing anywhere would leave the winding number wrong
// from there on: with a cavity, the cavity would vanish or the rest of the
// line fill up. A hollow cube, probed exactly through the shared diagonals
// and corners of both shells.
TEST(MeshSolid, HollowCubeThroughEdgesAndCorners) {
  MeshSpec outer = triangulatedCube(dvec3(10)), inner = triangulatedCube(dvec3(4), dvec3(3));
  auto hollow = meshOf(combined(outer, inner, true));
  EXPECT_NEAR(hollow->volume(), 1000.0 - 64.0, 1e-9);
  EXPECT_FALSE(hollow->contains(dvec3(5, 5, 5)));
  EXPECT_TRUE(hollow->contains(dvec3(1, 5, 5)));
  auto expectTwoSpans = [&](const Ray& ray, double a, double b, double c, double d) {
    SpanList spans = spansOf(*hollow, ray);
    ASSERT_EQ(spans.size(), 2u);
    EXPECT_NEAR(spans[0].in.t, a, 1e-13);
    EXPECT_NEAR(spans[0].out.t, b, 1e-13);
    EXPECT_NEAR(spans[1].in.t, c, 1e-13);
    EXPECT_NEAR(spans[1].out.t, d, 1e-13);
  };
  expectTwoSpans(Ray(dvec3(5, 5, -1), dvec3(0, 0, 1)), 1, 4, 8, 11);
  expectTwoSpans(Ray(dvec3(4, 4, 12), dvec3(0, 0, -1)), 2, 5, 9, 12);
  expectTwoSpans(Ray(dvec3(-1, -1, -1), dvec3(1, 1, 1)), 1, 4, 8, 11);
  expectTwoSpans(Ray(dvec3(11, 11, 11), dvec3(-1, -1, -1)), 1, 4, 8, 11);
  // Along x through the diagonals of the side faces of both shells.
  expectTwoSpans(Ray(dvec3(-1, 5, 5), dvec3(1, 0, 0)), 1, 4, 8, 11);
}

// Spans of the triangulated cube equal box{}'s: on random lines, on lines
// through every corner, and through random points of edges and face
// diagonals.
TEST(MeshSolid, SpansEqualBoxSpans) {
  dvec3 size(10, 7, 5);
  auto box = Primitive::create<Box>(size);
  auto cube = meshOf(triangulatedCube(size));
  std::mt19937_64 rng(11);
  Bounds around{dvec3(-2), size + dvec3(2)};
  for (int i = 0; i < 3000; ++i) {
    Ray line(test::randomPoint(rng, around), randomDirection(rng), -kInfinity, kInfinity);
    expectSameSpans(*cube, *box, line, 1e-9);
    if (HasFailure()) return;
  }
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto& points = cube->points();
  for (const dvec3& corner : points) {
    for (int i = 0; i < 200; ++i) {
      expectSameSpans(*cube, *box, Ray(corner, randomDirection(rng), -kInfinity, kInfinity), 1e-9);
      if (HasFailure()) return;
    }
  }
  // Points on the edges of the triangles (the cube's edges and the face
  // diagonals), reached from random origins: the line goes through them.
  for (const auto& tri : cube->triangles()) {
    for (int k = 0; k < 3; ++k) {
      for (int i = 0; i < 30; ++i) {
        dvec3 onEdge = glm::mix(points[tri[k]], points[tri[(k + 1) % 3]], u(rng));
        dvec3 from = test::randomPoint(rng, around);
        expectSameSpans(*cube, *box, Ray(from, onEdge - from, -kInfinity, kInfinity), 1e-9);
        expectSameSpans(*cube, *box, Ray(onEdge, randomDirection(rng), -kInfinity, kInfinity),
                        1e-9);
        if (HasFailure()) return;
      }
    }
  }
}

// Rays with a window (tMin, tMax) give spans that are exact within it:
// the same length there as the whole line's, and the same boundaries.
TEST(MeshSolid, SpansAreExactWithinTheWindow) {
  auto hollow = meshOf(combined(uvSphere(2.0, 12, 24), uvSphere(1.0, 12, 24), true));
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> u(-4.0, 4.0);
  Bounds around{dvec3(-2.5), dvec3(2.5)};
  for (int i = 0; i < 3000; ++i) {
    dvec3 o = test::randomPoint(rng, around), d = randomDirection(rng);
    double a = u(rng), b = u(rng);
    if (a > b) std::swap(a, b);
    SpanList whole = spansOf(*hollow, Ray(o, d, -kInfinity, kInfinity));
    SpanList window = spansOf(*hollow, Ray(o, d, a, b));
    ASSERT_TRUE(window.valid());
    EXPECT_NEAR(window.lengthWithin(a, b), whole.lengthWithin(a, b), 1e-12);
    for (const Span& s : whole)
      for (const Boundary* end : {&s.in, &s.out}) {
        if (end->t < a || end->t > b) continue;
        bool found = false;
        for (const Span& w : window)
          found = found || (w.in.t == end->t && w.in.face == end->face) ||
                  (w.out.t == end->t && w.out.face == end->face);
        EXPECT_TRUE(found) << "t=" << end->t;
      }
    // Nothing wholly beyond the window's end is reported.
    for (const Span& w : window) EXPECT_LE(w.in.t, b);
    if (HasFailure()) return;
  }
}

// Lines along an edge lie in the surface: whatever they give is valid and
// is all of the edge or nothing.
TEST(MeshSolid, LinesAlongEdges) {
  auto cube = meshOf(triangulatedCube(dvec3(10, 7, 5)));
  const auto& p = cube->points();
  for (const auto& tri : cube->triangles()) {
    for (int k = 0; k < 3; ++k) {
      dvec3 a = p[tri[k]], b = p[tri[(k + 1) % 3]];
      Ray line(a, b - a, -kInfinity, kInfinity);
      SpanList spans = spansOf(*cube, line);
      ASSERT_TRUE(spans.valid());
      double length = spans.lengthWithin(-kInfinity, kInfinity);
      EXPECT_TRUE(std::abs(length) < 1e-12 || std::abs(length - 1.0) < 1e-12) << length;
    }
  }
}

TEST(MeshSolid, SpansAgreeWithContains) {
  for (const MeshSpec& m : {openScadCube(), triangulatedCube(dvec3(3, 4, 5)), tetrahedron(2),
                            octahedron(1.5), uvSphere(2, 12, 24)}) {
    auto mesh = meshOf(m);
    expectSpansAgreeWithContainsOnRandomLines(*mesh, 2000);
    for (const dvec3& v : m.points) expectAgreementOnLinesThrough(*mesh, v, 50);
    expectOutwardUnitNormals(*mesh, 1e-12);
    SolidPtr moved = mesh->transformed(Affine::rotation(0.7, dvec3(1, 2, 3)))
                         ->transformed(Affine::translation(dvec3(1, -2, 0.5)));
    expectSpansAgreeWithContainsOnRandomLines(*moved, 500);
    if (HasFailure()) return;
  }
}

// ---------------------------------------------------------------- volumes

TEST(MeshSolid, Volumes) {
  auto cube = meshOf(openScadCube());
  expectGridVolume(cube, 350.0);
  auto tetra = meshOf(tetrahedron(3));
  EXPECT_NEAR(tetra->volume(), 4.5, 1e-12);
  expectGridVolume(tetra, 4.5);
  auto octa = meshOf(octahedron(2));
  EXPECT_NEAR(octa->volume(), 32.0 / 3.0, 1e-12);
  expectGridVolume(octa, 32.0 / 3.0);
  auto hollow =
      meshOf(combined(triangulatedCube(dvec3(10)), triangulatedCube(dvec3(4), dvec3(3)), true));
  expectGridVolume(hollow, 936.0);
}

// ---------------------------------------------------------------- polygons

// A non-convex face (an L-shaped prism's caps) is cut by ear clipping; the
// prism equals the union of two boxes.
TEST(MeshSolid, NonConvexFaces) {
  std::vector<dvec3> p;
  std::vector<glm::dvec2> l = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  for (double z : {0.0, 1.0})
    for (const auto& q : l) p.push_back({q.x, q.y, z});
  Faces f;
  // Bottom (z = 0), seen from below: counter-clockwise from above, so
  // clockwise from outside. Top: the reverse.
  f.push_back({0, 1, 2, 3, 4, 5});
  f.push_back({11, 10, 9, 8, 7, 6});
  for (int i = 0; i < 6; ++i) {
    int j = (i + 1) % 6;
    f.push_back({i, i + 6, j + 6, j});
  }
  auto prism = meshOf({p, f});
  EXPECT_FALSE(prism->turned());
  EXPECT_NEAR(prism->volume(), 3.0, 1e-12);
  SolidPtr boxes =
      unionOf({Primitive::create<Box>(dvec3(2, 1, 1)), Primitive::create<Box>(dvec3(1, 2, 1))});
  std::mt19937_64 rng(5);
  Bounds around{dvec3(-1), dvec3(3)};
  for (int i = 0; i < 2000; ++i) {
    Ray line(test::randomPoint(rng, around), randomDirection(rng), -kInfinity, kInfinity);
    expectSameSpans(*prism, *boxes, line, 1e-9);
    if (HasFailure()) return;
  }
  expectSpansAgreeWithContainsOnRandomLines(*prism);
}

// A face with a point in the middle of an edge (shared with the face next
// to it): collinear points are not cut into triangles without area.
// collinear() decides in doubles where that is sure and exactly where it
// is not: points on one line are collinear at every scale, one unit in the
// last place off the line makes a sliver that is not, and so is every
// random triangle.
TEST(MeshSolid, CollinearIsExactAtEveryScale) {
  std::mt19937 random(61);
  std::uniform_int_distribution<int> small(-40, 40);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const int exponent : {-700, -30, 0, 30, 500}) {
    const double s = std::ldexp(1.0, exponent);
    for (int trial = 0; trial < 200; ++trial) {
      // Small integers times a power of two: every point is exact.
      const dvec3 a = s * dvec3(small(random), small(random), small(random));
      const dvec3 d = s * dvec3(small(random), small(random), small(random));
      const dvec3 b = a + 3.0 * d, c = a - 5.0 * d;
      EXPECT_TRUE(collinear(a, b, c)) << exponent << " " << trial;
      EXPECT_TRUE(collinear(a, a, c)) << exponent << " " << trial;
      if (d == dvec3(0.0)) continue;
      for (int axis = 0; axis < 3; ++axis) {
        // (A coordinate of 0 would move to a subnormal: exact only for
        // points of nearby exponents, as meshes have.)
        if (c[axis] == 0.0) continue;
        dvec3 off = c;
        off[axis] = std::nextafter(off[axis], INFINITY);
        // Off the line unless the line runs along that axis alone.
        const bool alongAxis = d[(axis + 1) % 3] == 0.0 && d[(axis + 2) % 3] == 0.0;
        EXPECT_EQ(collinear(a, b, off), alongAxis) << exponent << " " << trial << " " << axis;
      }
      const dvec3 p = s * dvec3(u(random), u(random), u(random)),
                  q = s * dvec3(u(random), u(random), u(random));
      EXPECT_FALSE(collinear(a, p, q)) << exponent << " " << trial;
    }
  }
}

TEST(MeshSolid, FacesWithCollinearPoints) {
  MeshSpec m = openScadCube();
  m.points.push_back({5, 0, 0});  // 8: the middle of edge 0–1
  m.faces[0] = {0, 8, 1, 2, 3};
  m.faces[1] = {4, 5, 1, 8, 0};
  auto cube = meshOf(m);
  EXPECT_NEAR(cube->volume(), 350.0, 1e-9);
  expectSameSpans(*cube, *Primitive::create<Box>(dvec3(10, 7, 5)),
                  Ray(dvec3(5, -1, -1), dvec3(0, 1, 1), -kInfinity, kInfinity), 1e-12);
  expectSpansAgreeWithContainsOnRandomLines(*cube);
}

// ---------------------------------------------------------------- big mesh

TEST(MeshSolid, SphereOfTwentyThousandTriangles) {
  double r = 2.0;
  auto mesh = meshOf(uvSphere(r, 72, 144));
  EXPECT_GE(mesh->triangles().size(), 20000u);
  // What the script is charged: points, triangles and the BVH, about 150
  // bytes per triangle (as docs/script.md says; 154 with the 4-wide BVH).
  double perTriangle = double(mesh->memoryBytes()) / double(mesh->triangles().size());
  EXPECT_GT(perTriangle, 120.0);
  EXPECT_LT(perTriangle, 200.0);
  auto ball = Primitive::create<Sphere>(r);
  // Volume: within the chord error of the ball's, and by spans.
  EXPECT_NEAR(mesh->volume(), 4.0 / 3.0 * kPi * r * r * r, 0.002 * mesh->volume());
  expectGridVolume(mesh, mesh->volume(), 200);

  // Lines through the inner part of the ball: one span each, within the
  // chord error of the sphere's (the facets are at most 2.4e-4 r inside).
  std::mt19937_64 rng(17);
  Bounds inner{dvec3(-0.5 * r), dvec3(0.5 * r)};
  int rays = 0;
  auto start = std::chrono::steady_clock::now();
  SpanList spans;
  for (int i = 0; i < 20000; ++i) {
    Ray line(test::randomPoint(rng, inner), randomDirection(rng), -kInfinity, kInfinity);
    mesh->spans(line, spans);
    ++rays;
    ASSERT_EQ(spans.size(), 1u);
    SpanList exact = spansOf(*ball, line);
    EXPECT_NEAR(spans[0].in.t, exact[0].in.t, 2e-3 * r);
    EXPECT_NEAR(spans[0].out.t, exact[0].out.t, 2e-3 * r);
    if (HasFailure()) return;
  }
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("  %d lines through a %zu-triangle mesh: %.2f µs each; %.0f bytes per triangle\n",
              rays, mesh->triangles().size(), 1e6 * seconds / rays, perTriangle);
  expectSpansAgreeWithContainsOnRandomLines(*mesh, 2000);
  // Rays aimed exactly at vertices from outside: at most one span, and
  // one where the line passes well inside.
  const auto& points = mesh->points();
  for (int i = 0; i < 2000; ++i) {
    const dvec3& v = points[rng() % points.size()];
    dvec3 from = 3.0 * r * randomDirection(rng);
    Ray line(from, v - from, -kInfinity, kInfinity);
    SpanList s = spansOf(*mesh, line);
    ASSERT_TRUE(s.valid());
    ASSERT_LE(s.size(), 1u);
    double closest = glm::length(glm::cross(line.dir, -from)) / glm::length(line.dir);
    if (closest < 0.9 * r) {
      ASSERT_EQ(s.size(), 1u) << i;
      EXPECT_TRUE(std::abs(s[0].in.t - 1.0) < 1e-12 || std::abs(s[0].out.t - 1.0) < 1e-12);
    }
  }
}

// A hollow ball of two UV spheres, the inner one inside out: rays aimed
// exactly at vertices of either shell still give the cavity.
TEST(MeshSolid, HollowSphereThroughVertices) {
  MeshSpec outer = uvSphere(2.0, 16, 32), inner = uvSphere(1.0, 16, 32);
  auto hollow = meshOf(combined(outer, inner, true));
  std::mt19937_64 rng(23);
  for (int i = 0; i < 3000; ++i) {
    const MeshSpec& shell = i % 2 ? inner : outer;
    const dvec3& v = shell.points[rng() % shell.points.size()];
    dvec3 from = 5.0 * randomDirection(rng);
    Ray line(from, v - from, -kInfinity, kInfinity);
    SpanList spans = spansOf(*hollow, line);
    ASSERT_TRUE(spans.valid());
    // A line through a vertex of the inner shell passes through the
    // cavity (unless it grazes it) and so meets the solid twice.
    double closest = glm::length(glm::cross(line.dir, -from)) / glm::length(line.dir);
    if (closest < 0.9) {
      ASSERT_EQ(spans.size(), 2u) << i;
    } else if (closest > 1.05 && closest < 1.8) {
      ASSERT_EQ(spans.size(), 1u) << i;
    }
    expectSpansAgreeWithContains(*hollow, line);
    if (HasFailure()) return;
  }
}

// Spans reuse a per-thread scratch buffer: after the first ray, none
// allocates.
TEST(MeshSolid, RaysDoNotAllocate) {
  auto mesh = meshOf(uvSphere(1.0, 24, 48));
  SpanList spans;
  std::mt19937_64 rng(3);
  std::vector<Ray> lines;
  for (int i = 0; i < 1000; ++i)
    lines.emplace_back(test::randomPoint(rng, Bounds{dvec3(-0.5), dvec3(0.5)}),
                       randomDirection(rng), -kInfinity, kInfinity);
  mesh->spans(lines[0], spans);
  long before = test::allocations();
  bool inside = false;
  for (const Ray& line : lines) {
    mesh->spans(line, spans);
    inside = inside != mesh->contains(line.origin);
  }
  EXPECT_EQ(test::allocations(), before);
}

// ---------------------------------------------------------------- refusals

TEST(MeshSolid, Refusals) {
  MeshSpec cube = openScadCube();

  MeshSpec open = cube;
  open.faces.erase(open.faces.begin() + 2);  // no top
  EXPECT_EQ(refusal(open), "polyhedron: open mesh: edge 4→5 (face 1) has no opposite face 5→4");

  MeshSpec flipped = cube;
  std::reverse(flipped.faces[0].begin(), flipped.faces[0].end());  // {3, 2, 1, 0}
  EXPECT_EQ(refusal(flipped),
            "polyhedron: inconsistent orientation: edge 3→2 is used twice in the same direction "
            "(faces 0 and 4); list every face clockwise as seen from outside");

  MeshSpec range = cube;
  range.faces[2] = {7, 6, 8, 4};
  EXPECT_EQ(refusal(range),
            "polyhedron: face 2: point index 8 is out of range (there are 8 points, numbered "
            "from 0)");
  range.faces[2] = {7, 6, -1, 4};
  EXPECT_EQ(refusal(range),
            "polyhedron: face 2: point index -1 is out of range (there are 8 points, numbered "
            "from 0)");

  MeshSpec degenerate = tetrahedron(1);
  degenerate.points[3] = {0.5, 0, 0};  // on the edge 0–1
  EXPECT_NE(refusal(degenerate).find("is degenerate: it has no area"), std::string::npos)
      << refusal(degenerate);
  EXPECT_NE(refusal(degenerate).find("polyhedron: face 1 (points "), std::string::npos)
      << refusal(degenerate);

  MeshSpec nan = cube;
  nan.points[2].y = kNaN;
  EXPECT_TRUE(refusal(nan).starts_with("polyhedron: point 2 has a coordinate that is not finite ("))
      << refusal(nan);

  MeshSpec few = tetrahedron(1);
  few.points.pop_back();
  EXPECT_EQ(refusal(few), "polyhedron: needs at least 4 points (got 3)");
  few = tetrahedron(1);
  few.faces.pop_back();
  EXPECT_EQ(refusal(few), "polyhedron: needs at least 4 faces (got 3)");

  MeshSpec twice = cube;
  twice.faces[3] = {5, 6, 5, 1};
  EXPECT_EQ(refusal(twice), "polyhedron: face 3 uses point 5 twice");
  MeshSpec two = cube;
  two.faces[3] = {5, 6};
  EXPECT_EQ(refusal(two), "polyhedron: face 3 has 2 points; a face needs at least 3");

  // Two tetrahedra sharing the edge 0–1: four faces on it.
  MeshSpec pair = combined(tetrahedron(1), tetrahedron(1), false);
  for (auto& f : pair.faces)
    for (auto& i : f)
      if (i == 4 || i == 5) i -= 4;
  pair.points[6] = {0, -1, 0};
  pair.points[7] = {0, 0, -1};
  EXPECT_EQ(refusal(pair),
            "polyhedron: non-manifold edge 0–1: it is used by 4 faces (faces 0, 1, 4 and 5); "
            "every edge must join exactly two faces");

  // Four points in a plane make a closed tetrahedron without volume.
  MeshSpec flat = tetrahedron(1);
  flat.points[3] = {1, 1, 0};
  EXPECT_EQ(refusal(flat),
            "polyhedron: the faces connected to face 0 enclose no volume (a flat or doubled "
            "surface)");

  // Two cubes side by side, one inside out: that one is not a cavity.
  MeshSpec sideBySide =
      combined(triangulatedCube(dvec3(1)), triangulatedCube(dvec3(0.5), dvec3(3, 0, 0)), true);
  EXPECT_EQ(refusal(sideBySide),
            "polyhedron: inside-out shell: the faces connected to face 12 run the other way "
            "from the rest of the mesh, but do not bound a cavity inside it; list every face "
            "clockwise as seen from outside");
}

// ---------------------------------------------------------------- script API

const char* kCubeLua =
    "local points = {{0,0,0}, {10,0,0}, {10,7,0}, {0,7,0}, {0,0,5}, {10,0,5}, {10,7,5}, {0,7,5}}\n"
    "local faces = {{0,1,2,3}, {4,5,1,0}, {7,6,5,4}, {5,6,2,1}, {6,7,3,2}, {7,4,0,3}}\n";

TEST(MeshSolidScript, Polyhedron) {
  Scene scene = runScript(std::string(kCubeLua) +
                              "local p = polyhedron{points=points, faces=faces, convexity=10}\n"
                              "assert(p:contains(5, 3, 2) and not p:contains(11, 3, 2))\n"
                              "return (p - sphere(2):translate(10, 7, 5)):translate(1, 0, 0)",
                          "part.lua");
  ASSERT_EQ(scene.objects.size(), 1u);
  const Solid& part = *scene.objects[0];
  expectVecNear(part.bounds().lo, dvec3(1, 0, 0), 1e-12);
  expectVecNear(part.bounds().hi, dvec3(11, 7, 5), 1e-12);
  EXPECT_TRUE(part.contains(dvec3(2, 1, 1)));
  EXPECT_FALSE(part.contains(dvec3(10.5, 6.5, 4.5)));  // in the sphere's bite
  SpanList spans = spansOf(part, Ray(dvec3(0, 3.5, 2.5), dvec3(1, 0, 0)));
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_DOUBLE_EQ(spans[0].in.t, 1.0);
  EXPECT_DOUBLE_EQ(spans[0].out.t, 11.0);
}

TEST(MeshSolidScript, ErrorsNameTheLineAndTheBadPart) {
  std::string cube = kCubeLua;
  auto call = [&](const std::string& points, const std::string& faces) {
    return cube + "return polyhedron{points=" + points + ", faces=" + faces + "}";
  };
  EXPECT_EQ(scriptError(call("points", "{{0,1,2,3}, {4,5,1,0}, {5,6,2,1}, {6,7,3,2}, {7,4,0,3}}")),
            "part.lua:3: polyhedron: open mesh: edge 4→5 (face 1) has no opposite face 5→4");
  EXPECT_EQ(scriptError(call("points",
                             "{{3,2,1,0}, {4,5,1,0}, {7,6,5,4}, {5,6,2,1}, {6,7,3,2}, "
                             "{7,4,0,3}}")),
            "part.lua:3: polyhedron: inconsistent orientation: edge 3→2 is used twice in the "
            "same direction (faces 0 and 4); list every face clockwise as seen from outside");
  EXPECT_EQ(scriptError(call("points",
                             "{{0,1,2,8}, {4,5,1,0}, {7,6,5,4}, {5,6,2,1}, {6,7,3,2}, "
                             "{7,4,0,3}}")),
            "part.lua:3: polyhedron: face 0: point index 8 is out of range (there are 8 points, "
            "numbered from 0)");
  EXPECT_EQ(scriptError(call("{{0,0,0}, {1,0,0}, {2,0,0}, {0,0,1}}",
                             "{{0,1,2}, {0,3,1}, {1,3,2}, {2,3,0}}")),
            "part.lua:3: polyhedron: face 0 (points 0, 1, 2) is degenerate: it has no area");
  EXPECT_EQ(scriptError(call("{{0,0,0}, {1,0,0}, {0,0/0,0}, {0,0,1}}", "faces")),
            "part.lua:3: polyhedron: point 2: y must be finite");
  EXPECT_EQ(scriptError(call("points", "{{0,1,2.5,3}}")),
            "part.lua:3: polyhedron: face 0: 2.5 is not a point index (an integer from 0)");
  EXPECT_EQ(scriptError(call("points", "{{0,1,'x'}}")),
            "part.lua:3: polyhedron: face 0: a string is not a point index (an integer from 0)");
  EXPECT_EQ(scriptError(call("{{0,0}}", "faces")),
            "part.lua:3: polyhedron: point 0 must be a list of three numbers {x, y, z}");
  EXPECT_EQ(scriptError(call("5", "faces")),
            "part.lua:3: polyhedron: points must be a list of points {{x, y, z}, ...}, got number");
  EXPECT_EQ(scriptError(cube + "return polyhedron{points=points}"),
            "part.lua:3: polyhedron: needs faces={{i, j, k}, ...} (point indices from 0, "
            "clockwise seen from outside)");
  EXPECT_EQ(scriptError(cube + "return polyhedron{points=points, faces=faces, triangles=faces}"),
            "part.lua:3: polyhedron: unknown parameter 'triangles'");
}

// The mesh is charged against the memory cap, for the rest of the run: 30
// copies of a 20 000-triangle sphere (about 4 MB each) do not fit in
// 64 MiB, although the Lua tables they are built from are shared.
TEST(MeshSolidScript, MeshesCountAgainstTheMemoryCap) {
  std::string sphere = R"(
    local rings, segments, points, faces = 72, 144, {{0, 0, 1}}, {}
    for i = 1, rings - 1 do
      local theta = math.pi * i / rings
      for j = 0, segments - 1 do
        local phi = 2 * math.pi * j / segments
        points[#points + 1] = {math.sin(theta) * math.cos(phi), math.sin(theta) * math.sin(phi),
                               math.cos(theta)}
      end
    end
    points[#points + 1] = {0, 0, -1}
    local function at(i, j) return 1 + (i - 1) * segments + j % segments end
    for j = 0, segments - 1 do faces[#faces + 1] = {0, at(1, j + 1), at(1, j)} end
    for i = 1, rings - 2 do
      for j = 0, segments - 1 do
        faces[#faces + 1] = {at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)}
      end
    end
    for j = 0, segments - 1 do faces[#faces + 1] = {#points - 1, at(rings - 1, j), at(rings - 1, j + 1)} end
  )";
  ScriptOptions options;
  options.limits.memoryBytes = 64u << 20;
  EXPECT_EQ(scriptError(sphere + "return polyhedron{points=points, faces=faces}", options),
            "(no error)");
  std::string e =
      scriptError(sphere +
                      "local parts = {}\n"
                      "for i = 1, 30 do\n"
                      "  parts[i] = polyhedron{points=points, faces=faces}:translate(3 * i, 0, 0)\n"
                      "end\n"
                      "return union(parts)",
                  options);
  EXPECT_NE(e.find("script exceeded the memory limit of 64 MiB"), std::string::npos) << e;
}

}  // namespace
}  // namespace csgray::detail
