// Bézier edges of profiles (the outlines of letters: TrueType fonts draw
// them with quadratic curves, OpenType CFF fonts with cubic ones). A curve
// of degree n with control points P0 ... Pn is
//   B(s) = Σ C(n, k)·(1 − s)^(n−k)·s^k·Pk,  s ∈ [0, 1]
// (Farin, "Curves and Surfaces for CAGD", 5th ed., ch. 4). What the plane
// asks of it is here: its points, bounds, area, the crossings of a
// horizontal half-line (even-odd containment) and polygons within a
// tolerance.
#pragma once

#include "profile/profile.h"

namespace csgray::detail {

// The curve in the power basis, B(s) = Σ c[k]·s^k: the form in which a
// line's equation along it is a polynomial in s.
struct BezierPolynomial {
  int degree = 2;
  dvec2 c[4] = {dvec2(0.0), dvec2(0.0), dvec2(0.0), dvec2(0.0)};

  dvec2 at(double s) const;
  dvec2 slope(double s) const;  // B'(s)
};

BezierPolynomial bezierPolynomial(const ProfileEdge& e);

// The point at s by de Casteljau's construction (stable, and exact at the
// ends).
dvec2 bezierPoint(const ProfileEdge& e, double s);

// Widens b to hold the curve: its ends and the extremes of x and y, where
// B'(s) has a zero component.
void includeBezier(ProfileBounds& b, const ProfileEdge& e);

// Does the half-line from p towards +x cross the curve an odd number of
// times? Profile::contains's half-open rule holds at the ends (an end at
// p's height counts for the side of the curve above it), so that a vertex
// shared with the next edge counts once.
bool bezierCrossesRight(const dvec2& p, const ProfileEdge& e);

// ∫ (x dy − y dx) along the curve, exactly: Green's theorem makes half the
// sum of these over a loop its signed area.
double bezierAreaTerm(const ProfileEdge& e);

// How many equal steps of s make a polygon within `tolerance` of the curve:
// linear interpolation strays by at most h²/8·max|B''| over steps of h, and
// |B''| <= n(n−1)·max|P(k) − 2P(k+1) + P(k+2)| (Wang's bound, in Filip,
// Magedson and Markot, "Surface algorithms using bounds on derivatives",
// CAGD 3, 1986).
int bezierSteps(const ProfileEdge& e, double tolerance);

// The parameter of the point of the curve nearest u (Newton's method on
// (B(s) − u)·B'(s) from the nearest of a few samples), in [0, 1]: for a
// point on the curve, where it is.
double nearestBezierParameter(const BezierPolynomial& b, const dvec2& u);

// The profile with each Bézier edge replaced by bezierSteps segments.
Profile bezierEdgesFlattened(const Profile& profile, double tolerance);

}  // namespace csgray::detail
