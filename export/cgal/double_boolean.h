// One boolean of two closed meshes whose points are all doubles, made in
// doubles: every decision by an exact predicate (CGAL's filtered orient3d
// and orient2d on Epick points), every new point a rounded construction.
// It declines wherever the operands are not in general position (a vertex
// on the other's plane, an edge through an edge, coplanar faces) or
// anything it builds is inconsistent; the evaluator then asks CGAL's exact
// corefinement (exact_boolean.h). The idea follows Manifold's booleans
// (Elalish et al., github.com/elalish/manifold, docs "Manifold
// Library"), doubles with exact predicates; the code is csgray's own.
#pragma once

#include <cstddef>
#include <optional>

#include "engine/boolean.h"
#include "export/cgal/double_mesh.h"

namespace csgray::detail {

// Why doubleBoolean made nothing: an operand it cannot take (a point that
// is not a double, a face that is not a triangle), or operands that are
// not in general position (or whose rounded points left something it
// built inconsistent), which a small move of one may put right.
enum class DoubleDecline { NotInDoubles, NotInGeneralPosition };

// a op b, its faces tagged with the materials of the faces they came
// from, its points doubles (so that a chain of such booleans stays
// eligible); nothing when declined. The operands must be closed,
// 2-manifold and outward: the result then is too, in general position,
// and is checked to be closed and 2-manifold (closedManifold) before it
// is returned. (An exact operand whose points are not all doubles is
// declined before, NotInDoubles, by doublesOf.) When it declines, `why`
// (if given) says why.
std::optional<DoubleMesh> doubleBoolean(const DoubleMesh& a, const DoubleMesh& b, Boolean::Op op,
                                        DoubleDecline* why = nullptr);

// The topology of a closed mesh: its shells (connected components) and its
// Euler characteristic V − E + F (2 for each sphere, 0 for each torus).
struct MeshTopology {
  std::size_t shells = 0;
  long long euler = 0;
  bool operator==(const MeshTopology&) const = default;
};
MeshTopology topologyOf(const DoubleMesh& mesh);

}  // namespace csgray::detail
