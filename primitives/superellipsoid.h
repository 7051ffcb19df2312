// A superellipsoid (Barr's superquadric ellipsoid, POV-Ray's
// superellipsoid): the points with
//   ((|x/a|^(2/e) + |y/b|^(2/e))^(e/n) + |z/c|^(2/n)) <= 1,
// a the radius along x, b along y, c along z; e shapes the sections across
// z (1 an ellipse, towards 0 a rectangle, 2 a diamond), n the profile along
// z alike. Both at 1 it is the ellipsoid; both small, a box with rounded
// edges. Exponents from kMinExponent to 2, where the solid is convex: above
// 2 it pinches in between its axes, which is not offered.
#pragma once

#include "primitives/primitive_shape.h"

namespace csgray::detail {

class Superellipsoid : public PrimitiveShape<Superellipsoid> {
 public:
  // The least exponent: its rounding is a thousandth of the radius wide,
  // below what a print or an image shows, while 2/e stays a power pow()
  // takes without overflow.
  static constexpr double kMinExponent = 1e-3;

  Superellipsoid(const dvec3& radii, double e, double n);
  const dvec3& radii() const { return radii_; }
  double e() const { return e_; }
  double n() const { return n_; }
  std::string kind() const override { return "superellipsoid"; }

  bool firstBoundaryCutsShort() const override { return true; }

  // The solid's gauge at a point of the unit shape (radii 1): the factor
  // by which the point lies out from the centre relative to the surface
  // along the same direction (1 on it, below inside), and its gradient,
  // which points outward. Exposed for the tessellation and the tests.
  struct Gauge {
    double value;
    dvec3 gradient;
  };
  Gauge unitGauge(const dvec3& p) const;

  // A power of the gauge, with what makes it cheaper: the power as a
  // whole number up to 64 (else 0), and k where it is 2^k (else −1).
  struct Power {
    double value;
    int whole, halvings;
    static Power of(double p);
  };

 protected:
  void objectSpans(const Ray& ray, SpanList& out) const override;
  void objectSpansToFirstBoundary(const Ray& ray, SpanList& out) const override;
  bool objectContains(const dvec3& p) const override;
  dvec3 objectNormal(const dvec3& p, int face) const override;
  Bounds objectBounds() const override;
  TriangleMesh objectTessellate(double tolerance, const Bounds& region) const override;

 private:
  // objectSpans, or with firstOnly only as far as the first boundary.
  void spansOf(const Ray& ray, bool firstOnly, SpanList& out) const;
  // The first point from `from` along `step` (a line in the unit shape's
  // space) where the gauge reaches 1, as a multiple of step no greater
  // than `length`; a negative number when the line does not get there.
  double firstInside(const dvec3& from, const dvec3& step, double length) const;

  dvec3 radii_;
  double e_, n_;
  Power p_, q_;   // 2/e and 2/n, the powers of the gauge
  double reach_;  // the radius of a ball about the centre that holds the unit shape
};

}  // namespace csgray::detail
