// Points of the unit circle at angles in degrees, for polygons that stand
// in for circles (regular polygons, OpenSCAD's facets): std::cos(π/2) is
// 6e-17, not 0, which puts a square's corner a hair's breadth off the
// axis and off the face of a box it should touch; the exporter's booleans
// then meet near-coincident faces instead of coincident ones.
#pragma once

#include <glm/vec2.hpp>

namespace csgray::detail {

using glm::dvec2;

// (cos, sin) of the angle: exact at multiples of 90° (and 0.5 at 30° and
// 60°), and symmetric bit for bit, so a polygon's corners at a and 180° − a
// are exact mirror images.
dvec2 unitCircleDegrees(double degrees);

}  // namespace csgray::detail
