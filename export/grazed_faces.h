// A flat cutter's faces that the part it cuts only grazes, moved clear.
//
// A box cut from a cylinder with its sides tangent to the cylinder (the
// half of a cylinder, cut by a box as wide as the cylinder: a habit of
// OpenSCAD's users), or from a ball whose equator it touches, meets the
// exact solid along a line or at a point. The curved solid's mesh does
// not stop there: its points lie a little outside the curve (the minimax
// polygons of circlePolygon), so it pokes past the box's side by up to
// its tessellation error, and the difference of the meshes keeps that
// sliver: a fin a hundredth wide and as tall as the cut, which the model
// has not. The mesh of an exact solid never strays more than the
// tolerance from it, so a face with no more than that of the minuend
// beyond it is grazed, not cut into: moving it out past that sliver
// changes the part by less than the tolerance and leaves no fin. Unless
// the exact solid itself reaches past the face: a skin thinner than the
// tolerance over a cavity (a pocket cut 10⁻³ short of the top), or a slab
// that thin (a box less itself moved by 10⁻³) is the model's, and moving
// the face out would cut it away.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "tessellation/tessellation.h"
#include "tessellation/triangle_mesh.h"

namespace csgray::detail {

// The minuend's triangles, held for the cutters of one difference.
class GrazeTest {
 public:
  // inside: is a point (in the mesh's frame) inside the exact minuend?
  GrazeTest(const TriangleMesh& minuend, double tolerance,
            std::function<bool(const dvec3&)> inside);

  // The cutter is the convex polytope of the planes (normal·p <= offset,
  // unit normals) within `box`. For each plane, the minuend's triangles
  // are taken where they lie within the face's prism (every other plane,
  // loosened by twice the tolerance) and less than twice the tolerance
  // beyond the plane; if what lies beyond reaches no further than the
  // tolerance, the plane moves out a tenth of the tolerance past it, unless
  // the exact minuend holds the point halfway there from the mesh's point
  // that reaches furthest, or a point of the face a hair outwards under a
  // grid of points of what lies beyond it (a skin thinner than the mesh's
  // bulge). Each plane is judged against the planes as they were. Returns
  // whether any moved.
  bool clearGrazedFaces(std::vector<BoundingPlane>& planes, const Bounds& box) const;

 private:
  // The triangles whose boxes meet `box`, by a grid over the minuend's
  // box in x and y: each cell lists the triangles whose boxes reach it.
  void trianglesNear(const Bounds& box, std::vector<std::uint32_t>& out) const;
  // The cells in x and y that the box covers, clamped to the grid.
  void cellRange(const Bounds& box, int lo[2], int hi[2]) const;

  const TriangleMesh& minuend_;
  double tolerance_;
  std::function<bool(const dvec3&)> inside_;
  std::vector<Bounds> boxes_;  // the triangles' boxes
  Bounds whole_;               // the minuend's box
  int cells_ = 1;              // a side of the grid
  std::vector<std::vector<std::uint32_t>> grid_;
  mutable std::vector<std::uint32_t> seen_;  // per triangle: the query that last took it
  mutable std::uint32_t query_ = 0;
};

}  // namespace csgray::detail
