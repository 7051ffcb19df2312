// Real roots of polynomials up to degree 4 by root isolation: the torus's
// solver where Newton's method on its convex pieces does not settle a ray
// (a near-tangency, a line through its axis), and the crossings of the
// sweeps (a line against a revolved conic, a Bézier curve, a twist).
//
// Closed forms (Ferrari's quartic, Cardano's cubic) lose most of their digits
// near multiple roots, which is exactly where a ray grazes a surface
// (Herbison-Evans, "Solving quartics and cubics for graphics", Graphics
// Gems V, 1995, discusses the cases and the cures). Instead the roots of the
// derivative, found the same way one degree down, split the interval into
// pieces on which the polynomial is monotone; each piece holds at most one
// root, which safeguarded Newton iteration finds (Numerical Recipes, 2nd ed.,
// 9.4, rtsafe: a Newton step when it stays inside the bracket and shrinks it
// fast enough, a bisection otherwise). This is the scheme of C. Yuksel,
// "High-Performance Polynomial Root Finding for Graphics", HPG 2022. The
// roots come out sorted, and the sign of the polynomial between them is
// known without evaluating it again.
#pragma once

#include <cmath>
#include <utility>

namespace csgray::detail {

// The root of a function in [lo, hi] whose sign changes once there:
// f(t) returns {value, slope}; "inside" means value <= 0, and loInside says
// which side lo is on (hi is on the other). The bracket shrinks around the
// change of sign until it is tolerance wide or a Newton step converges;
// every iterate stays in the bracket, so the result does too.
template <class F>
double bracketedRoot(const F& f, double lo, double hi, bool loInside, double tolerance) {
  double x = 0.5 * (lo + hi);
  double stepBefore = hi - lo;
  for (int i = 0; i < 200; ++i) {
    auto [value, slope] = f(x);
    if (value == 0.0) return x;
    if ((value <= 0.0) == loInside) {
      lo = x;
    } else {
      hi = x;
    }
    if (!(hi - lo > tolerance)) return 0.5 * (lo + hi);
    double next = x - value / slope;
    // Newton only when it lands strictly inside the bracket and at least
    // halves the step before last (rtsafe's guard against slow convergence).
    bool newton = next > lo && next < hi && 2.0 * std::abs(next - x) <= stepBefore;
    if (!newton) next = 0.5 * (lo + hi);
    double step = std::abs(next - x);
    if (newton && step <= 0.5 * tolerance) return next;
    if (next <= lo || next >= hi) return x;  // no double lies between: converged
    stepBefore = step;
    x = next;
  }
  return 0.5 * (lo + hi);
}

// p(t) = c[0] + c[1]·t + ... + c[n]·tⁿ.
inline double polynomialValue(const double* c, int n, double t) {
  double v = c[n];
  for (int i = n - 1; i >= 0; --i) v = v * t + c[i];
  return v;
}

// p'(t), the same way.
inline double polynomialSlope(const double* c, int n, double t) {
  double v = n * c[n];
  for (int i = n - 1; i >= 1; --i) v = v * t + i * c[i];
  return v;
}

// The boundaries, in [lo, hi] and sorted, of the set {t : p(t) <= 0} for the
// polynomial of degree n <= 4 with coefficients c[0..n] (c[n] != 0): every
// root where p changes sign once. A root of even multiplicity, where p only
// touches zero, is reported twice if rounding puts p <= 0 there (the ends of
// a point or a tiny interval) and not at all otherwise; lo and hi themselves
// are never reported. Returns the count (at most n).
int polynomialSublevelBoundaries(const double* c, int n, double lo, double hi, double* roots);

// The boundaries, as above, of {t : t⁴ + c3·t³ + c2·t² + c1·t + c0 <= 0} in
// [lo, hi]: the real roots of a monic quartic that the sign changes at.
int quarticRoots(double c3, double c2, double c1, double c0, double lo, double hi, double roots[4]);

}  // namespace csgray::detail
