// The general quadric's tessellation (issue 5): closed, outward meshes that
// follow the surface within the tolerance inside the region, with the
// volumes of table 17.1's solids; and the canonical form it is built on.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "engine/solvers/quadric_form.h"
#include "export/cgal/mesh_validity.h"
#include "primitives/quadric.h"
#include "script/script.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

using test::diagonal;

constexpr double kPi = std::numbers::pi;

// The matrices of api_quadrics.cpp (table 17.1 scaled by a positive factor).
glm::dmat4 ellipsoidM(double a, double b, double c) {
  return diagonal(1 / (a * a), 1 / (b * b), 1 / (c * c), -1);
}
glm::dmat4 hyperboloid1M(double a, double b, double c) {
  return diagonal(1 / (a * a), 1 / (b * b), -1 / (c * c), -1);
}
glm::dmat4 hyperboloid2M(double a, double b, double c) {
  return diagonal(1 / (a * a), 1 / (b * b), -1 / (c * c), 1);
}
glm::dmat4 coneM(double a, double b, double c) {
  return diagonal(1 / (a * a), 1 / (b * b), -1 / (c * c), 0);
}
glm::dmat4 ellipticParaboloidM(double a, double b) {
  glm::dmat4 m = diagonal(1 / (a * a), 1 / (b * b), 0, 0);
  m[2][3] = m[3][2] = -0.5;
  return m;
}
glm::dmat4 hyperbolicParaboloidM(double a, double b) {
  glm::dmat4 m = diagonal(1 / (a * a), -1 / (b * b), 0, 0);
  m[2][3] = m[3][2] = -0.5;
  return m;
}
glm::dmat4 ellipticCylinderM(double a, double b) {
  return diagonal(1 / (a * a), 1 / (b * b), 0, -1);
}
glm::dmat4 hyperbolicCylinderM(double a, double b) {
  return diagonal(-1 / (a * a), 1 / (b * b), 0, 1);
}
glm::dmat4 parabolicCylinderM(double p) {
  glm::dmat4 m(0.0);
  m[1][1] = 1.0;
  m[0][3] = m[3][0] = -p;
  return m;
}

// The matrix of the same quadric after moving it by the affine map x ↦ Ax + t:
// (H⁻¹)ᵀ M H⁻¹ with H the map as a 4×4 matrix.
glm::dmat4 moved(const glm::dmat4& m, const glm::dmat4& h) {
  const glm::dmat4 inv = glm::inverse(h);
  glm::dmat4 r = glm::transpose(inv) * m * inv;
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < c; ++row) r[c][row] = r[row][c] = 0.5 * (r[c][row] + r[row][c]);
  return r;
}

glm::dmat4 someMotion() {
  glm::dmat4 h = glm::translate(glm::dmat4(1.0), dvec3(1.5, -2.0, 0.75));
  h = glm::rotate(h, 0.7, glm::normalize(dvec3(1.0, 2.0, -0.5)));
  return glm::rotate(h, 1.9, glm::normalize(dvec3(-0.3, 0.4, 1.0)));
}

TriangleMesh tessellate(const glm::dmat4& m, double tolerance, const Bounds& region) {
  return Primitive::create<Quadric>(m)->tessellate(tolerance, region);
}

double form(const glm::dmat4& m, const dvec3& p) {
  const glm::dvec4 e(p, 1.0);
  return glm::dot(e, m * e);
}

// The distance from p to the surface, to first order: |q| / |∇q|.
double surfaceDistance(const glm::dmat4& m, const dvec3& p) {
  const dvec3 gradient = 2.0 * dvec3(m * glm::dvec4(p, 1.0));
  return std::abs(form(m, p)) / glm::length(gradient);
}

// Every directed edge has exactly one twin running the other way (closed,
// 2-manifold at edges, consistently oriented), and no face is degenerate.
void expectClosedAndOriented(const TriangleMesh& mesh) {
  ASSERT_FALSE(mesh.empty());
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  const double scale = glm::length(mesh.bounds().size());
  int degenerate = 0;
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
    const dvec3 a = mesh.points[t[0]], b = mesh.points[t[1]], c = mesh.points[t[2]];
    if (glm::length(glm::cross(b - a, c - a)) <= 1e-14 * scale * scale) ++degenerate;
  }
  EXPECT_EQ(degenerate, 0);
  int unmatched = 0;
  for (const auto& [edge, count] : edges) {
    auto twin = edges.find({edge.second, edge.first});
    if (count != 1 || twin == edges.end() || twin->second != 1) ++unmatched;
  }
  EXPECT_EQ(unmatched, 0);
  EXPECT_GT(mesh.volume(), 0.0);
}

