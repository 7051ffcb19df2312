#include "primitives/quadric.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <stdexcept>

#include "engine/solvers/quadratic.h"

namespace csgray::detail {

Quadric::Quadric(const glm::dmat4& m) : m_(m) {
  bool zero = true;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!std::isfinite(m[c][r]))
        throw std::invalid_argument("quadric: matrix has a non-finite entry");
      if (m[c][r] != m[r][c]) throw std::invalid_argument("quadric: matrix must be symmetric");
      if (m[c][r] != 0.0) zero = false;
    }
  }
  if (zero) throw std::invalid_argument("quadric: matrix is zero");
}

void Quadric::objectSpans(const Ray& ray, SpanList& out) const {
  // With e = (o, 1) and r = (d, 0): u = rᵀMr, v = 2 rᵀMe, w = eᵀMe (docs/theory.md).
  glm::dvec4 e(ray.origin, 1.0), r(ray.dir, 0.0);
  glm::dvec4 me = m_ * e;
  double u = glm::dot(r, m_ * r);
  double v = 2.0 * glm::dot(r, me);
  double w = glm::dot(e, me);
  Interval inside[2];
  int n = quadraticSublevel(u, v, w, inside);
  for (int i = 0; i < n; ++i) {
    const Interval& s = inside[i];
    if (s.hi < ray.tMin || s.lo > ray.tMax || s.lo == s.hi) continue;
    Boundary lo = std::isinf(s.lo) ? Boundary{s.lo, nullptr, 0, false} : boundary(s.lo);
    Boundary hi = std::isinf(s.hi) ? Boundary{s.hi, nullptr, 0, false} : boundary(s.hi);
    out.push_back(lo, hi);
  }
}

bool Quadric::objectContains(const dvec3& p) const {
  glm::dvec4 e(p, 1.0);
  return glm::dot(e, m_ * e) <= 0.0;
}

// The gradient of pᵀMp is 2(Mp)xyz; the factor 2 does not matter.
dvec3 Quadric::objectNormal(const dvec3& p, int) const { return dvec3(m_ * glm::dvec4(p, 1.0)); }

Bounds Quadric::objectBounds() const {
  // With M = [A b; bᵀ m] and A positive definite the solid is the ellipsoid
  // (p - c)ᵀ A (p - c) <= k, c = -A⁻¹b, k = bᵀA⁻¹b - m, whose half-extent
  // along axis i is sqrt(k·(A⁻¹)ᵢᵢ). Anything else is treated as unbounded.
  glm::dmat3 a(m_);
  dvec3 b(m_[3]);
  double minor1 = a[0][0];
  double minor2 = a[0][0] * a[1][1] - a[0][1] * a[1][0];
  double minor3 = glm::determinant(a);
  if (!(minor1 > 0.0 && minor2 > 0.0 && minor3 > 0.0)) return Bounds::everything();
  glm::dmat3 inv = glm::inverse(a);
  dvec3 c = -(inv * b);
  double k = glm::dot(b, inv * b) - m_[3][3];
  if (k < 0.0) return Bounds{};  // empty
  dvec3 half(std::sqrt(k * inv[0][0]), std::sqrt(k * inv[1][1]), std::sqrt(k * inv[2][2]));
  return {c - half, c + half};
}

}  // namespace csgray::detail
