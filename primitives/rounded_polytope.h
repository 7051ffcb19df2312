// The Minkowski sum of a convex polytope P and a ball of radius r: the
// points within r of P (OpenSCAD's minkowski() of a polyhedron and a
// sphere, a rounded box). Its boundary is P's faces moved out by r along
// their normals, a strip of cylinder of radius r along each edge, and a
// patch of sphere about each vertex (over the directions of the planes
// that touch P there: its normal cone).
//
// Exact along a ray: the solid is the union of, for each face, the prism
// of height r over it, for each edge the cylinder of radius r about it, and
// for each vertex the ball of radius r about it (a point within r of P is
// within r of a nearest point, which lies inside a face, on an edge or at a
// vertex). The sum is convex, so a line meets it in one interval, which is
// the union of the pieces' intervals: from the first entry to the last
// exit. Faces: 0 .. F−1 the polytope's faces, then one per edge, then one
// per vertex.
//
// P may be a flat polygon (its two sides are its faces): the hull of
// equal spheres whose centres lie in a plane.
#pragma once

#include <memory>
#include <string>

#include "primitives/polytope.h"
#include "primitives/primitive_shape.h"

namespace csgray::detail {

class RoundedPolytope : public PrimitiveShape<RoundedPolytope> {
 public:
  // Throws std::invalid_argument naming kind for r not positive and
  // finite, a polytope below dimension 2, or faces whose edges do not pair
  // up (each edge a→b of one face must be b→a in exactly one other).
  RoundedPolytope(Polytope polytope, double radius, std::string kind = "minkowski");

  std::string kind() const override { return kind_; }
  double radius() const { return radius_; }
  const Polytope& polytope() const { return shape_->polytope; }

  struct Edge {
    std::uint32_t a = 0, b = 0;         // a→b runs along the loop of face `left`
    std::uint32_t left = 0, right = 0;  // the faces on either side
    dvec3 direction{0.0};               // unit, a to b
    double length = 0.0;
  };
  // A plane n·p <= offset of a face's prism.
  struct Side {
    dvec3 normal{0.0};
    double offset = 0.0;
  };
  struct Shape {
    Polytope polytope;
    std::vector<Edge> edges;
    std::vector<std::vector<Side>> prisms;  // per face: its top, its base, its sides
  };

 protected:
  void objectSpans(const Ray& ray, SpanList& out) const override;
  bool objectContains(const dvec3& p) const override;
  dvec3 objectNormal(const dvec3& p, int face) const override;
  Bounds objectBounds() const override;
  TriangleMesh objectTessellate(double tolerance, const Bounds& region) const override;

 private:
  // Shared: clones (moves, materials) keep one copy.
  std::shared_ptr<const Shape> shape_;
  double radius_;
  std::string kind_;
};

}  // namespace csgray::detail
