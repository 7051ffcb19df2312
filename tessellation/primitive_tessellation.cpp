// Primitive::tessellate: a primitive's mesh in world space, from the
// one its shape makes in object space (objectTessellate).
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "engine/primitive.h"
#include "tessellation/triangle_mesh.h"

namespace csgray::detail {

namespace {

// The largest singular value of m: the most a length can grow under it,
// found by power iteration on mᵀm (converges to the top eigenvalue; 64
// steps are plenty for the ratios of real frames, and the result only sets
// how fine a mesh is).
double largestStretch(const glm::dmat3& m) {
  const glm::dmat3 mtm = glm::transpose(m) * m;
  dvec3 v = glm::normalize(dvec3(0.57735, 0.57736, 0.57737));
  double lambda = 0.0;
  for (int i = 0; i < 64; ++i) {
    dvec3 w = mtm * v;
    double len = glm::length(w);
    if (len == 0.0) break;
    lambda = len;
    v = w / len;
  }
  return std::sqrt(lambda);
}

}  // namespace

double Primitive::objectTolerance(double tolerance) const {
  if (frame_.isIdentity()) return tolerance;
  return tolerance / largestStretch(glm::dmat3(frame_.worldFromObject()));
}

TriangleMesh Primitive::tessellate(double tolerance, const Bounds& region) const {
  if (frame_.isIdentity()) return objectTessellate(tolerance, region);
  Bounds objectRegion;
  if (region.finite()) {
    for (int i = 0; i < 8; ++i) {
      dvec3 corner(i & 1 ? region.hi.x : region.lo.x, i & 2 ? region.hi.y : region.lo.y,
                   i & 4 ? region.hi.z : region.lo.z);
      objectRegion.include(frame_.pointToObject(corner));
    }
  } else {
    objectRegion = region;
  }
  const glm::dmat3 linear(frame_.worldFromObject());
  TriangleMesh mesh = objectTessellate(objectTolerance(tolerance), objectRegion);
  for (dvec3& p : mesh.points) p = frame_.pointToWorld(p);
  // A mirroring frame turns the triangles inside out.
  if (glm::determinant(linear) < 0.0) mesh.flip();
  return mesh;
}

}  // namespace csgray::detail
