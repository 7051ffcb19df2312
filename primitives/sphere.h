// A ball of radius r about the object origin. Ellipsoids are spheres under a
// non-uniform scale (see script ellipsoid{}), which stays exact.
#pragma once

#include "primitives/primitive_shape.h"

namespace csgray::detail {

class Sphere : public PrimitiveShape<Sphere> {
 public:
  explicit Sphere(double radius);
  std::string kind() const override { return "sphere"; }
  double radius() const { return radius_; }

 protected:
  void objectSpans(const Ray& ray, SpanList& out) const override;
  bool objectContains(const dvec3& p) const override;
  dvec3 objectNormal(const dvec3& p, int face) const override;
  Bounds objectBounds() const override;
  Bounds objectBoundsUnder(const Affine& worldFromObject) const override;
  TriangleMesh objectTessellate(double tolerance, const Bounds& region) const override;

 private:
  double radius_;
};

}  // namespace csgray::detail
