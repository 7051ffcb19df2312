// The hulls and sums that are sweeps of exact outlines (scene/hull_shapes.h
// decides when): turned about an axis, the hull of two balls and the
// rounded cylinder; extruded, the hull of discs in a plane, whose arcs the
// 2D hull keeps.
#pragma once

#include <vector>

#include "engine/solid.h"
#include "profile/profile.h"

namespace csgray::detail {

// A ball in world space, as hulls and sums find it in a sphere whose frame
// scales alike along every axis.
struct Ball {
  dvec3 centre{0.0};
  double radius = 0.0;
};

SolidPtr sphereAt(const Ball& ball);

// The hull of two balls: the larger when it holds the other, else both
// and the cone frustum that touches each along a circle (a capsule for
// equal radii), turned about the line of their centres.
SolidPtr twoBallHull(const Ball& a, const Ball& b);

// A cylinder of radius R and height H along +z from z = 0 whose rims are
// rounded with radius f (0 < f <= R, 2f <= H).
SolidPtr roundedCylinder(double R, double H, double f);

// Axes u, w, a (right-handed) for a unit direction a: the frame a solid
// made about the z axis is turned into to stand along a.
struct AxisFrame {
  dvec3 u, w, a;
  explicit AxisFrame(const dvec3& axis);
  // The solid's x, y, z along u, w, a, its origin moved to origin.
  SolidPtr place(const SolidPtr& solid, const dvec3& origin) const;
};

// A disc of the plane across an axis.
struct Disc {
  dvec2 centre;
  double radius;
};

// The hull of the discs (coordinates along frame.u and frame.w), extruded
// along frame.a from `from` to `to`.
SolidPtr extrudedDiscHull(const std::vector<Disc>& discs, const AxisFrame& frame, double from,
                          double to);

}  // namespace csgray::detail
