#include "engine/solvers/quartic.h"

#include <algorithm>
#include <limits>

namespace csgray::detail {

int polynomialSublevelBoundaries(const double* c, int n, double lo, double hi, double* roots) {
  while (n > 0 && c[n] == 0.0) --n;
  if (n == 0 || !(lo < hi)) return 0;
  if (n == 1) {
    // A line changes sign once, at −c0/c1: no search needed.
    const double root = -c[0] / c[1];
    if (!(root > lo && root < hi)) return 0;
    roots[0] = root;
    return 1;
  }
  // Far below any distance that matters at the scale of the interval, and
  // about where doubles run out: roots are found to a few ulps.
  double tolerance =
      std::max(4.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(lo), std::abs(hi)),
               std::numeric_limits<double>::min());
  // The points where p' changes sign split [lo, hi] into pieces on which p
  // is monotone (a root of p' without a change of sign is an inflection
  // with a level tangent: p stays monotone through it).
  double breaks[6];
  int count = 0;
  breaks[count++] = lo;
  if (n >= 2) {
    double derivative[4];
    for (int i = 1; i <= n; ++i) derivative[i - 1] = i * c[i];
    double critical[3];
    int k = polynomialSublevelBoundaries(derivative, n - 1, lo, hi, critical);
    for (int i = 0; i < k; ++i)
      if (critical[i] > breaks[count - 1] && critical[i] < hi) breaks[count++] = critical[i];
  }
  breaks[count++] = hi;
  // On each monotone piece p changes sign at most once.
  auto f = [&](double t) {
    return std::pair<double, double>(polynomialValue(c, n, t), polynomialSlope(c, n, t));
  };
  int found = 0;
  bool inside = polynomialValue(c, n, lo) <= 0.0;
  for (int i = 1; i < count; ++i) {
    bool next = polynomialValue(c, n, breaks[i]) <= 0.0;
    if (next != inside)
      roots[found++] = bracketedRoot(f, breaks[i - 1], breaks[i], inside, tolerance);
    inside = next;
  }
  return found;
}

int quarticRoots(double c3, double c2, double c1, double c0, double lo, double hi,
                 double roots[4]) {
  const double c[5] = {c0, c1, c2, c3, 1.0};
  return polynomialSublevelBoundaries(c, 4, lo, hi, roots);
}

}  // namespace csgray::detail
