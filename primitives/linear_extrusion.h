// OpenSCAD's linear_extrude of a region, exact: the points (x, y, z) with
// z in [z0, z0 + h] (z0 = 0, or −h/2 centred) whose image in the profile
// plane lies in the region. At the fraction ζ = (z − z0)/h of the height
// the profile is the region turned by −twist·ζ (a positive twist turns
// clockwise seen from +z, OpenSCAD's convention) and then scaled by
// σ(ζ) = 1 + (s − 1)·ζ on each axis: p = S(ζ)·Rot(−twist·ζ)·u.
//
// Sides: without twist and with a uniform scale a segment sweeps a plane
// and an arc a cone (or cylinder), so a ray meets them where a linear or
// quadratic equation vanishes; a non-uniform scale makes them ruled
// quadratic patches and quartic surfaces; a twist makes them helicoids,
// whose crossings are isolated numerically on bounded intervals
// (docs/architecture.md, "Sweeps"). Faces: kSweepStartFace the bottom cap,
// kSweepEndFace the top, then one per edge of the region (profile_sweep.h).
#pragma once

#include <optional>
#include <vector>

#include "primitives/primitive_shape.h"
#include "primitives/profile_sweep.h"
#include "profile/region_evaluation.h"

namespace csgray::detail {

class LinearExtrusion : public PrimitiveShape<LinearExtrusion>, public RegionSweep {
 public:
  // A twist beyond this many degrees is refused: more turns than any part
  // can show, and the numeric search's work grows with them.
  static constexpr double kMaxTwistDegrees = 360.0 * 1000.0;

  // Throws std::invalid_argument for a height that is not a positive
  // finite number, a twist that is not finite or beyond kMaxTwistDegrees,
  // a scale that is negative or not finite, or a bad region.
  LinearExtrusion(RegionPtr region, double height, bool center, double twistDegrees, dvec2 scale);

  const RegionPtr& region() const { return swept_->region(); }
  double height() const { return height_; }
  double bottom() const { return z0_; }
  double twistDegrees() const { return twistDegrees_; }
  dvec2 scale() const { return scale_; }
  std::string kind() const override { return "linear_extrude"; }
  const RegionPtr& sweptRegion() const override { return region(); }
  SolidPtr sweepOf(RegionPtr region) const override;

  // Straight: no twist, and a scale of 1 (its sides are prisms).
  bool prism() const { return twist_ == 0.0 && scale_.x == 1.0 && scale_.y == 1.0; }
  // The region's loops as their corners (each loop's points in order, the
  // first not repeated) where every edge is a segment and the sides are
  // planes (no twist, one scale on both axes): a polyhedron's, for hulls
  // and flat cutters. Nothing for a curved region or other sides.
  std::optional<std::vector<std::vector<dvec2>>> polygonLoops() const;
  // A copy whose export cuts the region's circles that are among `rims`
  // (in its plane) on those cylinders' rim polygons (flatten()), as a
  // prism: the exporter gives it the circles that the part's cylinders
  // stand on (export/swept_rims.h).
  std::shared_ptr<const LinearExtrusion> withRims(std::vector<CircleRim> rims) const;

  // The point of the profile plane that p (object space) lies over, and
  // whether the extrusion holds p.
  dvec2 profilePoint(const dvec3& p) const;

  // Only a path of many pieces (a twist, a scale other in x than in y)
  // stops at the first boundary.
  bool firstBoundaryCutsShort() const override { return twist_ != 0.0 || scale_.x != scale_.y; }

 protected:
  void objectSpans(const Ray& ray, SpanList& out) const override;
  void objectSpansToFirstBoundary(const Ray& ray, SpanList& out) const override;
  bool objectContains(const dvec3& p) const override;
  dvec3 objectNormal(const dvec3& p, int face) const override;
  Bounds objectBounds() const override;
  TriangleMesh objectTessellate(double tolerance, const Bounds& region) const override;

 private:
  // objectSpans, or with firstOnly only as far as the first boundary
  // (SweptRegion::spans).
  void spansOf(const Ray& ray, bool firstOnly, SpanList& out) const;

  std::shared_ptr<const SweptRegion> swept_;  // shared by copies (transforms, materials)
  double height_, z0_;
  double twistDegrees_, twist_;  // twist_ in radians
  dvec2 scale_;
  std::vector<CircleRim> rims_;  // withRims; empty for a part's own
};

}  // namespace csgray::detail
