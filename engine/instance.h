// A use of a shared solid in another place: the child tree is stored once
// and every instance holds it with its own frame, so a part used many times
// (the copies of a fractal's level, the parts of an assembly) costs memory
// for each distinct part, not for each use. A ray is taken into the child's
// frame, with its direction left unnormalised so that t stays the world's,
// and the child's boundaries come back as they are: they name the child's
// primitives, whose frames are the child's, so the surface at a boundary is
// found with the instance frames on the way to it (engine/instance_surface.h).
#pragma once

#include <mutex>

#include "engine/solid.h"

namespace csgray::detail {

class Instance : public Solid {
 public:
  Instance(SolidPtr child, const Affine& worldFromChild);

  const SolidPtr& child() const { return child_; }
  const Affine& frame() const { return worldFromChild_; }
  // The ray in the child's frame, with the same t (and 1/dir, which the
  // child's boxes need).
  Ray rayToChild(const Ray& ray) const;
  // The child's box under the composed frames (a turned lens keeps the
  // box its balls and cylinder give, not its turned box's corners').
  Bounds boundsUnder(const Affine& outer) const override;

  const Bounds& bounds() const override { return bounds_; }
  const Bounds& rayBox() const override { return rayBox_; }
  void spans(const Ray& ray, SpanList& out) const override;
  void spansToFirstBoundary(const Ray& ray, SpanList& out) const override;
  bool firstBoundaryCutsShort() const override { return child_->firstBoundaryCutsShort(); }
  bool meetsWindow(const Ray& ray, SpanList& scratch) const override;
  bool contains(const dvec3& p) const override;
  void prepare() const override { child_->prepare(); }
  SolidPtr forRays() const override;
  std::span<const SolidPtr> children() const override { return {&child_, 1}; }
  // What the user made and moved: "union", ...
  std::string kind() const override { return child_->kind(); }
  const Instance* asInstance() const override { return this; }
  // The child's primitives moved into this instance's frame, then f.
  SolidPtr mapPrimitives(const PrimitiveMap& f) const override;
  SolidPtr mapSharedPrimitives(const PrimitiveMap& f, SharedMap& done) const override;

 private:
  SolidPtr child_;
  Affine worldFromChild_;
  Bounds bounds_;
  Bounds rayBox_;  // within bounds_
  // forRays()'s union (keptFlatUnion) when it is not this use (which it cannot hold).
  mutable std::once_flag flatMade_;
  mutable SolidPtr flat_;
};

// The same solid with every instance replaced by a copy of its child in
// the instance's frame (the solid itself when it has none): for consumers
// that read primitives' frames directly (meshes, the check, hulls).
SolidPtr flattened(const SolidPtr& solid);

}  // namespace csgray::detail
