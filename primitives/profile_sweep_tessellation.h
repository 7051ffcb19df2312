// What the sweeps' meshes share: the region as polygons within a chord
// tolerance, outer loops counter-clockwise and holes clockwise, and the
// triangulation of such a polygon set (a cap of an extrusion, a flat face
// of a revolution's wedge).
#pragma once

#include <cstdint>
#include <functional>
#include <glm/vec2.hpp>
#include <vector>

#include "profile/region.h"

namespace csgray::detail {

using SweepLoops = std::vector<std::vector<dvec2>>;

// The region evaluated (profile/region_evaluation.h) and flattened into
// loops within `tolerance` of its edges (arcs by the sagitta rule), outer
// loops counter-clockwise, holes clockwise, none crossing another. Throws
// std::invalid_argument naming kind for a region without area.
SweepLoops sweepLoops(const Region& region, double tolerance, const char* kind);

// Triangles covering the polygon set (loops as sweepLoops makes them),
// counter-clockwise in the plane: triangle(a, b, c) gets ids[loop][point]
// of its corners. Holes are joined to their outer loop by bridges and the
// result is cut by ear clipping (D. Eberly, "Triangulation by Ear
// Clipping", Geometric Tools, 2002).
void triangulateLoops(
    const SweepLoops& loops, const std::vector<std::vector<std::uint32_t>>& ids,
    const std::function<void(std::uint32_t, std::uint32_t, std::uint32_t)>& triangle);

// Twice the signed area of a polygon (positive counter-clockwise).
double signedArea2(const std::vector<dvec2>& loop);

}  // namespace csgray::detail
