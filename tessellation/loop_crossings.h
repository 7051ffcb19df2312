// Whether closed polygons in the plane cross or touch: the test that a set
// of loops made within a tolerance (a sweep's region, its circles pushed
// out to a cylinder's rim polygon) is still a set of simple loops, none
// meeting another.
#pragma once

#include <glm/vec2.hpp>
#include <vector>

namespace csgray::detail {

using glm::dvec2;

// Do two edges of the loops (each closed: its last point joins its first)
// meet anywhere but at the point two consecutive edges share? Touching,
// overlapping along a line and a loop that passes through one point twice
// count as meeting. In doubles: an edge within rounding of another may be
// said to meet it, never the other way round where they cross clearly.
// Edges are sorted into a grid of cells, about one edge each, so that the
// cost grows with the number of edges and of edges close to each other;
// loops whose edges would fill far more cells than that (a few long edges
// across a box of extreme shape) are said to meet, without a test.
bool loopsMeet(const std::vector<std::vector<dvec2>>& loops);

}  // namespace csgray::detail
