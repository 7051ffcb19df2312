// Where lines parallel to an axis cross a triangle mesh. The triangles are
// bucketed by the cells of a grid across the axis, so that a line meets
// only the few whose shadow covers its cell: csgray check sends some
// 50 000 such lines through a mesh, and a general ray query (CGAL's AABB
// tree) spent most of its time on boxes.
#pragma once

#include <cstdint>
#include <vector>

#include "tessellation/triangle_mesh.h"

namespace csgray::detail {

class AxisCrossings {
 public:
  // The grid: n × n cells over the box's two other axes, (axis + 1) % 3
  // first.
  AxisCrossings(const TriangleMesh& mesh, const Bounds& box, int axis, int n);

  struct Crossing {
    double t;                // along the axis, from the line's origin
    dvec3 normal;            // unit normal of the triangle crossed
    std::uint32_t triangle;  // its index in the mesh
  };
  // The crossings of the line through origin along +axis, sorted by t; the
  // origin lies in cell (i, j). A line through an edge or a corner may list
  // a crossing once for each triangle there; a triangle seen edge-on is not
  // crossed.
  void crossings(const dvec3& origin, int i, int j, std::vector<Crossing>& out) const;
  // The distance from p to the triangle a crossing crossed.
  double distance(const dvec3& p, const Crossing& c) const;

 private:
  const TriangleMesh& mesh_;
  int axis_, u_, v_, n_;
  std::vector<std::uint32_t> first_;      // per cell, into triangles_; n² + 1 entries
  std::vector<std::uint32_t> triangles_;  // triangle indices, cell by cell
};

}  // namespace csgray::detail
