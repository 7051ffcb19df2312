// B-spline curves in the plane, as a DXF drawing's SPLINE entity gives them
// (degree, knot vector, control points), turned into the Bézier edges that
// profiles hold: over each span between two knots, the span's ends are
// inserted until each is repeated `degree` times (Boehm, "Inserting new
// knots into B-spline curves", Computer-Aided Design 12, 1980), after which
// the span's control points are a Bézier curve's (Piegl and Tiller, "The
// NURBS Book", 2nd ed., section 5.4, "decomposing curves"). The curve is
// kept exactly, not flattened.
#pragma once

#include <vector>

#include "profile/profile.h"

namespace csgray::detail {

struct BSpline {
  int degree = 3;
  std::vector<double> knots;    // non-decreasing, controls.size() + degree + 1 of them
  std::vector<dvec2> controls;  // at least degree + 1
};

// The curve over its domain [knots[degree], knots[controls.size()]] as
// segments (degree 1), quadratic (2) or cubic (3) Bézier edges, in order.
// Throws std::invalid_argument naming what is wrong (a degree outside 1 to
// 3, a knot count that does not fit, knots that decrease, an empty domain).
std::vector<ProfileEdge> bSplineEdges(const BSpline& spline);

}  // namespace csgray::detail
