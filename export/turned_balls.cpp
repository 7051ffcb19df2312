#include "export/turned_balls.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

namespace csgray::detail {

namespace {

// How far a turn's matrix, composed in doubles, may stray from
// orthonormal: a few units in the last place of each product.
constexpr double kRounding = 1e-12;

// The one length of the columns of m where m is a scale times a swap and
// reversal of the axes (each column along a coordinate axis), or 0.
double axisAlignedScale(const glm::dmat3& m) {
  double scale = 0.0;
  for (int c = 0; c < 3; ++c) {
    int nonZero = 0;
    for (int r = 0; r < 3; ++r)
      if (m[c][r] != 0.0) {
        ++nonZero;
        if (scale != 0.0 && std::abs(m[c][r]) != scale) return 0.0;
        scale = std::abs(m[c][r]);
      }
    if (nonZero != 1) return 0.0;
  }
  return scale;
}

bool orthonormal(const glm::dmat3& m) {
  for (int c = 0; c < 3; ++c) {
    if (std::abs(glm::dot(m[c], m[c]) - 1.0) > kRounding) return false;
    if (std::abs(glm::dot(m[c], m[(c + 1) % 3])) > kRounding) return false;
  }
  return true;
}

}  // namespace

std::shared_ptr<const Sphere> unturnedBall(const Sphere& ball, const Affine& frame) {
  const glm::dmat4& m = frame.worldFromObject();
  const glm::dmat3 linear(m);
  double scale = axisAlignedScale(linear);
  if (scale == 0.0 && orthonormal(linear)) scale = 1.0;
  if (scale == 0.0 || linear == glm::dmat3(scale)) return nullptr;
  glm::dmat4 unturned(scale);
  unturned[3] = m[3];
  return std::static_pointer_cast<const Sphere>(ball.withFrame(Affine::fromMatrix(unturned)));
}

}  // namespace csgray::detail
