#include "engine/affine.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>
#include <stdexcept>

namespace csgray::detail {

Affine::Affine(const glm::dmat4& worldFromObject)
    : worldFromObject_(worldFromObject),
      objectFromWorld_(glm::inverse(worldFromObject)),
      // Normals transform with the inverse transpose of the linear part.
      normalFromObject_(glm::transpose(glm::dmat3(objectFromWorld_))),
      identity_(worldFromObject == glm::dmat4(1.0)),
      translation_(glm::dmat3(worldFromObject) == glm::dmat3(1.0)) {}

Affine Affine::fromMatrix(const glm::dmat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) throw std::invalid_argument("transform has a non-finite entry");
  if (m[0][3] != 0.0 || m[1][3] != 0.0 || m[2][3] != 0.0 || m[3][3] != 1.0)
    throw std::invalid_argument("transform is not affine (last row must be 0 0 0 1)");
  // Singular relative to the scale of the matrix: det of the 3x3 part
  // against the product of its column lengths (Hadamard's bound).
  glm::dmat3 linear(m);
  double det = glm::determinant(linear);
  double bound = glm::length(linear[0]) * glm::length(linear[1]) * glm::length(linear[2]);
  if (!(std::abs(det) > 1e-12 * bound)) throw std::invalid_argument("transform is singular");
  return Affine(m);
}

Affine Affine::translation(const dvec3& offset) {
  return fromMatrix(glm::translate(glm::dmat4(1.0), offset));
}

Affine Affine::scaling(const dvec3& factors) {
  return fromMatrix(glm::scale(glm::dmat4(1.0), factors));
}

Affine Affine::rotation(double radians, const dvec3& axis) {
  if (!std::isfinite(radians))
    throw std::invalid_argument("rotation needs a finite angle and a non-zero axis");
  // cos and sin of a multiple of 90° come out as 6e-17 instead of 0: they
  // are made exact, so that a part turned by 90° keeps its faces on exact
  // planes (and flush faces flush, for the exporter's booleans).
  double c = std::cos(radians), s = std::sin(radians);
  if (std::abs(c) < 1e-15) c = 0.0, s = s > 0.0 ? 1.0 : -1.0;
  if (std::abs(s) < 1e-15) s = 0.0, c = c > 0.0 ? 1.0 : -1.0;
  return rotation(c, s, axis);
}

Affine Affine::rotation(double c, double s, const dvec3& axis) {
  double len = glm::length(axis);
  if (!(len > 0.0) || !std::isfinite(len) || !std::isfinite(c) || !std::isfinite(s))
    throw std::invalid_argument("rotation needs a finite angle and a non-zero axis");
  // Rodrigues' formula R = cI + s[k]× + (1 − c)kkᵀ.
  const dvec3 k = axis / len;
  glm::dmat4 m(1.0);
  for (int col = 0; col < 3; ++col)
    for (int row = 0; row < 3; ++row) m[col][row] = (1.0 - c) * k[row] * k[col];
  // About a coordinate axis, that axis's own entry c + (1 − c)·1 rounds
  // to a neighbour of 1 for some angles (95°, 105°, 125°, ...), which
  // would tilt a hole turned about the plate's axis off the plate's face;
  // it is exactly 1.
  for (int i = 0; i < 3; ++i) m[i][i] = k[i] * k[i] == 1.0 ? 1.0 : m[i][i] + c;
  // [k]× has rows (0, −kz, ky), (kz, 0, −kx), (−ky, kx, 0); glm is
  // column-major, m[col][row].
  m[1][0] -= s * k.z, m[2][0] += s * k.y;
  m[0][1] += s * k.z, m[2][1] -= s * k.x;
  m[0][2] -= s * k.y, m[1][2] += s * k.x;
  return fromMatrix(m);
}

Affine Affine::mirror(const dvec3& normal) {
  double len = glm::length(normal);
  if (!(len > 0.0) || !std::isfinite(len))
    throw std::invalid_argument("mirror needs a non-zero finite normal");
  dvec3 n = normal / len;
  // Householder reflection I - 2 n nᵀ.
  glm::dmat4 m(1.0);
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) m[c][r] -= 2.0 * n[r] * n[c];
  return fromMatrix(m);
}

Affine Affine::then(const Affine& outer) const {
  return fromMatrix(outer.worldFromObject_ * worldFromObject_);
}

dvec3 Affine::normalToWorld(const dvec3& n) const {
  return glm::normalize(translation_ ? n : normalFromObject_ * n);
}

}  // namespace csgray::detail
