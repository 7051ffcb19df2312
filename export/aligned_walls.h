// Walls that two solids share, made flush where rounding put them a hair
// apart.
//
// A pin through a swept plate's round hole stands on the same polygon as
// the hole's wall (export/swept_rims.h), but each is placed by its own
// frame: where those differ by a move or a turn, the two walls' points
// differ in their last bits, the walls cross each other at a sliver's
// angle, and the union is refused as self-intersecting or keeps crevices.
// Such walls run along an axis of the frame the export evaluates in (a
// sweep's and a cylinder's sides are lines along their axis), so they are
// made flush there: the lines along an axis that one mesh's edges lie on
// and that come within a hair of another mesh's lines on that axis are
// moved onto those, so that the faces between them lie in one plane,
// exactly, and the booleans resolve them as any faces that coincide.
#pragma once

#include <span>
#include <vector>

#include "tessellation/triangle_mesh.h"

namespace csgray::detail {

// For each axis, every line along it that an edge of one of the meshes
// lies on (its two points differ in that coordinate only) and that lies
// within `reach` across the axis of a line of an earlier mesh (and of no
// other line) is moved onto that line: every point of its mesh on it takes
// the earlier line's two other coordinates. A line is left where it is
// when two lines of its mesh would move onto one (which would fold the
// faces between them) or when the line it would move onto moves too.
// Returns, for each mesh, whether any of its points moved.
std::vector<bool> alignAxisLines(std::span<TriangleMesh* const> meshes, double reach);

}  // namespace csgray::detail