// Every vertex is on the surface, or outside the region (on the mesh's own
// caps and walls); every point of the triangles inside the region is within
// the tolerance of the surface.
void expectFollowsSurface(const TriangleMesh& mesh, const glm::dmat4& m, const Bounds& region,
                          double tolerance) {
  int strayVertices = 0;
  for (const dvec3& p : mesh.points) {
    if (region.contains(p) && surfaceDistance(m, p) > 1e-9) ++strayVertices;
  }
  EXPECT_EQ(strayVertices, 0);
  double worst = 0.0;
  int inside = 0;
  static const std::array<dvec3, 7> weights{
      dvec3(1, 1, 1) / 3.0, dvec3(0.5, 0.5, 0),   dvec3(0, 0.5, 0.5),  dvec3(0.5, 0, 0.5),
      dvec3(0.7, 0.2, 0.1), dvec3(0.1, 0.7, 0.2), dvec3(0.2, 0.1, 0.7)};
  for (const auto& t : mesh.triangles) {
    for (const dvec3& w : weights) {
      const dvec3 p = w.x * mesh.points[t[0]] + w.y * mesh.points[t[1]] + w.z * mesh.points[t[2]];
      if (!region.contains(p)) continue;
      ++inside;
      worst = std::max(worst, surfaceDistance(m, p));
    }
  }
  EXPECT_GT(inside, 0);
  EXPECT_LE(worst, tolerance);
  // Not far finer than asked either: the tessellation uses its tolerance.
  EXPECT_GT(worst, 0.05 * tolerance);
}

void expectValid(const TriangleMesh& mesh, const glm::dmat4& m, const Bounds& region,
                 double tolerance) {
  expectClosedAndOriented(mesh);
  expectFollowsSurface(mesh, m, region, tolerance);
  EXPECT_EQ(meshDefect(mesh).text, "");
}

// ---- Volumes of the mesh within a box or a slab ------------------------------------

// The convex polygon clipped to n·p <= c (Sutherland and Hodgman 1974).
std::vector<dvec3> clipPolygon(const std::vector<dvec3>& polygon, const dvec3& n, double c) {
  std::vector<dvec3> out;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const dvec3& a = polygon[i];
    const dvec3& b = polygon[(i + 1) % polygon.size()];
    const double da = glm::dot(n, a) - c, db = glm::dot(n, b) - c;
    if (da <= 0.0) out.push_back(a);
    if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0))
      out.push_back(a + (da / (da - db)) * (b - a));
  }
  return out;
}

using Plane = std::pair<dvec3, double>;  // n·p <= c

// Σ over the mesh's triangles clipped to the planes of ∫ f(p)·n dA, for an
// affine field f: f at each fan triangle's centroid times its area vector.
double fluxWithin(const TriangleMesh& mesh, const std::vector<Plane>& planes,
                  const std::function<dvec3(const dvec3&)>& f) {
  double sum = 0.0;
  for (const auto& t : mesh.triangles) {
    std::vector<dvec3> polygon{mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]};
    for (const auto& [n, c] : planes) polygon = clipPolygon(polygon, n, c);
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
      const dvec3 areaVector =
          0.5 * glm::cross(polygon[k] - polygon[0], polygon[k + 1] - polygon[0]);
      sum += glm::dot(f((polygon[0] + polygon[k] + polygon[k + 1]) / 3.0), areaVector);
    }
  }
  return sum;
}

// The volume of the solid inside the mesh between the planes n·p = c0 and
// n·p = c1 (n a unit vector), by the divergence theorem with the field
// (p − (p·n)n)/2: its divergence is 1 and it is tangent to the two cut
// faces, which therefore add nothing and need not be built.
double volumeInSlab(const TriangleMesh& mesh, const dvec3& n, double c0, double c1) {
  return fluxWithin(mesh, {{n, c1}, {-n, -c0}},
                    [n](const dvec3& p) { return 0.5 * (p - glm::dot(p, n) * n); });
}

