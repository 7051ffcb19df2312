// A torus about the z axis: the points whose distance from the circle of
// radius R in the xy plane (the core circle) is at most r, that is
// (√(x² + y²) − R)² + z² ≤ r². Any R >= 0 is a solid: R > r is the ring
// torus; R = r closes the hole to a point (horn torus); R < r makes the tube
// overlap itself across the axis (spindle torus, whose dimples at the poles
// are part of the surface and whose inner lemon is solid); R = 0 is a ball.
#pragma once

#include "primitives/primitive_shape.h"

namespace csgray::detail {

// A torus's sizes in units of its bounding radius, as the conditioning of
// every ray (torus.cpp) uses them: divided once, not per ray.
struct TorusInUnits {
  double size;  // R + r, the bounding sphere's radius
  double R, r;  // the radii in units of size
  double slab;  // the half-height r, grown by the solver's margin
  double hole;  // the hole's radius R − r, shrunk by the margin
};

class Torus : public PrimitiveShape<Torus> {
 public:
  Torus(double majorRadius, double minorRadius);
  double majorRadius() const { return R_; }
  double minorRadius() const { return r_; }
  std::string kind() const override { return "torus"; }

  bool firstBoundaryCutsShort() const override { return true; }

 protected:
  void objectSpans(const Ray& ray, SpanList& out) const override;
  void objectSpansToFirstBoundary(const Ray& ray, SpanList& out) const override;
  bool objectMeetsWindow(const Ray& ray, SpanList& scratch) const override;
  bool objectContains(const dvec3& p) const override;
  dvec3 objectNormal(const dvec3& p, int face) const override;
  Bounds objectBounds() const override;
  TriangleMesh objectTessellate(double tolerance, const Bounds& region) const override;

 private:
  // objectSpans, or with firstOnly only as far as the first boundary.
  void spansOf(const Ray& ray, bool firstOnly, SpanList& out) const;

  double R_, r_;
  TorusInUnits inUnits_;
};

}  // namespace csgray::detail
