#include "engine/primitive.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <stdexcept>

#include "engine/moved_box.h"

namespace csgray::detail {

namespace {

// ask(r) with r the ray in the frame's object space, not copied when the
// frame is the identity.
template <class Ask>
void inObjectSpace(const Affine& frame, const Ray& ray, Ask&& ask) {
  if (frame.isIdentity()) {
    ask(ray);
  } else {
    ask(frame.rayToObject(ray));
  }
}

}  // namespace

void Primitive::spans(const Ray& ray, SpanList& out) const {
  out.clear();
  inObjectSpace(frame_, ray, [&](const Ray& r) { objectSpans(r, out); });
}

void Primitive::spansToFirstBoundary(const Ray& ray, SpanList& out) const {
  out.clear();
  inObjectSpace(frame_, ray, [&](const Ray& r) { objectSpansToFirstBoundary(r, out); });
}

bool Primitive::meetsWindow(const Ray& ray, SpanList& scratch) const {
  bool met = false;
  inObjectSpace(frame_, ray, [&](const Ray& r) { met = objectMeetsWindow(r, scratch); });
  return met;
}

bool Primitive::objectMeetsWindow(const Ray& ray, SpanList& scratch) const {
  scratch.clear();
  objectSpansToFirstBoundary(ray, scratch);
  return scratch.meetsOpenWindow(ray.tMin, ray.tMax);
}

Bounds Primitive::boundsUnder(const Affine& outer) const {
  // A translation moves the box as it is; only a turn or a stretch can
  // make the parts' boxes tighter than the moved corners.
  if (outer.isTranslation()) return Solid::boundsUnder(outer);
  const Bounds local = objectBounds();
  if (local.empty() || !local.finite()) return Solid::boundsUnder(outer);
  return objectBoundsUnder(frame_.then(outer));
}

Bounds Primitive::objectBoundsUnder(const Affine& worldFromObject) const {
  return movedBox(objectBounds(), worldFromObject);
}

bool Primitive::contains(const dvec3& p) const {
  // A point that is no point is in no solid (a sweep's grid of cells
  // would file a NaN somewhere).
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
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

SolidPtr Primitive::placedAs(std::shared_ptr<Primitive> shape) const {
  shape->frame_ = frame_;
  shape->material_ = material_;
  shape->textureFromObject_ = textureFromObject_;
  shape->updateBounds();
  shape->setOrigin(origin());
  return shape;
}

Bounds Primitive::boundsInFrame(const glm::dmat4& worldFromObject) const {
  const Bounds local = objectBounds();
  if (local.empty()) return local;
  // An unbounded shape may reach anywhere once rotated.
  if (!local.finite()) return worldFromObject == glm::dmat4(1.0) ? local : Bounds::everything();
  return movedBox(local, worldFromObject);
}

void Primitive::updateBounds() { bounds_ = boundsInFrame(frame_.worldFromObject()); }

}  // namespace csgray::detail
