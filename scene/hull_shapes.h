// Hulls and Minkowski sums of solids (OpenSCAD's hull() and minkowski()),
// and the rounded shapes most minkowski() calls build (docs/script.md,
// "Hull and Minkowski"). Exact where the result is a known shape: the hull
// of points and polyhedra is a convex polyhedron of planes; the hull of
// spheres of one radius and the sum of a convex polyhedron and a ball are
// rounded polytopes (primitives/rounded_polytope.h); the hull of two
// spheres and a cylinder's sum with a ball are revolutions of their
// outlines. Other convex operands are replaced by their meshes at
// kHullTolerance of their size, and the rest is refused. Each throws
// std::invalid_argument with a one-line message naming the function.
#pragma once

#include <optional>
#include <vector>

#include "engine/solid.h"

namespace csgray::detail {

// The tolerance, relative to the operands' size (the diagonal of their
// box), of the meshes that stand in for curved operands that have no exact
// hull or sum: a part in 10⁴, a hundredth of a millimetre on a 100 mm part.
constexpr double kHullTolerance = 1e-4;

// The convex hull of the solids: primitives and unions of them (the hull of
// a union is the hull of its operands), bounded.
SolidPtr hullShape(const std::vector<SolidPtr>& operands);
// The Minkowski sum of the solids, taken pairwise from the first. A union
// is summed operand by operand (the sum distributes over unions).
SolidPtr minkowskiShape(const std::vector<SolidPtr>& operands);

// A box of the given outer size with its edges and corners rounded to
// radius r (0 < r <= half the smallest side): the Minkowski sum of the box
// shrunk by r on every side and a ball of radius r. From the origin to
// size, or centred on the origin.
SolidPtr roundedBoxShape(const std::optional<dvec3>& size, std::optional<double> r, bool center);
// A cylinder of radius r and height h along +z whose two rims are rounded
// with radius fillet (0 < fillet <= r and <= h/2); centred on the origin
// with center.
SolidPtr roundedCylinderShape(std::optional<double> r, std::optional<double> h,
                              std::optional<double> fillet, bool center);

}  // namespace csgray::detail
