// The surface at a boundary, in the world's frame. A boundary names a
// primitive, whose frame is the world's unless the primitive lies under
// instances (engine/instance.h): a shared primitive is in its instance's
// child's frame, and the boundary alone does not say which of its uses the
// ray met. The use is found again from the root: down the instances whose
// boxes hold the point, to the primitive that has a boundary there, and its
// normal is brought back up through their frames. Only the one boundary
// that is shaded pays for it; a tree without instances pays nothing.
#pragma once

#include <cstdint>

#include "engine/solid.h"

namespace csgray::detail {

struct BoundarySurface {
  dvec3 normal;         // unit, outward from the primitive (a flip is the caller's)
  dvec3 texturePoint;   // Primitive::texturePoint, when asked for
  dvec3 textureNormal;  // Primitive::textureNormal, when asked for
  // Primitive::textureFromWorld, when asked for, under the frames of the
  // instances on the way (the derivative of texturePoint by the point
  // where the ray met the surface).
  glm::dmat3 textureFromWorld{1.0};
  // Which use of the primitive: 0 where it has one; under instances, a key
  // of the instances on the way to it, the same for the same use (the edge
  // lines tell two uses of one primitive apart by it).
  std::uintptr_t use = 0;
};

class Instance;

// Where the last search found its use: the root searched and the
// instances on the way, outermost first. Neighbouring pixels mostly see
// the same part, so a renderer keeps one hint per thread and tries that
// way first, for whichever primitive of the part the boundary names, if
// the primitive is known to lie under the way's last instance with no
// other instance between (its child and the primitive were seen together
// at the end of a way before: `known`).
struct UseHint {
  static constexpr int kMaxInstances = 16;
  static constexpr int kKnown = 8;
  struct Reach {
    const Solid* subtree = nullptr;  // the child of a way's last instance (or the root)
    const Primitive* primitive = nullptr;
  };

  const Solid* root = nullptr;  // null: no hint
  int instances = 0;
  const Instance* chain[kMaxInstances];
  Reach known[kKnown];  // the last few seen, oldest overwritten first
  int nextKnown = 0;

  // Where the way ends: its last instance's child, or the root.
  const Solid* wayEnd() const;
  bool knows(const Solid* subtree, const Primitive* primitive) const;
  void learn(const Solid* subtree, const Primitive* primitive);
};

// The surface at boundary b (b.primitive not null) of a ray through root,
// given in the frame root is in. With a hint, the use of b's primitive on
// its way is offered first and taken when it has a boundary on b's face
// within rounding of b.t, which is what ends the search too; after a
// search the hint is the way to the use found. (The search takes the first such use in its order,
// the hint the last one found: they differ only where two uses of one primitive have that face at
// one point of the ray.)
BoundarySurface boundarySurface(const Solid& root, const Ray& ray, const Boundary& b,
                                bool texture = false, UseHint* hint = nullptr);

}  // namespace csgray::detail
