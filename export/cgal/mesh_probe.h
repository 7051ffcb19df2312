// Questions about a triangle mesh, answered by CGAL independently of the
// exact model: which side of it a point lies on, its volume and area, and
// how far a point is from it. What `csgray check`
// holds against the exact model's answers.
#pragma once

#include <memory>
#include <vector>

#include "tessellation/triangle_mesh.h"

namespace csgray::detail {

class MeshProbe {
 public:
  // The mesh need not be valid: a mesh that is not a closed 2-manifold
  // still has distances, but no sides (canClassify() is false).
  explicit MeshProbe(const TriangleMesh& mesh);
  ~MeshProbe();
  MeshProbe(const MeshProbe&) = delete;
  MeshProbe& operator=(const MeshProbe&) = delete;

  enum class Side { Inside, Boundary, Outside };
  // Can side() be asked: is the mesh a closed 2-manifold?
  bool canClassify() const;
  // CGAL's Side_of_triangle_mesh (ray shooting on an AABB tree). Safe to
  // call from several threads.
  Side side(const dvec3& p) const;
  // CGAL's volume of a closed mesh (the signed sum of tetrahedra otherwise)
  // and the summed area of the faces.
  double volume() const;
  double area() const;

  // The distance from p to the nearest point of the faces.
  double distance(const dvec3& p) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace csgray::detail