// The volume of the solid inside the mesh within the box: inclusion and
// exclusion over the box's corners of the volumes within the orthants
// {p <= corner}, each by the divergence theorem with the field p − corner,
// which is tangent to the orthant's three faces.
double volumeInBox(const TriangleMesh& mesh, const Bounds& box) {
  double sum = 0.0;
  for (int i = 0; i < 8; ++i) {
    const dvec3 corner(i & 1 ? box.lo.x : box.hi.x, i & 2 ? box.lo.y : box.hi.y,
                       i & 4 ? box.lo.z : box.hi.z);
    const int sign = (i & 1 ? -1 : 1) * (i & 2 ? -1 : 1) * (i & 4 ? -1 : 1);
    const std::vector<Plane> orthant{
        {dvec3(1, 0, 0), corner.x}, {dvec3(0, 1, 0), corner.y}, {dvec3(0, 0, 1), corner.z}};
    sum +=
        sign * fluxWithin(mesh, orthant, [corner](const dvec3& p) { return (p - corner) / 3.0; });
  }
  return sum;
}

double areaInBox(const TriangleMesh& mesh, const Bounds& box) {
  double sum = 0.0;
  for (const auto& t : mesh.triangles) {
    std::vector<dvec3> polygon{mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]};
    for (int a = 0; a < 3; ++a) {
      dvec3 n(0.0);
      n[a] = 1.0;
      polygon = clipPolygon(polygon, n, box.hi[a]);
      polygon = clipPolygon(polygon, -n, -box.lo[a]);
    }
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
      sum += 0.5 * glm::length(glm::cross(polygon[k] - polygon[0], polygon[k + 1] - polygon[0]));
  }
  return sum;
}

// The mesh's volume within the box is the exact one within the tolerance
// times the surface's area there (the mesh is within tolerance of it).
void expectVolumeInBox(const TriangleMesh& mesh, const Bounds& box, double exact,
                       double tolerance) {
  const double area = areaInBox(mesh, box);
  EXPECT_GT(area, 0.0);
  EXPECT_NEAR(volumeInBox(mesh, box), exact, tolerance * area);
}

Bounds cube(double h) { return {dvec3(-h), dvec3(h)}; }

// ---- The canonical form -------------------------------------------------------------

TEST(QuadricForm, JacobiDiagonalizesASymmetricMatrix) {
  glm::dmat3 a(4.0, 1.0, -2.0, 1.0, 3.0, 0.5, -2.0, 0.5, -1.0);
  dvec3 values;
  glm::dmat3 vectors;
  symmetricEigen(a, values, vectors);
  for (int i = 0; i < 3; ++i) {
    test::expectVecNear(a * vectors[i], values[i] * vectors[i], 1e-12);
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(glm::dot(vectors[i], vectors[j]), i == j, 1e-12);
  }
  // The trace and determinant are the sum and product of the eigenvalues.
  EXPECT_NEAR(values.x + values.y + values.z, 6.0, 1e-12);
  EXPECT_NEAR(values.x * values.y * values.z, glm::determinant(a), 1e-11);
}

TEST(QuadricForm, ReproducesTheFormOfEveryNamedQuadricMoved) {
  const std::vector<glm::dmat4> matrices{
      ellipsoidM(3, 2, 1),     hyperboloid1M(1, 2, 1.5),    hyperboloid2M(1, 1, 2),
      coneM(1, 2, 1),          ellipticParaboloidM(2, 1),   hyperbolicParaboloidM(1, 2),
      ellipticCylinderM(2, 1), hyperbolicCylinderM(1, 1.5), parabolicCylinderM(-0.5)};
  std::mt19937_64 rng(5);
  for (const glm::dmat4& m0 : matrices) {
    const glm::dmat4 m = moved(m0, someMotion());
    const QuadricForm f = canonicalQuadricForm(m);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(glm::dot(f.axes[i], f.axes[j]), i == j, 1e-12);
    EXPECT_NEAR(std::max({std::abs(f.lambda.x), std::abs(f.lambda.y), std::abs(f.lambda.z)}), 1.0,
                1e-12);
    if (f.linear != 0.0) {
      EXPECT_EQ(f.lambda.z, 0.0);
      EXPECT_EQ(f.constant, 0.0);
    }
    for (int k = 0; k < 20; ++k) {
      const dvec3 p = test::randomPoint(rng, cube(5.0));
      EXPECT_NEAR(form(m, p), f.scale * f.at(f.toCanonical(p)),
                  1e-9 * (1.0 + std::abs(form(m, p))));
    }
  }
}

