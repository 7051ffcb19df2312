// OpenSCAD's rotate_extrude of a region, exact: the region, drawn in the
// profile plane (u, v) = (ρ, z) with ρ = √(x² + y²) >= 0, turned about the
// z axis. Every point of the region must have u >= 0. With an angle under
// 360° only the wedge from +x counter-clockwise (seen from +z) over that
// angle is kept; its two flat faces are faces of the primitive.
//
// A ray's curve in the profile plane is (ρ(t), z(t)) with ρ² quadratic in
// t: a segment's line aρ + bz = c becomes a²ρ² = (c − bz)², a quadratic
// (cones, cylinders, flat rings), and an arc's ellipse, with its odd
// powers of ρ moved to one side and squared, a quartic (tori, spheres and
// their elliptic kin); the roots of the squared equations that are not the
// edge's own (those of the profile mirrored in the axis) are dropped
// (profile_sweep.h). Faces: kSweepStartFace the wedge's face at angle 0,
// kSweepEndFace the one at its angle, then one per edge of the region.
#pragma once

#include <optional>

#include "primitives/primitive_shape.h"
#include "primitives/profile_sweep.h"
#include "primitives/profile_sweep_tessellation.h"

namespace csgray::detail {

// rotate_extrude as users give it: an angle in (0, 360] turns the region
// counter-clockwise seen from +z; one in [−360, 0) clockwise, as
// OpenSCAD's does (the turn of its size mirrored in the xz plane). Throws
// std::invalid_argument for an angle of 0 or past a turn either way, and
// what Revolution throws.
SolidPtr revolutionSolid(RegionPtr region, double angleDegrees);

class Revolution : public PrimitiveShape<Revolution>, public RegionSweep {
 public:
  // Throws std::invalid_argument for an angle not in (0, 360], or a
  // region with points at u < 0 (crossing the axis), or a bad region.
  Revolution(RegionPtr region, double angleDegrees);

  const RegionPtr& region() const { return swept_->region(); }
  double angleDegrees() const { return angleDegrees_; }
  std::string kind() const override { return "rotate_extrude"; }
  const RegionPtr& sweptRegion() const override { return region(); }
  SolidPtr sweepOf(RegionPtr region) const override;

  bool firstBoundaryCutsShort() const override { return true; }

  // For export: the steps of a full turn whose rings put their points at
  // ρ·(cos, sin)(360°·k/steps), as this turn's mesh at `tolerance` (in its
  // own frame) does over its angle (a turn through a share of 360°, p/q
  // with q ≤ 24, takes a multiple of p steps: those of a whole turn of
  // steps·q/p), if the turn has a wall at ρ = radius (a loop's edge along
  // the axis there) that overlaps z0..z1; nothing otherwise. A cylinder
  // standing in that wall takes those rings (export/swept_rims.h).
  std::optional<int> wallSteps(double radius, double z0, double z1, double tolerance) const;

  // For export: the polygon a circle of the region (its centre in the
  // profile plane and its radius) takes in this turn's mesh at `tolerance`
  // (in its own frame), where one of the mesh's loops is that circle's
  // inscribed regular polygon: its sides, and the angle about the centre
  // of one of its points. Nothing otherwise. A cylinder standing on an end
  // face of the turn, on that circle, takes the same polygon
  // (export/swept_rims.h), so that the two meet point for point.
  struct CircleLoop {
    int segments;
    double phase;
  };
  std::optional<CircleLoop> circleLoop(const dvec2& center, double radius, double tolerance) const;

 protected:
  void objectSpans(const Ray& ray, SpanList& out) const override;
  void objectSpansToFirstBoundary(const Ray& ray, SpanList& out) const override;
  bool objectContains(const dvec3& p) const override;
  dvec3 objectNormal(const dvec3& p, int face) const override;
  Bounds objectBounds() const override;
  TriangleMesh objectTessellate(double tolerance, const Bounds& region) const override;

 private:
  // The loops as the mesh takes them, and its steps about the axis.
  struct Turned {
    SweepLoops loops;
    int steps;
    bool pinched;  // the region touches itself at a point
  };
  Turned turned(double tolerance) const;
  bool inWedge(const dvec3& p) const;
  // objectSpans, or with firstOnly only as far as the first boundary
  // (SweptRegion::spans).
  void spansOf(const Ray& ray, bool firstOnly, SpanList& out) const;

  std::shared_ptr<const SweptRegion> swept_;
  double angleDegrees_, angle_;  // angle_ in radians
  bool fullTurn_;
};

}  // namespace csgray::detail
