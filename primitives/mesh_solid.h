// A closed triangle mesh as a solid: OpenSCAD's polyhedron(points, faces).
//
// Faces are polygons of indices into the points (from 0), listed clockwise
// as seen from outside, as OpenSCAD wants them. A face of more than three
// points must be a planar, simple polygon (convex or not); it is split into
// triangles by ear clipping. The mesh must be closed and consistently
// oriented: every directed edge a→b of a face has exactly one opposite b→a
// in another face. A mesh whose faces all run counter-clockwise (the STL and
// OBJ convention) encloses a negative volume; since it is closed, that can
// only mean the other convention, so it is turned rather than refused.
//
// Inside is where the winding number of the mesh is positive: a shell that
// faces the other way from the whole (inside a larger one) is a cavity.
//
// Rays meet the triangles through a BVH over their boxes, with the
// watertight test of triangle_crossing.h, so a ray through an edge or a
// vertex crosses the surface exactly once: spans are neither lost nor
// doubled there.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "engine/bvh.h"
#include "primitives/primitive_shape.h"

namespace csgray::detail {

class MeshSolid : public PrimitiveShape<MeshSolid> {
 public:
  using Triangle = std::array<std::uint32_t, 3>;

  // Validates the mesh and throws std::invalid_argument ("polyhedron: ...")
  // naming the first bad point, face or edge (all numbered from 0).
  MeshSolid(const std::vector<dvec3>& points, const std::vector<std::vector<std::int64_t>>& faces);

  std::string kind() const override { return "polyhedron"; }

  const std::vector<dvec3>& points() const;
  // Counter-clockwise seen from outside: (b − a) × (c − a) points out.
  const std::vector<Triangle>& triangles() const;
  // The face of the input that a triangle was cut from.
  std::uint32_t faceOf(std::uint32_t triangle) const;
  // The enclosed volume (positive), by the divergence theorem.
  double volume() const;
  // Were the faces given counter-clockwise seen from outside, and turned?
  bool turned() const;
  // Bytes the mesh holds (points, triangles, BVH), shared by all copies of
  // this solid (transforms and materials copy the primitive, not the mesh).
  std::size_t memoryBytes() const;

  struct Mesh;

 protected:
  void objectSpans(const Ray& ray, SpanList& out) const override;
  bool objectContains(const dvec3& p) const override;
  // The outward normal of triangle `face`.
  dvec3 objectNormal(const dvec3& p, int face) const override;
  Bounds objectBounds() const override;
  TriangleMesh objectTessellate(double tolerance, const Bounds& region) const override;

 private:
  std::shared_ptr<const Mesh> mesh_;
};

}  // namespace csgray::detail
