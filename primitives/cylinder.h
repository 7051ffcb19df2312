// A capped cylinder or cone frustum along +z from z = 0 to z = h, with
// radius r1 at the bottom and r2 at the top (OpenSCAD's cylinder). Either
// radius may be zero for a cone, not both. Faces: 0 side, 1 bottom, 2 top.
#pragma once

#include <memory>
#include <optional>

#include "primitives/primitive_shape.h"
#include "tessellation/tessellation.h"

namespace csgray::detail {

class Cylinder : public PrimitiveShape<Cylinder> {
 public:
  Cylinder(double r1, double r2, double height);
  double r1() const { return r1_; }
  double r2() const { return r2_; }
  double height() const { return height_; }
  std::string kind() const override { return r1_ == r2_ ? "cylinder" : "cone"; }
  // For export: this cylinder with both rims on `polygon` instead of the
  // polygon of its radius (export/swept_rims.h: a full turn's ring).
  std::shared_ptr<const Cylinder> withPolygon(const CirclePolygon& polygon) const;
  // This frustum with its radii swapped (r2 at the bottom), in the same
  // frame and of the same material: turned upside down, the same solid
  // again (export/upright_cylinders.h).
  std::shared_ptr<const Cylinder> withRadiiSwapped() const;

 protected:
  void objectSpans(const Ray& ray, SpanList& out) const override;
  bool objectContains(const dvec3& p) const override;
  dvec3 objectNormal(const dvec3& p, int face) const override;
  Bounds objectBounds() const override;
  Bounds objectBoundsUnder(const Affine& worldFromObject) const override;
  TriangleMesh objectTessellate(double tolerance, const Bounds& region) const override;

 private:
  double radiusAt(double z) const { return r1_ + slope_ * z; }
  TriangleMesh rimsAndSides(const CirclePolygon rim[2], double tolerance) const;

  double r1_, r2_, height_;
  double slope_;                          // dr/dz
  std::optional<CirclePolygon> polygon_;  // withPolygon's
};

}  // namespace csgray::detail
