// The general quadric solid {p : pᵀ M p <= 0} for homogeneous p = (x, y, z, 1)
// and a symmetric 4×4 matrix M (seed 000, 17.3.3 and table 17.1). Most
// quadrics are unbounded; their spans may start or end at infinity.
#pragma once

#include <glm/mat4x4.hpp>

#include "modeler/primitive.h"

namespace csgray {

class Quadric : public Primitive {
 public:
  explicit Quadric(const glm::dmat4& m);
  const glm::dmat4& matrix() const { return m_; }
  std::string kind() const override { return "quadric"; }

 protected:
  void objectSpans(const Ray& ray, SpanList& out) const override;
  bool objectContains(const dvec3& p) const override;
  dvec3 objectNormal(const dvec3& p, int face) const override;
  Bounds objectBounds() const override;
  std::shared_ptr<Primitive> clone() const override { return std::make_shared<Quadric>(*this); }

 private:
  glm::dmat4 m_;
};

}  // namespace csgray
