// A solid's boolean tree evaluated on meshes, for export: every primitive
// tessellates itself within the chord tolerance, and the booleans are
// computed by CGAL's corefinement (Polygon Mesh Processing) with exact
// predicates and exact constructions, so that chained operations stay
// consistent.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/part_mesh.h"
#include "modeler/solid.h"

namespace csgray {

// What the evaluation did, for --stats and the benchmarks.
struct MeshBooleanStats {
  std::size_t primitives = 0;     // primitives tessellated
  std::size_t corefinements = 0;  // CGAL boolean operations
  std::size_t merges = 0;         // operands joined without one (boxes apart)
  bool exact = false;             // evaluated again with exact constructions
  double checkSeconds = 0.0;      // in meshDefect
};

// The closed mesh of the solid. Operands whose boxes do not overlap are
// joined without a boolean; an n-ary node is evaluated in a balanced order.
// Unbounded primitives are tessellated within the box of the bounded solid
// they are cut by. Throws std::invalid_argument for an unbounded part or a
// primitive that cannot be tessellated, std::runtime_error when CGAL cannot
// make a 2-manifold result (operands that touch along an edge or a point).
// The exact result is rounded to doubles, or to floats when the file holds
// floats (binary STL, 3MF); faces that rounding leaves without area are
// removed. The result is checked with meshDefect (closed, 2-manifold,
// outward, no self-intersections): the booleans run with inexact
// constructions first and again with exact ones if that check fails; if it
// still fails, std::runtime_error says why.
PartMesh meshOfSolid(const Solid& solid, double tolerance, bool floats = false,
                     MeshBooleanStats* stats = nullptr);

}  // namespace csgray
