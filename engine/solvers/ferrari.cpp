#include "engine/solvers/ferrari.h"

#include <algorithm>
#include <cmath>

namespace csgray::detail {

namespace {

// The largest real root of the monic cubic m³ + a·m² + b·m + c, by
// Cardano's formula or, with three real roots, Viète's trigonometric form
// (Press et al., "Numerical Recipes", 2nd ed., §5.6, eqs. 5.6.10–5.6.18).
double largestCubicRoot(double a, double b, double c) {
  const double Q = (a * a - 3.0 * b) / 9.0;
  const double R = (2.0 * a * a * a - 9.0 * a * b + 27.0 * c) / 54.0;
  const double Q3 = Q * Q * Q;
  if (R * R < Q3) {
    const double theta = std::acos(R / std::sqrt(Q3));
    return -2.0 * std::sqrt(Q) * std::cos(theta / 3.0) - a / 3.0;
  }
  const double A = -std::copysign(std::cbrt(std::abs(R) + std::sqrt(R * R - Q3)), R);
  const double B = A != 0.0 ? Q / A : 0.0;
  return A + B - a / 3.0;
}

}  // namespace

// Depressed by t = y − c3/4 to y⁴ + p·y² + q·y + r, the quartic is
// (y² + p/2 + m)² = 2m·y² − q·y + m² + m·p + p²/4 − r for any m; the right
// side is a square when m solves the resolvent cubic
// 8m³ + 8p·m² + (2p² − 8r)·m − q² = 0, and then y² + p/2 + m =
// ±(√(2m)·y − q/(2√(2m))), two quadratics (Ferrari's method, as set out in
// Wikipedia, "Quartic function", § Ferrari's solution).
int ferrariRoots(double c3, double c2, double c1, double c0, double roots[4]) {
  const double shift = 0.25 * c3;
  const double s2 = shift * shift;
  const double p = c2 - 6.0 * s2;
  const double q = c1 - 2.0 * c2 * shift + 8.0 * s2 * shift;
  const double r = c0 - c1 * shift + c2 * s2 - 3.0 * s2 * s2;
  const double m = largestCubicRoot(p, 0.25 * p * p - r, -0.125 * q * q);
  if (!(m > 0.0)) return 0;
  const double w = std::sqrt(2.0 * m);
  const double cross = q / w;
  int count = 0;
  for (double sign : {1.0, -1.0}) {
    // y² − sign·w·y + (p/2 + m + sign·q/(2w)) = 0.
    const double disc = -(2.0 * p + 2.0 * m + sign * 2.0 * cross);
    if (disc < 0.0) continue;
    const double root = std::sqrt(disc);
    roots[count++] = 0.5 * (sign * w - root) - shift;
    roots[count++] = 0.5 * (sign * w + root) - shift;
  }
  std::sort(roots, roots + count);
  return count;
}

}  // namespace csgray::detail