TEST(QuadricForm, FindsTheKindOfAMovedCone) {
  // The cone's constant stays 0 despite the rounding of the motion, and
  // y₂ is its axis.
  const glm::dmat4 h = someMotion();
  const QuadricForm f = canonicalQuadricForm(moved(coneM(1, 2, 1), h));
  EXPECT_EQ(f.constant, 0.0);
  EXPECT_LT(f.lambda.z, 0.0);
  test::expectVecNear(f.origin, dvec3(h[3]), 1e-12);
  EXPECT_NEAR(std::abs(glm::dot(f.axes[2], glm::normalize(dvec3(h * glm::dvec4(0, 0, 1, 0))))), 1.0,
              1e-12);
}

// ---- The nine named quadrics --------------------------------------------------------

TEST(QuadricTessellation, EllipsoidIgnoresTheRegionAndHasItsVolume) {
  const double tol = 0.01;
  const glm::dmat4 m = ellipsoidM(3, 2, 1);
  const TriangleMesh mesh = tessellate(m, tol, Bounds::everything());
  expectValid(mesh, m, cube(10), tol);
  // Inscribed: a little smaller than 4/3·πabc, by at most tol × area.
  const double exact = 4.0 / 3.0 * kPi * 3 * 2 * 1;
  EXPECT_LT(mesh.volume(), exact);
  EXPECT_GT(mesh.volume(), exact - tol * mesh.area());
  // A region elsewhere changes nothing.
  EXPECT_EQ(tessellate(m, tol, cube(0.1)).size(), mesh.size());
}

TEST(QuadricTessellation, HyperboloidOfOneSheet) {
  const double tol = 0.01, a = 1, b = 2, c = 1.5, h = 2;
  const glm::dmat4 m = hyperboloid1M(a, b, c);
  const Bounds region{dvec3(-6, -8, -h), dvec3(6, 8, h)};
  const TriangleMesh mesh = tessellate(m, tol, region);
  expectValid(mesh, m, region, tol);
  // Sections πab(1 + z²/c²) for |z| <= h.
  expectVolumeInBox(mesh, region, kPi * a * b * (2 * h + 2 * h * h * h / (3 * c * c)), tol);
}

TEST(QuadricTessellation, HyperboloidOfTwoSheetsIsTwoShells) {
  const double tol = 0.01, a = 1, b = 1.5, c = 1, h = 2.5;
  const glm::dmat4 m = hyperboloid2M(a, b, c);
  const Bounds region{dvec3(-4, -5, -h), dvec3(4, 5, h)};
  const TriangleMesh mesh = tessellate(m, tol, region);
  expectValid(mesh, m, region, tol);
  // Sections πab(z²/c² − 1) for c <= |z| <= h, on both sheets.
  const double exact = 2 * kPi * a * b * ((h * h * h - c * c * c) / (3 * c * c) - (h - c));
  expectVolumeInBox(mesh, region, exact, tol);
  // Only the upper sheet when the region is above the lower one.
  const Bounds upper{dvec3(-4, -5, 0.5), dvec3(4, 5, h)};
  const TriangleMesh one = tessellate(m, tol, upper);
  expectValid(one, m, upper, tol);
  EXPECT_GT(one.bounds().lo.z, 0.0);
}

TEST(QuadricTessellation, ConeNappeFromItsApex) {
  const double tol = 0.01, a = 1, b = 2, c = 1, h = 2;
  const glm::dmat4 m = coneM(a, b, c);
  const Bounds region{dvec3(-3, -5, 0), dvec3(3, 5, h)};
  const TriangleMesh mesh = tessellate(m, tol, region);
  expectValid(mesh, m, region, tol);
  // Only the upper nappe: nothing below the apex.
  EXPECT_GE(mesh.bounds().lo.z, 0.0);
  expectVolumeInBox(mesh, region, kPi * a * b * h * h * h / (3 * c * c), tol);
  // The lower nappe alone below.
  const Bounds below{dvec3(-3, -5, -h), dvec3(3, 5, -0.5)};
  const TriangleMesh lower = tessellate(m, tol, below);
  expectValid(lower, m, below, tol);
  EXPECT_LE(lower.bounds().hi.z, 0.0);
}

