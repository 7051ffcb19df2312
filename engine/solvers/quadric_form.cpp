#include "engine/solvers/quadric_form.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <vector>

namespace csgray::detail {

namespace {

// Below this fraction of the largest term a coefficient is rounding noise of
// a rotated or translated matrix, not a feature of the surface.
constexpr double kNegligible = 1e-12;

}  // namespace

void symmetricEigen(const glm::dmat3& m, dvec3& values, glm::dmat3& vectors) {
  // Cyclic Jacobi (Golub and Van Loan, Matrix Computations, 4th ed., §8.5.2;
  // the rotation as in Numerical Recipes, 3rd ed., §11.1): each rotation
  // A ← JᵀAJ zeroes one off-diagonal pair; a sweep over the three pairs
  // converges quadratically. a[r][c] is row r, column c.
  double a[3][3], v[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      a[r][c] = m[c][r];
      v[r][c] = r == c ? 1.0 : 0.0;
    }
  for (int sweep = 0; sweep < 64; ++sweep) {
    double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    double diagonal = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
    if (off == 0.0 || off <= 1e-36 * diagonal) break;
    for (int p = 0; p < 2; ++p) {
      for (int q = p + 1; q < 3; ++q) {
        if (a[p][q] == 0.0) continue;
        const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
        const double t = (theta >= 0.0 ? 1.0 : -1.0) / (std::abs(theta) + std::hypot(theta, 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        // A ← A J, then A ← Jᵀ A, with J the identity but J_pp = J_qq = c,
        // J_pq = s, J_qp = −s; the eigenvectors collect V ← V J.
        for (int r = 0; r < 3; ++r) {
          const double arp = a[r][p], arq = a[r][q];
          a[r][p] = c * arp - s * arq;
          a[r][q] = s * arp + c * arq;
          const double vrp = v[r][p], vrq = v[r][q];
          v[r][p] = c * vrp - s * vrq;
          v[r][q] = s * vrp + c * vrq;
        }
        for (int col = 0; col < 3; ++col) {
          const double apc = a[p][col], aqc = a[q][col];
          a[p][col] = c * apc - s * aqc;
          a[q][col] = s * apc + c * aqc;
        }
        a[p][q] = a[q][p] = 0.0;
      }
    }
  }
  for (int i = 0; i < 3; ++i) {
    values[i] = a[i][i];
    vectors[i] = glm::normalize(dvec3(v[0][i], v[1][i], v[2][i]));
  }
}

QuadricForm canonicalQuadricForm(const glm::dmat4& m) {
  // pᵀMp = pᵀAp + 2 b·p + w with A the 3×3 block, b the last column.
  const glm::dmat3 a(m);
  const dvec3 b(m[3]);
  const double w = m[3][3];
  dvec3 lambda;
  glm::dmat3 e;
  symmetricEigen(a, lambda, e);
  double largest = std::max({std::abs(lambda.x), std::abs(lambda.y), std::abs(lambda.z)});
  for (int i = 0; i < 3; ++i)
    if (std::abs(lambda[i]) <= kNegligible * largest) lambda[i] = 0.0;

  // In the eigenbasis p = E z: Σ λᵢ zᵢ² + 2 cᵢ zᵢ + w with c = Eᵀb.
  // Completing the square along each axis with λᵢ ≠ 0 moves the origin by
  // −cᵢ/λᵢ and leaves the constant w − Σ cᵢ²/λᵢ; the linear terms on the
  // zero axes add up to one vector n, which becomes the axis y₂.
  std::vector<int> nonzero, zero;
  for (int i = 0; i < 3; ++i) (lambda[i] != 0.0 ? nonzero : zero).push_back(i);
  QuadricForm form;
  double constant = w, constantSize = std::abs(w);
  dvec3 n(0.0);
  for (int i : nonzero) {
    const double c = glm::dot(e[i], b);
    form.origin -= (c / lambda[i]) * e[i];
    constant -= c * c / lambda[i];
    constantSize += c * c / std::abs(lambda[i]);
  }
  for (int i : zero) n += glm::dot(e[i], b) * e[i];
  const double nLength = glm::length(n);
  const bool linear = !zero.empty() && nLength > kNegligible * (glm::length(b) + largest);
  if (!linear && std::abs(constant) <= kNegligible * constantSize) constant = 0.0;

  // The order of the axes (see the header).
  std::array<int, 3> order{0, 1, 2};
  if (linear || nonzero.size() < 3) {
    int k = 0;
    for (int i : nonzero) order[k++] = i;
    for (int i : zero) order[k++] = i;
  } else {
    int positive = (lambda.x > 0) + (lambda.y > 0) + (lambda.z > 0);
    int odd = 0;
    if (positive == 3 || positive == 0) {
      for (int i = 1; i < 3; ++i)
        if (std::abs(lambda[i]) < std::abs(lambda[odd])) odd = i;
    } else {
      for (int i = 0; i < 3; ++i)
        if ((lambda[i] > 0) == (positive == 1)) odd = i;
    }
    order = {(odd + 1) % 3, (odd + 2) % 3, odd};
  }
  for (int k = 0; k < 3; ++k) {
    form.axes[k] = e[order[k]];
    form.lambda[k] = lambda[order[k]];
  }

  if (linear) {
    // y₂ along n; the other zero axes (if any) made orthogonal to it;
    // Σ λ y² + 2|n| y₂ + constant, with y₂ shifted to absorb the constant.
    const dvec3 axis = n / nLength;
    form.axes[2] = axis;
    if (nonzero.size() == 1) {
      dvec3 other = e[zero[0]] - glm::dot(e[zero[0]], axis) * axis;
      const dvec3 second = e[zero[1]] - glm::dot(e[zero[1]], axis) * axis;
      if (glm::length(second) > glm::length(other)) other = second;
      form.axes[1] = glm::normalize(other);
    } else if (nonzero.empty()) {
      // A plane: any two unit vectors across it.
      const dvec3 helper = std::abs(axis.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
      form.axes[0] = glm::normalize(glm::cross(axis, helper));
      form.axes[1] = glm::cross(axis, form.axes[0]);
    }
    form.origin -= (constant / (2.0 * nLength)) * axis;
    form.linear = nLength;
    constant = 0.0;
  }
  form.constant = constant;

  // A positive factor leaves the solid as it is.
  form.scale = largest > 0.0 ? largest : form.linear > 0.0 ? form.linear : std::abs(w);
  form.lambda /= form.scale;
  form.linear /= form.scale;
  form.constant /= form.scale;
  return form;
}

}  // namespace csgray::detail
