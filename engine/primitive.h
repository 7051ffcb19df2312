// A leaf of the boolean tree: a shape defined in its own frame, placed in
// the world by an affine frame, with an optional material. Subclasses answer
// in object space; this class maps rays, points and normals.
#pragma once

#include <memory>
#include <utility>

#include "engine/solid.h"

namespace csgray::detail {

// A primitive's mesh (tessellation/triangle_mesh.h), made by the
// tessellation layer above this one.
struct TriangleMesh;

class Primitive : public Solid {
 public:
  // Constructs a primitive and computes its world bounds. Shape constructors
  // validate their parameters and throw std::invalid_argument.
  template <class T, class... Args>
  static std::shared_ptr<T> create(Args&&... args) {
    auto p = std::make_shared<T>(std::forward<Args>(args)...);
    p->updateBounds();
    return p;
  }

  const Bounds& bounds() const final { return bounds_; }
  Bounds boundsUnder(const Affine& outer) const final;
  void spans(const Ray& ray, SpanList& out) const final;
  void spansToFirstBoundary(const Ray& ray, SpanList& out) const final;
  bool meetsWindow(const Ray& ray, SpanList& scratch) const final;
  bool contains(const dvec3& p) const final;
  SolidPtr mapPrimitives(const PrimitiveMap& f) const final { return f(*this); }

  const Affine& frame() const { return frame_; }
  // The box of this shape in the frame given by its matrix: bounds() of
  // its copy in that frame (withFrame), up to rounding.
  Bounds boundsInFrame(const glm::dmat4& worldFromObject) const;
  const MaterialPtr& material() const { return material_; }
  SolidPtr withFrame(const Affine& worldFromObject) const;
  SolidPtr withMaterial(const MaterialPtr& material) const;

  // A closed, outward-oriented triangle mesh of the primitive in world space
  // whose surface lies within `tolerance` (model units) of the exact one.
  // An unbounded primitive is meshed where it meets `region` (a finite world
  // box) and closed by faces outside that box, so that intersecting the mesh
  // with a solid inside the region gives that solid's part of it. Throws
  // std::invalid_argument (naming kind()) when the mesh would be too large
  // or cannot be a 2-manifold.
  TriangleMesh tessellate(double tolerance, const Bounds& region) const;
  // The tolerance tessellate() asks of objectTessellate: `tolerance` over
  // the most the frame stretches a length.
  double objectTolerance(double tolerance) const;

  // Unit outward normal in world space at a world point on the given face.
  dvec3 normal(const dvec3& worldPoint, int face) const {
    return frame_.normalToWorld(objectNormal(frame_.pointToObject(worldPoint), face));
  }
  // Texture space is the world as it was when the material was given, so a
  // texture stays on the part when the part is moved afterwards.
  dvec3 texturePoint(const dvec3& worldPoint) const {
    return textureFromObject_.pointToWorld(frame_.pointToObject(worldPoint));
  }
  dvec3 textureNormal(const dvec3& worldPoint, int face) const {
    return textureFromObject_.normalToWorld(objectNormal(frame_.pointToObject(worldPoint), face));
  }
  // How texturePoint moves with the world point: its (constant) derivative,
  // which takes a pattern's gradient in texture space to the world's.
  glm::dmat3 textureFromWorld() const {
    return glm::dmat3(textureFromObject_.worldFromObject()) * glm::dmat3(frame_.objectFromWorld());
  }

 protected:
  // Spans of a ray given in object space; boundaries name this primitive.
  virtual void objectSpans(const Ray& ray, SpanList& out) const = 0;
  // objectSpans for a ray that needs only the first boundary within the
  // window (Solid::spansToFirstBoundary): a shape whose later boundaries
  // cost more may leave them out. All of them by default.
  virtual void objectSpansToFirstBoundary(const Ray& ray, SpanList& out) const {
    objectSpans(ray, out);
  }
  // Solid::meetsWindow for a ray in object space: the answer of
  // objectSpansToFirstBoundary's spans by default; a shape that can tell
  // without finding its boundaries exactly may answer sooner. scratch is
  // working space, whatever it holds on entry.
  virtual bool objectMeetsWindow(const Ray& ray, SpanList& scratch) const;
  virtual bool objectContains(const dvec3& p) const = 0;
  // Outward normal (any length) at an object-space point on the face.
  virtual dvec3 objectNormal(const dvec3& p, int face) const = 0;
  virtual Bounds objectBounds() const = 0;
  // A box that holds the shape under worldFromObject, not a translation:
  // the moved corners of objectBounds() by default; a shape whose box under
  // a rotation is cheap to make tighter (a ball, a cylinder) makes it so.
  virtual Bounds objectBoundsUnder(const Affine& worldFromObject) const;
  virtual std::shared_ptr<Primitive> clone() const = 0;
  // tessellate() in object space: the tolerance divided by the frame's
  // largest stretch, and the box of the region's corners in the frame.
  virtual TriangleMesh objectTessellate(double tolerance, const Bounds& region) const = 0;

  // shape, a new primitive in object space, placed as this one is: its
  // frame, its material and texture frame, and where the script made it.
  SolidPtr placedAs(std::shared_ptr<Primitive> shape) const;

  Boundary boundary(double t, int face = 0) const {
    return Boundary{t, this, static_cast<decltype(Boundary::face)>(face), false};
  }

 private:
  void updateBounds();

  Affine frame_;
  MaterialPtr material_;
  Affine textureFromObject_;  // the frame when the material was given
  Bounds bounds_;
};

}  // namespace csgray::detail
