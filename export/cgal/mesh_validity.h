// Is a triangle mesh the boundary of a printable solid? Closed, 2-manifold,
// outward-oriented, free of degenerate faces and of self-intersections:
// checked with CGAL's exact predicates.
#pragma once

#include <string>

#include "tessellation/triangle_mesh.h"

namespace csgray::detail {

// The first problem found in a mesh, if any: its kind, for callers that act
// on it (a repair mends some kinds and not others), and one line for the
// user that says what it is and where (face or vertex indices from 0 and a
// point), e.g. "open: the edge from vertex 3 (1, 0, 2) to vertex 7 (...)
// has one face". The text begins with the kind's word where it has one
// ("open", "self-intersecting", ...).
struct MeshDefect {
  enum class Kind {
    None,                     // closed, 2-manifold, outward, no self-intersections
    Empty,                    // no triangles
    NotFinite,                // a vertex has a NaN or infinite coordinate
    BadIndex,                 // a face names a vertex the mesh does not have
    Degenerate,               // a face uses a vertex twice or has no area
    Open,                     // an edge has one face: a hole
    NonManifold,              // an edge has more than two faces, or a vertex joins two fans
    InconsistentOrientation,  // two faces run the same way along their edge
    SelfIntersecting,         // two faces cross
    InsideOut,                // faces point inward
  };
  Kind kind = Kind::None;
  std::string text;  // empty when kind is None

  bool valid() const { return kind == Kind::None; }
};

MeshDefect meshDefect(const TriangleMesh& mesh);

}  // namespace csgray::detail
