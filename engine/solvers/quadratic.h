// Where a quadratic a·t² + b·t + c is at most zero: the ray test of every
// quadric surface (uλ² + vλ + w = 0; docs/theory.md, "Quadrics") reduces to this.
#pragma once

namespace csgray::detail {

struct Interval {
  double lo, hi;
};

// The set {t : a·t² + b·t + c <= 0} as 0, 1 or 2 closed intervals, sorted,
// possibly unbounded. Roots use the cancellation-free form
// q = -(b + sign(b)·sqrt(b² - 4ac))/2, t = q/a and c/q (Numerical Recipes 5.6).
int quadraticSublevel(double a, double b, double c, Interval out[2]);

}  // namespace csgray::detail
