// An axis-aligned box from the object origin to size (OpenSCAD's cube).
// Faces are numbered axis·2 + (0 for the low side, 1 for the high side).
#pragma once

#include "primitives/primitive_shape.h"

namespace csgray::detail {

class Box : public PrimitiveShape<Box> {
 public:
  explicit Box(const dvec3& size);
  const dvec3& size() const { return size_; }
  std::string kind() const override { return "box"; }

 protected:
  void objectSpans(const Ray& ray, SpanList& out) const override;
  bool objectContains(const dvec3& p) const override;
  dvec3 objectNormal(const dvec3& p, int face) const override;
  Bounds objectBounds() const override;
  TriangleMesh objectTessellate(double tolerance, const Bounds& region) const override;

 private:
  dvec3 size_;
};

}  // namespace csgray::detail
