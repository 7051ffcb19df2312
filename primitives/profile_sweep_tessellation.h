// What the sweeps' meshes share: the region as polygons within a chord
// tolerance, outer loops counter-clockwise and holes clockwise, and the
// triangulation of such a polygon set (a cap of an extrusion, a flat face
// of a revolution's wedge).
#pragma once

#include <cstdint>
#include <functional>
#include <glm/vec2.hpp>
#include <span>
#include <vector>

#include "profile/region.h"
#include "profile/region_evaluation.h"
#include "tessellation/triangle_mesh.h"

namespace csgray::detail {

using SweepLoops = std::vector<std::vector<dvec2>>;

// The region evaluated (profile/region_evaluation.h) and flattened into
// loops within `tolerance` of its edges (arcs by the sagitta rule; arcs on
// `rims`, on a cylinder's rim polygon at rimTolerance: flatten()), outer
// loops counter-clockwise, holes clockwise, none crossing another; none
// for a region without points. Throws std::invalid_argument naming kind
// for a region whose loops all flatten to nothing (thinner than the
// tolerance). pinched,
// if given, is set to whether the region touches itself at a point
// (profile/pinch_points.h).
SweepLoops sweepLoops(const Region& region, double tolerance, const char* kind,
                      std::span<const CircleRim> rims = {}, double rimTolerance = 0.0,
                      bool* pinched = nullptr);

// Triangles covering the polygon set (loops as sweepLoops makes them),
// counter-clockwise in the plane: triangle(a, b, c) gets ids[loop][point]
// of its corners. Holes are joined to their outer loop by bridges and the
// result is cut by ear clipping (D. Eberly, "Triangulation by Ear
// Clipping", Geometric Tools, 2002).
void triangulateLoops(
    const SweepLoops& loops, const std::vector<std::vector<std::uint32_t>>& ids,
    const std::function<void(std::uint32_t, std::uint32_t, std::uint32_t)>& triangle);

// levels[k][l][i]: the mesh point of loop l's point i at level k of a sweep
// (the same point at several levels where they meet: a point on a
// revolution's axis, an extrusion's apex).
using SweepLevels = std::vector<std::vector<std::vector<std::uint32_t>>>;

// Adds to the mesh (whose points the levels index) the faces of the loops
// swept through the levels. Sides: the quad of loop l's edge i → i + 1
// between levels k and k + 1 (and between the last level and the first
// when `closed`) is cut along its diagonal from (i, k) to (i + 1, k + 1),
// or along the other where otherDiagonal(k, l, i) says; triangles with a
// repeated corner are left out. Ends, unless closed: the loops'
// triangulation at the first and the last level. Faces point out for
// loops as sweepLoops makes them swept along their plane's normal (an
// extrusion upwards); `reversed` for the other sense (a revolution of
// loops in the (ρ, z) plane).
void addSweepFaces(TriangleMesh& mesh, const SweepLoops& loops, const SweepLevels& levels,
                   bool closed, bool reversed,
                   const std::function<bool(int, std::size_t, std::size_t)>& otherDiagonal = {});

// The loops (in the (ρ, z) half plane, points on the axis at ρ = 0
// exactly) turned about the z axis from +x counter-clockwise by
// angleDegrees in `steps` equal steps: a ring of their points at each
// step (one vertex for a point on the axis), quads between, and unless
// fullTurn (the last step back at the first) the loops as flat faces at
// both ends.
TriangleMesh revolvedLoops(const SweepLoops& loops, double angleDegrees, int steps, bool fullTurn);

// Twice the signed area of a polygon (positive counter-clockwise).
double signedArea2(const std::vector<dvec2>& loop);

}  // namespace csgray::detail