TEST(QuadricTessellation, EllipticParaboloid) {
  const double tol = 0.01, a = 2, b = 1, h = 4;
  const glm::dmat4 m = ellipticParaboloidM(a, b);
  const Bounds region{dvec3(-5, -5, 0), dvec3(5, 5, h)};
  const TriangleMesh mesh = tessellate(m, tol, region);
  expectValid(mesh, m, region, tol);
  // Sections πab·z up to z = h: πab h²/2.
  expectVolumeInBox(mesh, region, kPi * a * b * h * h / 2, tol);
  EXPECT_NEAR(volumeInSlab(mesh, dvec3(0, 0, 1), -1, h), kPi * a * b * h * h / 2,
              tol * mesh.area());
}

TEST(QuadricTessellation, HyperbolicParaboloid) {
  const double tol = 0.01, a = 1, b = 2;
  const glm::dmat4 m = hyperbolicParaboloidM(a, b);
  const Bounds region{dvec3(-1, -1, -2), dvec3(1, 1, 2)};
  const TriangleMesh mesh = tessellate(m, tol, region);
  expectValid(mesh, m, region, tol);
  // ∫∫ (2 − x²/a² + y²/b²) over [−1, 1]².
  expectVolumeInBox(mesh, region, 8 - 4 / (3 * a * a) + 4 / (3 * b * b), tol);
}

TEST(QuadricTessellation, EllipticCylinder) {
  const double tol = 0.01, a = 2, b = 1, h = 3;
  const glm::dmat4 m = ellipticCylinderM(a, b);
  const Bounds region{dvec3(-3, -3, -h), dvec3(3, 3, h)};
  const TriangleMesh mesh = tessellate(m, tol, region);
  expectValid(mesh, m, region, tol);
  expectVolumeInBox(mesh, region, kPi * a * b * 2 * h, tol);
}

TEST(QuadricTessellation, HyperbolicCylinderIsTwoShells) {
  const double tol = 0.01, a = 1, b = 1.5, x = 3, y = 2, z = 1;
  const glm::dmat4 m = hyperbolicCylinderM(a, b);
  const Bounds region{dvec3(-x, -y, -z), dvec3(x, y, z)};
  const TriangleMesh mesh = tessellate(m, tol, region);
  expectValid(mesh, m, region, tol);
  // Each sheet's section: ∫ (x − a√(1 + y²/b²)) dy over [−y, y].
  const double s = y / b;
  const double section = 2 * x * y - a * b * (s * std::sqrt(1 + s * s) + std::asinh(s));
  expectVolumeInBox(mesh, region, 2 * section * 2 * z, tol);
}

TEST(QuadricTessellation, RegionBetweenTheSheetsOfAHyperbolicCylinder) {
  // The hyperbolic cylinder's complement (the table's own matrix).
  const double tol = 0.01, a = 1, b = 1.5, x = 3, y = 2, z = 1;
  const glm::dmat4 m = -hyperbolicCylinderM(a, b);
  const Bounds region{dvec3(-x, -y, -z), dvec3(x, y, z)};
  const TriangleMesh mesh = tessellate(m, tol, region);
  expectValid(mesh, m, region, tol);
  const double s = y / b;
  const double section = 2 * x * y - a * b * (s * std::sqrt(1 + s * s) + std::asinh(s));
  expectVolumeInBox(mesh, region, (4 * x * y - 2 * section) * 2 * z, tol);
}

TEST(QuadricTessellation, ParabolicCylinderOpensEitherWay) {
  const double tol = 0.01, x = 4, y = 2, z = 1;
  for (double p : {1.0, -0.75}) {
    SCOPED_TRACE(p);
    const glm::dmat4 m = parabolicCylinderM(p);
    const Bounds region{dvec3(-x, -y, -z), dvec3(x, y, z)};
    const TriangleMesh mesh = tessellate(m, tol, region);
    expectValid(mesh, m, region, tol);
    // ∫ (x − y²/(2|p|)) dy over [−y, y], times the height.
    const double section = 2 * x * y - y * y * y / (3 * std::abs(p));
    expectVolumeInBox(mesh, region, section * 2 * z, tol);
  }
}

