// The general quadric solid {p : pᵀ M p <= 0} for homogeneous p = (x, y, z, 1)
// and a symmetric 4×4 matrix M (docs/theory.md, "Quadrics"). Most
// quadrics are unbounded; their spans may start or end at infinity.
#pragma once

#include <glm/mat4x4.hpp>

#include "primitives/primitive_shape.h"

namespace csgray::detail {

class Quadric : public PrimitiveShape<Quadric> {
 public:
  explicit Quadric(const glm::dmat4& m);
  const glm::dmat4& matrix() const { return m_; }
  std::string kind() const override { return "quadric"; }

 protected:
  void objectSpans(const Ray& ray, SpanList& out) const override;
  bool objectContains(const dvec3& p) const override;
  dvec3 objectNormal(const dvec3& p, int face) const override;
  Bounds objectBounds() const override;
  // A closed mesh of the solid within a box a little larger than the region
  // (see quadric_tessellation.cpp); throws std::invalid_argument where that cannot be a
  // 2-manifold (a cone's apex or two crossing planes inside the region) and
  // for the outside of an ellipsoid, elliptic cylinder, hyperboloid or cone.
  TriangleMesh objectTessellate(double tolerance, const Bounds& region) const override;

 private:
  glm::dmat4 m_;
};

}  // namespace csgray::detail
