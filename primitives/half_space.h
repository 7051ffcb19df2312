// The closed half-space {p : n·p <= offset}: an unbounded solid, mostly
// useful to cut other solids.
#pragma once

#include "primitives/primitive_shape.h"

namespace csgray::detail {

class HalfSpace : public PrimitiveShape<HalfSpace> {
 public:
  HalfSpace(const dvec3& normal, double offset);
  std::string kind() const override { return "half_space"; }
  const dvec3& planeNormal() const { return normal_; }  // unit
  double planeOffset() const { return offset_; }

 protected:
  void objectSpans(const Ray& ray, SpanList& out) const override;
  bool objectContains(const dvec3& p) const override;
  dvec3 objectNormal(const dvec3& p, int face) const override;
  Bounds objectBounds() const override;
  TriangleMesh objectTessellate(double tolerance, const Bounds& region) const override;

 private:
  dvec3 normal_;  // unit
  double offset_;
};

}  // namespace csgray::detail
