// A section: the part cut by a plane at render time, to see inside it. Each
// solid is intersected with the half-space {p : normal·p <= offset}, whose
// face carries the section colour, so the cut faces show where the plane
// passes through material; the model itself is not changed. Exact: the
// renderer's span lists already know inside from outside, so the cut is
// the half-space's boundary wherever a span begins on the plane.
#pragma once

#include <memory>

#include "scene/material.h"
#include "scene/scene.h"

namespace csgray::detail {

struct SectionPlane {
  dvec3 normal{0.0, 0.0, 1.0};  // the side kept is normal·p <= offset
  double offset = 0.0;
};

// The colour of the cut faces (linear): a warm red, unlike any part's default grey.
dvec3 sectionColor();
// The material of the cut faces, one for every section: a face with it is a cut.
const MaterialPtr& sectionMaterial();

// The scene with each solid cut by the plane (its ghosts and highlights
// too); open surfaces are kept as they are. Throws std::invalid_argument for a zero or non-finite
// normal.
Scene sectioned(const Scene& scene, const SectionPlane& plane);

}  // namespace csgray::detail
