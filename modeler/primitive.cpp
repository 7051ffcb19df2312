#include "modeler/primitive.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <stdexcept>

namespace csgray {

void Primitive::spans(const Ray& ray, SpanList& out) const {
  out.clear();
  if (frame_.isIdentity()) {
    objectSpans(ray, out);
  } else {
    objectSpans(frame_.rayToObject(ray), out);
  }
}

bool Primitive::contains(const dvec3& p) const {
  return objectContains(frame_.isIdentity() ? p : frame_.pointToObject(p));
}

SolidPtr Primitive::withFrame(const Affine& worldFromObject) const {
  std::shared_ptr<Primitive> copy = clone();
  copy->frame_ = worldFromObject;
  copy->updateBounds();
  return copy;
}

SolidPtr Primitive::withMaterial(const MaterialPtr& material) const {
  std::shared_ptr<Primitive> copy = clone();
  copy->material_ = material;
  copy->textureFromObject_ = frame_;
  return copy;
}

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
  TriangleMesh mesh = objectTessellate(tolerance / largestStretch(linear), objectRegion);
  for (dvec3& p : mesh.points) p = frame_.pointToWorld(p);
  // A mirroring frame turns the triangles inside out.
  if (glm::determinant(linear) < 0.0) mesh.flip();
  return mesh;
}

void Primitive::updateBounds() {
  Bounds local = objectBounds();
  if (local.empty()) {
    bounds_ = local;
    return;
  }
  if (!local.finite()) {
    // An unbounded shape may reach anywhere once rotated.
    bounds_ = frame_.isIdentity() ? local : Bounds::everything();
    return;
  }
  // The box of the eight transformed corners.
  bounds_ = Bounds{};
  for (int i = 0; i < 8; ++i) {
    dvec3 corner(i & 1 ? local.hi.x : local.lo.x, i & 2 ? local.hi.y : local.lo.y,
                 i & 4 ? local.hi.z : local.lo.z);
    bounds_.include(frame_.pointToWorld(corner));
  }
}

}  // namespace csgray
