// The real roots of a monic quartic in closed form, by Ferrari's method:
// the torus's cheap path for a camera ray's entry, which the caller
// polishes and checks (a closed form loses digits near multiple roots,
// quartic.h).
#pragma once

namespace csgray::detail {

// The real roots of t⁴ + c3·t³ + c2·t² + c1·t + c0, sorted, written to
// roots; returns their count (0, 2 or 4; a double root counts twice).
int ferrariRoots(double c3, double c2, double c1, double c0, double roots[4]);

}  // namespace csgray::detail
