// B-spline curves in the plane, as a DXF drawing's SPLINE entity gives them
// (degree, knot vector, control points), turned into the Bézier edges that
// profiles hold: over each span between two knots, the span's ends are
// inserted until each is repeated `degree` times (Boehm, "Inserting new
// knots into B-spline curves", Computer-Aided Design 12, 1980), after which
// the span's control points are a Bézier curve's (Piegl and Tiller, "The
// NURBS Book", 2nd ed., section 5.4, "decomposing curves"). The curve is
// kept exactly, not flattened. A rational spline (control points of
// different weights) is decomposed the same way in homogeneous
// coordinates; of degree 2, its pieces are conics, kept exactly as the
// arcs of ellipses (circles among them) or parabolas they are, which is
// how drawing programs write circles and ellipses as splines.
#pragma once

#include <vector>

#include "profile/profile.h"

namespace csgray::detail {

struct BSpline {
  int degree = 3;
  std::vector<double> knots;    // non-decreasing, controls.size() + degree + 1 of them
  std::vector<dvec2> controls;  // at least degree + 1
  // One per control point, all > 0; none (or all alike) for a spline that
  // is not rational.
  std::vector<double> weights;
};

// The curve over its domain [knots[degree], knots[controls.size()]] as
// segments (degree 1), quadratic (2) or cubic (3) Bézier edges, in order;
// a rational spline's pieces of degree 2 as arcs of ellipses (a conic
// with its middle weight below the geometric mean of its end weights) or
// quadratic Bézier edges (a parabola: equal to it). Throws
// std::invalid_argument naming what is wrong (a degree outside 1 to 3, a
// knot count that does not fit, knots that decrease, an empty domain,
// weights that do not fit or are not > 0, a rational spline of degree 3
// or with a piece of a hyperbola, which profiles cannot hold exactly).
std::vector<ProfileEdge> bSplineEdges(const BSpline& spline);

}  // namespace csgray::detail
