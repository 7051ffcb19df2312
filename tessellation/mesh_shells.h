// The separate shells of a triangle mesh (its pieces connected through
// shared vertices), and where two of them come nearest: what `csgray
// check` says of an export that falls apart.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "tessellation/triangle_mesh.h"

namespace csgray::detail {

struct MeshShells {
  std::size_t count = 0;
  // Of those, the shells that bound a cavity (inside another shell, facing
  // inwards: their signed volume is negative): not pieces of their own.
  std::size_t cavities = 0;
  std::vector<std::uint32_t> shellOfPoint;  // by point index; unused points get their own
};

MeshShells meshShells(const TriangleMesh& mesh);

// The nearest two points of different shells, a vertex of one and a
// vertex or a face of another (infinite distance for fewer than two
// shells; where it is a face, both points are the vertex). Past a budget
// of pairs, the nearest found so far: an upper bound.
struct ShellApproach {
  double distance = 0.0;
  dvec3 a{0.0}, b{0.0};
};

ShellApproach nearestShells(const TriangleMesh& mesh, const MeshShells& shells);

// The shells within `distance` of each other (a vertex of one within it of
// a vertex or a face of another: solids that touch, kept apart by a hair)
// joined into groups: for each shell number, the least shell number of its
// group. Nothing where the pairs ran past a budget, before all were seen.
std::optional<std::vector<std::uint32_t>> shellGroupsWithin(const TriangleMesh& mesh,
                                                            const MeshShells& shells,
                                                            double distance);

}  // namespace csgray::detail
