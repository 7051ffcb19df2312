// A closed triangle mesh (outward, as the exporter makes it) brought down
// to the plane z = 0: its section by that plane and its shadow on it, as
// OpenSCAD's projection(cut = true) and projection(cut = false) are. Both
// are exact for the mesh's triangles as doubles give them (the 2D booleans
// are nonZeroFill's, region_evaluation.h); how near the mesh is to a
// curved solid is the caller's tolerance (export/solid_projection.h).
#pragma once

#include "profile/profile.h"
#include "tessellation/triangle_mesh.h"

namespace csgray::detail {

// Which way the plane z = 0 is moved, by a hair, for a section: a point
// on the plane counts as above it (Down) or as below it (Up), so that every
// edge of a mesh either crosses the plane once or not at all.
enum class PlaneShift { Down, Up };

// The section of the solid the mesh bounds by the plane so moved. Each
// triangle that crosses it gives a segment, directed so that the solid is
// on its left (the outward normal turned a right angle about z); the
// section is what they wind about. A face in the plane is in the section
// moved Down when the solid is below it, Up when it is above.
Profile meshSection(const TriangleMesh& mesh, PlaneShift shift);

// Does a point of the mesh lie on z = 0 (where the two shifts may differ)?
bool touchesPlane(const TriangleMesh& mesh);

// The points of z = 0 under or over the solid: the union of its triangles
// that face up (a positive area seen from above), projected. Every
// vertical line through the solid meets one of them. Edges between two
// such triangles cancel; what they wind about is the union.
Profile meshShadow(const TriangleMesh& mesh);

}  // namespace csgray::detail
