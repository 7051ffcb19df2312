#include "primitives/triangle_crossing.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace csgray::detail {

namespace {

// ---- Exact sign of a·b − c·d --------------------------------------------------
//
// Error-free transformations (Shewchuk, "Adaptive Precision Floating-Point
// Arithmetic and Fast Robust Geometric Predicates", 1997): a product is
// p + e exactly with e = fma(a, b, −p), and Two_Two_Diff turns
// (p₁ + e₁) − (p₂ + e₂) into a non-overlapping expansion whose largest
// non-zero component has the sign of the exact value.

void twoSum(double a, double b, double& x, double& y) {
  x = a + b;
  double bv = x - a, av = x - bv;
  y = (a - av) + (b - bv);
}

void twoDiff(double a, double b, double& x, double& y) {
  x = a - b;
  double bv = a - x, av = x + bv;
  y = (a - av) + (bv - b);
}

// (a1 + a0) − b = x2 + x1 + x0.
void twoOneDiff(double a1, double a0, double b, double& x2, double& x1, double& x0) {
  double i;
  twoDiff(a0, b, i, x0);
  twoSum(a1, i, x2, x1);
}

// Whether three points lie on one line, exactly (collinear): each component of the
// cross product (b − a) × (c − a) is zero when its two products are equal.
// In quadruple precision (113 bits) the differences of doubles of nearby
// exponents and their products are exact, so a sliver that doubles would
// round to no area at all (a float STL's, from an export) is told apart
// from a face that truly has none.
using Quad = __float128;
std::array<Quad, 3> quadCross(const dvec3& a, const dvec3& b, const dvec3& c) {
  const Quad ux = Quad(b.x) - Quad(a.x), uy = Quad(b.y) - Quad(a.y), uz = Quad(b.z) - Quad(a.z);
  const Quad vx = Quad(c.x) - Quad(a.x), vy = Quad(c.y) - Quad(a.y), vz = Quad(c.z) - Quad(a.z);
  return {uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};
}

// Is x·y − z·w, each factor the difference of two doubles, surely not
// zero, by doubles alone? Each difference is within a unit roundoff u =
// 2⁻⁵³ of its exact value, each product then within 3u (and its own
// rounding), the difference within u more: the computed value is within
// 6u·(|xy| + |zw|) of the exact one (the standard error analysis of such
// expressions, as in Shewchuk's static filters), so one larger than 8u
// times that sum has the exact value's sign and is not zero. Tiny values,
// where underflow would break the bound, are left to the exact test.
bool surelyNonZero(double x, double y, double z, double w) {
  const double p = x * y, q = z * w;
  const double bound = 8.0 * 0x1p-53 * (std::abs(p) + std::abs(q));
  return bound > 0x1p-960 && std::abs(p - q) > bound;
}

}  // namespace

bool collinear(const dvec3& a, const dvec3& b, const dvec3& c) {
  // Most triangles are plainly not flat: decided in doubles (a mesh of
  // millions of faces spent a fifth of its load in quadruple precision).
  const dvec3 u = b - a, v = c - a;
  if (surelyNonZero(u.y, v.z, u.z, v.y) || surelyNonZero(u.z, v.x, u.x, v.z) ||
      surelyNonZero(u.x, v.y, u.y, v.x))
    return false;
  const std::array<Quad, 3> n = quadCross(a, b, c);
  return n[0] == 0 && n[1] == 0 && n[2] == 0;
}

dvec3 triangleNormal(const dvec3& a, const dvec3& b, const dvec3& c) {
  const dvec3 n = glm::cross(b - a, c - a);
  if (n != dvec3(0.0)) return glm::normalize(n);
  const std::array<Quad, 3> q = quadCross(a, b, c);
  Quad largest = 0;
  for (Quad x : q) largest = std::max(largest, x < 0 ? -x : x);
  if (largest == 0) return n;
  return glm::normalize(
      dvec3(double(q[0] / largest), double(q[1] / largest), double(q[2] / largest)));
}

int RayFrame::exactSignOfDifference(double a, double b, double c, double d) {
  double p = a * b, pe = std::fma(a, b, -p);
  double q = c * d, qe = std::fma(c, d, -q);
  double x[4], j, z;
  twoOneDiff(p, pe, qe, j, z, x[0]);
  twoOneDiff(j, z, q, x[3], x[2], x[1]);
  for (int i = 3; i >= 0; --i)
    if (x[i] != 0.0) return signOf(x[i]);
  return 0;
}

bool usableRay(const Ray& ray) {
  auto finite = [](const dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
  };
  return finite(ray.origin) && finite(ray.dir) && ray.dir != dvec3(0.0);
}

Bvh triangleBvh(const std::vector<dvec3>& points, const std::vector<MeshTriangle>& triangles,
                const Bounds& bounds) {
  const dvec3 size = bounds.size();
  const double extent = std::max({size.x, size.y, size.z});
  double scale = std::max({extent, glm::length(bounds.lo), glm::length(bounds.hi)});
  dvec3 pad(1e-9 * scale);
  std::vector<Bounds> boxes(triangles.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    for (std::uint32_t v : triangles[i]) boxes[i].include(points[v]);
    boxes[i].lo -= pad;
    boxes[i].hi += pad;
  }
  return Bvh(boxes);
}

}  // namespace csgray::detail
