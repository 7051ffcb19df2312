// A blob (POV-Ray's blob, after Wyvill's soft objects): balls whose
// fields add up, the solid where the sum reaches a threshold. Ball i adds
//   strength_i · (1 − d²/r_i²)²   within its radius r_i (d the distance
// from its centre), nothing beyond, so the field and its slope are
// continuous and two balls near each other melt into one smooth shape.
// A negative strength takes away. Inside: the sum >= threshold.
#pragma once

#include <vector>

#include "primitives/primitive_shape.h"

namespace csgray::detail {

// The threshold when none is given: a lone ball of strength 1 is then a
// ball of radius r·√(1 − √0.5) ≈ 0.54·r, and two of them a radius apart
// melt into one.
inline constexpr double kDefaultBlobThreshold = 0.5;

struct BlobBall {
  dvec3 center;
  double radius;
  double strength;
};

class Blob : public PrimitiveShape<Blob> {
 public:
  // The most balls a blob takes: each ray tests every ball.
  static constexpr std::size_t kMaxBalls = 10'000;

  Blob(std::vector<BlobBall> balls, double threshold);
  const std::vector<BlobBall>& balls() const { return balls_; }
  double threshold() const { return threshold_; }
  std::string kind() const override { return "blob"; }

  bool firstBoundaryCutsShort() const override { return true; }

  // The field minus the threshold at an object-space point: <= 0 inside.
  double excess(const dvec3& p) const;
  // The gradient of the field at an object-space point (pointing in).
  dvec3 fieldGradient(const dvec3& p) const;

 protected:
  void objectSpans(const Ray& ray, SpanList& out) const override;
  void objectSpansToFirstBoundary(const Ray& ray, SpanList& out) const override;
  bool objectContains(const dvec3& p) const override;
  dvec3 objectNormal(const dvec3& p, int face) const override;
  Bounds objectBounds() const override;
  TriangleMesh objectTessellate(double tolerance, const Bounds& region) const override;

 private:
  void spansOf(const Ray& ray, bool firstOnly, SpanList& out) const;

  std::vector<BlobBall> balls_;
  double threshold_;
  dvec3 center_;  // of the ball that holds every ball of positive strength
  double size_;   // its radius: the ray's conditioning unit
};

}  // namespace csgray::detail