TEST(QuadricTessellation, ScriptsClippedQuadric) {
  const Scene scene = runScript(
      "return clip(hyperboloid1{a=1, b=2, c=1}, {lo={-3, -5, -1}, hi={3, 5, 2}})", "test");
  ASSERT_EQ(scene.objects.size(), 1u);
  const Quadric* quadric = nullptr;
  for (const SolidPtr& child : scene.objects[0]->children())
    if (auto q = dynamic_cast<const Quadric*>(child.get())) quadric = q;
  ASSERT_NE(quadric, nullptr);
  const Bounds region = scene.objects[0]->bounds();
  const TriangleMesh mesh = quadric->tessellate(0.02, region);
  expectValid(mesh, quadric->matrix(), region, 0.02);
  // The clip box holds the sections (semi-axes up to √5, 2√5) for
  // −1 <= z <= 2: πab(3 + (8 + 1)/3).
  expectVolumeInBox(mesh, region, kPi * 2 * (3 + 3), 0.02);
}

// ---- Moved, general and degenerate quadrics ---------------------------------------

TEST(QuadricTessellation, MovedQuadricsKeepTheirVolumes) {
  const double tol = 0.01;
  const glm::dmat4 h = someMotion();
  const dvec3 axis = glm::normalize(dvec3(h * glm::dvec4(0, 0, 1, 0)));
  const double offset = glm::dot(axis, dvec3(h[3]));
  {
    const glm::dmat4 m = moved(ellipsoidM(3, 2, 1), h);
    const TriangleMesh mesh = tessellate(m, tol, Bounds::everything());
    expectValid(mesh, m, cube(10), tol);
    EXPECT_NEAR(mesh.volume(), tessellate(ellipsoidM(3, 2, 1), tol, cube(1)).volume(),
                tol * mesh.area());
  }
  {
    // The hyperboloid between the planes at ±2 along its axis.
    const Bounds region{dvec3(h[3]) - dvec3(7), dvec3(h[3]) + dvec3(7)};
    const glm::dmat4 m = moved(hyperboloid1M(1, 2, 1.5), h);
    const TriangleMesh mesh = tessellate(m, tol, region);
    expectValid(mesh, m, region, tol);
    const TriangleMesh canonical = tessellate(hyperboloid1M(1, 2, 1.5), tol, cube(7));
    EXPECT_NEAR(volumeInSlab(mesh, axis, offset - 2, offset + 2),
                volumeInSlab(canonical, dvec3(0, 0, 1), -2, 2), tol * mesh.area());
  }
  {
    const Bounds region{dvec3(h[3]) - dvec3(5), dvec3(h[3]) + dvec3(5)};
    const glm::dmat4 m = moved(ellipticParaboloidM(2, 1), h);
    const TriangleMesh mesh = tessellate(m, tol, region);
    expectValid(mesh, m, region, tol);
    EXPECT_NEAR(volumeInSlab(mesh, axis, offset - 1, offset + 3), kPi * 2 * 1 * 9 / 2,
                tol * mesh.area());
  }
  {
    // A saddle moved: its volume in a box about the moved box's centre is
    // its canonical one's in the matching box, found through the slab of
    // the moved z axis (the x and y extents are those of the saddle's own
    // tessellation, which covers the whole region).
    const Bounds region{dvec3(h[3]) - dvec3(3), dvec3(h[3]) + dvec3(3)};
    const glm::dmat4 m = moved(hyperbolicParaboloidM(1, 2), h);
    expectValid(tessellate(m, tol, region), m, region, tol);
  }
}

