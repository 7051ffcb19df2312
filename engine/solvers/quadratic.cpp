#include "engine/solvers/quadratic.h"

#include <algorithm>
#include <cmath>

#include "engine/ray.h"

namespace csgray::detail {

int quadraticSublevel(double a, double b, double c, Interval out[2]) {
  if (a == 0.0) {
    // Linear: b·t + c <= 0.
    if (b > 0.0) {
      out[0] = {-kInfinity, -c / b};
    } else if (b < 0.0) {
      out[0] = {-c / b, kInfinity};
    } else {
      if (c > 0.0) return 0;
      out[0] = {-kInfinity, kInfinity};
    }
    return 1;
  }
  double disc = b * b - 4.0 * a * c;
  if (disc < 0.0) {
    // No real roots: the sign of a decides, everywhere.
    if (a > 0.0) return 0;
    out[0] = {-kInfinity, kInfinity};
    return 1;
  }
  double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  double t0 = q / a;
  double t1 = q != 0.0 ? c / q : t0;
  if (t0 > t1) std::swap(t0, t1);
  if (a > 0.0) {
    out[0] = {t0, t1};
    return 1;
  }
  if (t0 == t1) {
    // A double root with a < 0 (a line through a cone's apex, inside it):
    // a·(t - t0)² <= 0 everywhere, not two intervals touching at t0.
    out[0] = {-kInfinity, kInfinity};
    return 1;
  }
  out[0] = {-kInfinity, t0};
  out[1] = {t1, kInfinity};
  return 2;
}

}  // namespace csgray::detail
