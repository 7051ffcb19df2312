// OpenSCAD's projection() of a solid: its section by the plane z = 0
// (cut = true) or its shadow on that plane (cut = false), as a 2D profile.
// Both are taken from meshes, whose flat faces are where the model puts
// them: the projection of a polyhedron, a box or OpenSCAD's polygons
// (--facets openscad) is exact, and a curved surface is replaced by its
// polygons, within the tolerance of it.
//
// A section commutes with booleans (that of a - b is a's less b's, in the
// plane moved a hair either way), so each primitive is tessellated and cut
// on its own and the booleans are done in 2D, exactly: no 3D boolean is
// needed. A shadow commutes with unions only: a difference or an
// intersection is meshed by the exporter's booleans (meshOfSolid) first.
#pragma once

#include "engine/solid.h"
#include "profile/profile.h"

namespace csgray::detail {

// How far the meshes that are cut (and the primitives and unions that are
// cast) may be from the solid's surface: a ten-thousandth of the solid's
// largest extent, and at most 10⁻³, a tenth of the export's default
// tolerance, so that an export of the projection is about as near the
// exact one as an export of a solid.
double projectionTolerance(const Solid& solid);
// The tolerance of the exporter's booleans for a shadow, ten times that:
// their triangles, and their time, grow as 1 / tolerance (Old_example021's
// ball less three cones: 1.4 s at 10⁻², 6.6 s at 10⁻³ on a busy machine).
double shadowBooleanTolerance(const Solid& solid);

// The section (cut) or shadow of the solid's model (ghosts and disabled
// solids left out: scene/modifiers.h); an empty profile when there is none.
// A face that lies in the plane belongs to the section (the closed solid's,
// as OpenSCAD's cut of a cube standing on z = 0 is its bottom face). Throws
// std::invalid_argument (an unbounded solid) and std::runtime_error (a mesh
// the booleans cannot make) with a one-line message.
Profile solidProjection(const SolidPtr& solid, bool cut);

}  // namespace csgray::detail