TEST(QuadricTessellation, PlanesSlabsAndTheWholeSpace) {
  const double tol = 0.01;
  const Bounds region = cube(2);
  // The half-space z <= 1 (2·z − 2 <= 0), tilted.
  glm::dmat4 half(0.0);
  half[2][3] = half[3][2] = 1.0;
  half[3][3] = -2.0;
  const TriangleMesh halfMesh = tessellate(half, tol, region);
  expectClosedAndOriented(halfMesh);
  EXPECT_NEAR(volumeInBox(halfMesh, region), 4 * 4 * 3, 1e-9);
  const glm::dmat4 tilted = moved(half, someMotion());
  const TriangleMesh tiltedMesh = tessellate(tilted, tol, region);
  expectClosedAndOriented(tiltedMesh);
  EXPECT_EQ(meshDefect(tiltedMesh).text, "");
  // The slab |x| <= 0.5, and the two half-spaces |x| >= 0.5 beside it.
  const glm::dmat4 slab = diagonal(4, 0, 0, -1);
  EXPECT_NEAR(volumeInBox(tessellate(slab, tol, region), region), 1 * 4 * 4, 1e-9);
  const TriangleMesh outside = tessellate(-slab, tol, region);
  expectClosedAndOriented(outside);
  EXPECT_NEAR(volumeInBox(outside, region), 3 * 4 * 4, 1e-9);
  // Everything: a box a little larger than the region.
  const TriangleMesh all = tessellate(diagonal(0, 0, 0, -1), tol, region);
  expectClosedAndOriented(all);
  EXPECT_NEAR(volumeInBox(all, region), 64, 1e-9);
  EXPECT_GT(all.volume(), 64);
  EXPECT_LT(all.volume(), 64 * 1.5);
  // Two planes |y| <= |x| crossing on the z axis: one wedge, away from it.
  const glm::dmat4 planes = diagonal(-1, 1, 0, 0);
  const Bounds right{dvec3(0.5, -2, -1), dvec3(2, 2, 1)};
  const TriangleMesh wedge = tessellate(planes, tol, right);
  expectClosedAndOriented(wedge);
  EXPECT_EQ(meshDefect(wedge).text, "");
  // Sections 2x wide for 0.5 <= x <= 2, 2 high.
  EXPECT_NEAR(volumeInBox(wedge, right), 2 * (2 * 2 - 0.5 * 0.5) / 2 * 2, 1e-9);
}

TEST(QuadricTessellation, EmptySolidsGiveEmptyMeshes) {
  const double tol = 0.01;
  EXPECT_TRUE(tessellate(diagonal(1, 1, 1, 1), tol, Bounds::everything()).empty());
  EXPECT_TRUE(tessellate(diagonal(1, 1, 1, 0), tol, Bounds::everything()).empty());  // a point
  EXPECT_TRUE(tessellate(diagonal(1, 1, 0, 0), tol, cube(1)).empty());               // a line
  EXPECT_TRUE(tessellate(diagonal(0, 0, 0, 1), tol, cube(1)).empty());
  // A paraboloid opening up, seen only below its vertex.
  EXPECT_TRUE(
      tessellate(ellipticParaboloidM(1, 1), tol, {dvec3(-1, -1, -3), dvec3(1, 1, -1)}).empty());
}

// ---- What is refused ----------------------------------------------------------------

void expectRefused(const glm::dmat4& m, double tolerance, const Bounds& region,
                   const std::string& start) {
  try {
    tessellate(m, tolerance, region);
    ADD_FAILURE() << "no exception, expected: " << start;
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).substr(0, start.size()), start) << e.what();
  }
}

TEST(QuadricTessellation, RefusesWhatCannotBeAClosedManifold) {
  const double tol = 0.01;
  expectRefused(hyperboloid1M(1, 1, 1), tol, Bounds::everything(),
                "quadric: is unbounded; clip it with a box or half-spaces to export it");
  expectRefused(diagonal(0, 0, 0, -1), tol, Bounds::everything(), "quadric: is unbounded");
  expectRefused(coneM(1, 1, 1), tol, cube(1), "quadric: the cone's apex");
  expectRefused(moved(coneM(1, 1, 1), someMotion()), tol,
                {dvec3(someMotion()[3]) - dvec3(1), dvec3(someMotion()[3]) + dvec3(1)},
                "quadric: the cone's apex");
  expectRefused(diagonal(-1, 1, 0, 0), tol, cube(1), "quadric: its two planes cross");
  expectRefused(-ellipsoidM(1, 2, 3), tol, cube(5), "quadric: the outside of");
  expectRefused(-hyperboloid1M(1, 2, 3), tol, cube(5), "quadric: the outside of");
  expectRefused(-ellipticCylinderM(1, 2), tol, cube(5), "quadric: the outside of");
  expectRefused(ellipsoidM(1, 1, 1), 0.0, cube(1), "quadric: the tolerance");
  // Far too fine a tolerance is an error before any memory is spent.
  expectRefused(ellipsoidM(1, 1, 1), 1e-12, cube(1), "quadric: a tolerance of");
  expectRefused(hyperbolicParaboloidM(1, 1), 1e-10, cube(10), "quadric: a tolerance of");
}

}  // namespace
}  // namespace csgray::detail
