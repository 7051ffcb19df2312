// The canonical form of a quadric: a rigid frame in which pᵀMp becomes a sum
// of squares plus at most one linear term (the principal-axes theorem; Hilbert
// and Cohn-Vossen, Geometry and the Imagination, §3; docs/theory.md).
// The tessellation of Quadric reads the kind of surface off this form.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "engine/ray.h"

namespace csgray::detail {

// p = origin + axes · y (axes' columns are orthonormal, in either handedness)
// and pᵀMp = scale · (Σ λᵢ yᵢ² + 2 linear · y₂ + constant) with scale > 0,
// so the solid is the same with the canonical form in place of M.
//
// Conventions, so that y₂ is the axis a tessellation runs along:
// - the largest |λᵢ| is 1; eigenvalues negligible next to it are exactly 0;
// - linear > 0 only when λ₂ = 0, and then constant = 0 (the translation
//   along y₂ absorbed it): a paraboloid, parabolic cylinder or half-space;
// - otherwise linear = 0, non-zero λ come first, except that with three of
//   them y₂ is the one whose sign differs from the other two's (or, with one
//   sign, the one of least |λ|, the longest axis of an ellipsoid).
struct QuadricForm {
  glm::dmat3 axes{1.0};
  dvec3 origin{0.0};
  dvec3 lambda{0.0};
  double linear = 0.0;
  double constant = 0.0;
  double scale = 1.0;

  // The canonical form at canonical coordinates y.
  double at(const dvec3& y) const {
    return lambda.x * y.x * y.x + lambda.y * y.y * y.y + lambda.z * y.z * y.z + 2.0 * linear * y.z +
           constant;
  }
  dvec3 toObject(const dvec3& y) const { return origin + axes * y; }
  dvec3 toCanonical(const dvec3& p) const { return glm::transpose(axes) * (p - origin); }
};

// The eigenvalues and unit eigenvectors (columns) of a symmetric 3×3 matrix,
// by the cyclic Jacobi method.
void symmetricEigen(const glm::dmat3& a, dvec3& values, glm::dmat3& vectors);

// M must be symmetric and not zero (as Quadric's constructor ensures).
QuadricForm canonicalQuadricForm(const glm::dmat4& m);

}  // namespace csgray::detail
