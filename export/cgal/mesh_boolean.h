// A solid's boolean tree evaluated on meshes, for export: every primitive
// tessellates itself within the chord tolerance, and the booleans are
// computed in doubles with exact predicates where the operands are in
// general position (double_boolean.h), else by CGAL's corefinement
// (Polygon Mesh Processing) with exact predicates and exact
// constructions, so that chained operations stay consistent.
#pragma once

#include <cstdint>
#include <vector>

#include "engine/solid.h"
#include "export/part_mesh.h"

namespace csgray::detail {

// How far operands that touch are moved to resolve the contact, in
// tolerances (docs/cli.md, "Contacts"): far above the rounding of a file's
// floats at a part's size (7.6·10⁻⁶ at 100 mm), far below what a printer
// makes. Solids placed closer than that may be joined across the gap.
constexpr double kContactOffset = 0.01;
// How wide the square is that a union of prisms on one slab gets where its
// outline touches itself at a point (export/prism_booleans.h), in
// tolerances: ten contact offsets, well above the slivers the finished
// mesh collapses (a hundredth of the tolerance); a square one contact
// offset wide had its walls folded onto the tiles' by that collapse.
constexpr double kPinchBridge = 10.0 * kContactOffset;

// What the evaluation did, for --stats and the benchmarks.
struct MeshBooleanStats {
  std::size_t primitives = 0;      // primitives tessellated
  std::size_t corefinements = 0;   // boolean operations on meshes
  std::size_t inDoubles = 0;       // of them, made in doubles (double_boolean.h), not by CGAL
  std::size_t perturbed = 0;       // of those, one operand moved off the other (perturbedInDoubles)
  bool redoneByCgal = false;       // the part failed its check with booleans in doubles
  std::size_t merges = 0;          // operands joined without one (boxes apart)
  std::size_t glued = 0;           // unions of solids on the same faces (stacked, a leg on a bend)
  std::size_t repairs = 0;         // self-intersections from rounding removed
  std::size_t contacts = 0;        // booleans whose operands touched (docs/cli.md)
  std::size_t strayShells = 0;     // slivers outside the exact part, removed
  std::size_t grazes = 0;          // flat cutters moved clear of a part they only graze
  bool holesFilled = false;        // made on a last try, holes that pins fill left out
  bool sweepsApart = false;        // made on a last try, sweeps of touching regions taken apart
  bool pinchesOpened = false;      // made on a last try, regions that touch themselves opened
  bool framesAsWritten = false;    // made on a last try, a turned part's places as written
  bool cuttersLengthened = false;  // made on a last try, cylinders cut away made a little longer
  // 0: made with the operands in the script's order; 1: reversed, on a
  // second try; more: shuffled, on a last try.
  std::size_t reordered = 0;
  double checkSeconds = 0.0;  // in meshDefect
};

// The closed mesh of the solid. Operands whose boxes do not overlap are
// joined without a boolean; an n-ary node is evaluated in a balanced order.
// Unbounded primitives are tessellated within the box of the bounded solid
// they are cut by. Throws std::invalid_argument for an unbounded part or a
// primitive that cannot be tessellated, std::runtime_error when CGAL cannot
// make a 2-manifold result (operands that touch along an edge or a point).
// The exact result is rounded to doubles and then by `stored` (to what the
// file will hold: floats for binary STL, ...); faces that rounding leaves
// without area are removed. The result is checked with meshDefect (closed, 2-manifold,
// outward, no self-intersections); std::runtime_error says why it fails.
// The boolean meshOfSolid is evaluating ("the union of box (part.lua:3) and
// cylinder (part.lua:5) near (1, 2, 3)"), or "the booleans" outside one:
// for a message when the process must end in the middle of it. A fixed
// buffer, safe to read from a signal handler.
const char* booleanInProgress();

// doubles: each boolean is tried in doubles first (double_boolean.h), and
// the part made again with CGAL's booleans alone if its mesh then fails;
// false: CGAL's booleans only (for tests that compare the two).
PartMesh meshOfSolid(const Solid& solid, double tolerance, StoredCoordinate stored = nullptr,
                     MeshBooleanStats* stats = nullptr, bool doubles = true);

}  // namespace csgray::detail
