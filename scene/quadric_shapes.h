// The named quadrics (docs/theory.md, "Quadrics") from their semi-axes, and
// clip, which bounds an unbounded solid: the script's hyperboloid1{},
// ..., clip() and the library's factories, with the same checks and
// messages. Each throws std::invalid_argument.
#pragma once

#include <optional>
#include <vector>

#include "engine/solid.h"
#include "scene/material.h"

namespace csgray::detail {

enum class NamedQuadric {
  Hyperboloid1,          // x²/a² + y²/b² − z²/c² <= 1
  Hyperboloid2,          // x²/a² + y²/b² − z²/c² <= −1
  EllipticCone,          // x²/a² + y²/b² <= z²/c²
  EllipticParaboloid,    // x²/a² + y²/b² <= z
  HyperbolicParaboloid,  // x²/a² − y²/b² <= z
  EllipticCylinder,      // x²/a² + y²/b² <= 1
  HyperbolicCylinder,    // x²/a² − y²/b² >= 1
  ParabolicCylinder,     // y² <= 2px
};

// The script function: "hyperboloid1", "elliptic_cone", ...
const char* quadricName(NamedQuadric kind);
// Does it take c (the hyperboloids and the cone), or p (the parabolic
// cylinder) instead of a and b?
bool takesC(NamedQuadric kind);
bool takesP(NamedQuadric kind);

// The parameters the kind takes, each required.
struct QuadricAxes {
  std::optional<double> a, b, c, p;
};
SolidPtr namedQuadricShape(NamedQuadric kind, const QuadricAxes& axes);

// The box from lo to hi that clip{lo=, hi=} cuts with; both are required.
SolidPtr clipBoxShape(const std::optional<dvec3>& lo, const std::optional<dvec3>& hi);
// The solid intersected with every cutter. Clipping only bounds the solid:
// cutters without a material of their own take the solid's when the whole
// solid has one, so that the faces they add look like the rest of it.
SolidPtr clippedShape(const SolidPtr& solid, std::vector<SolidPtr> cutters);
// The one material of all the solid's primitives, or null if they have
// none or several.
MaterialPtr uniformMaterial(const Solid& solid);

}  // namespace csgray::detail
