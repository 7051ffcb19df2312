// A region evaluated into one profile whose loops neither cross nor touch
// along an edge: outer loops counterclockwise, holes clockwise. What
// offsets, hulls, areas, outlines (SVG, DXF) and the tessellation of sweeps
// start from. Booleans of segments and circular arcs are exact (CGAL's
// general polygon sets with circle-segment traits); an arc of an ellipse
// that is not a circle is first replaced by a polygon within
// `ellipseTolerance`.
#pragma once

#include <span>
#include <vector>

#include "profile/region.h"

namespace csgray::detail {

Profile evaluate(const Region& region, double ellipseTolerance);

// Signed area of an evaluated profile: positive for counterclockwise loops.
double area(const Profile& evaluated);

// Each loop as a polygon within `tolerance` of the exact edges (the sagitta
// rule of the cylinders' tessellation for arcs); a loop's first point is
// not repeated at its end.
std::vector<std::vector<dvec2>> flatten(const Profile& profile, double tolerance);

// OpenSCAD's offset(r = r): every point within |r| of the region (r > 0)
// or the points of the region at least -r from its outside (r < 0); the
// corners it makes round are true arcs.
Profile offsetRounded(const Region& region, double r, double ellipseTolerance);
// OpenSCAD's offset(delta = d, chamfer = c): the edges moved by d along
// their normals; corners mitred, or cut flat with chamfer.
Profile offsetDelta(const Region& region, double delta, bool chamfer, double ellipseTolerance);
// The convex hull of the regions: segments and arcs of their circles.
Profile hull(std::span<const RegionPtr> regions, double ellipseTolerance);

}  // namespace csgray::detail
