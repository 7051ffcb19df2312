// Is a mesh closed and 2-manifold along its edges, and consistently
// oriented? So every edge must be used by exactly two faces, once each way.
// The one check of it: the validity check of meshes (meshDefect) and the
// one of polyhedron()'s faces (MeshSolid) both use it, each in its own
// words.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace csgray::detail {

// One side of one face: corner k to corner k + 1 (the last corner back to
// the first), as a use of the undirected edge between the two vertices.
struct EdgeUse {
  std::uint64_t edge;  // lo << 32 | hi, lo <= hi the two vertex indices
  std::uint32_t side;  // the side's place among all sides of all faces, in face order
  bool forward;        // the face runs from lo to hi
};

// Sorts by edge, and the uses of one edge by side.
void sortEdgeUses(std::vector<EdgeUse>& uses);

// Every side of the faces (each a sequence of vertex indices: a triangle, a
// polygon), sorted by edge and, along one edge, in face order. For
// triangles, side 3f + k is corner k of face f.
template <class Faces>
std::vector<EdgeUse> edgeUses(const Faces& faces) {
  std::size_t total = 0;
  for (const auto& face : faces) total += face.size();
  std::vector<EdgeUse> uses;
  uses.reserve(total);
  for (const auto& face : faces)
    for (std::size_t k = 0; k < face.size(); ++k) {
      const std::uint64_t a = face[k], b = face[(k + 1) % face.size()];
      uses.push_back({std::min(a, b) << 32 | std::max(a, b), std::uint32_t(uses.size()), a < b});
    }
  sortEdgeUses(uses);
  return uses;
}

// The uses of the edge whose first use is uses[first].
std::span<const EdgeUse> usesOfEdge(const std::vector<EdgeUse>& uses, std::size_t first);

// What is wrong with an edge, given all its uses.
enum class EdgeFault {
  None,         // two faces, one each way
  Open,         // one face: a hole
  NonManifold,  // more than two faces
  SameWay,      // two faces that run the same way: one is flipped
};
EdgeFault edgeFault(std::span<const EdgeUse> uses);

}  // namespace csgray::detail
