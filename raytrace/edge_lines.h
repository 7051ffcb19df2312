// Edge lines over a render, as a CAD viewer draws them: the outline of the
// part against the background and against what lies behind it, and the
// creases where two faces meet at an angle. They are found from what the
// ray through each pixel's centre meets first, exactly: the span boundary
// names its primitive and face, and its normal and distance are those of
// the true surface. Two neighbouring pixels are split by an edge when
// - one meets the part and the other nothing (an outline);
// - each lies off the other's tangent plane by more than a couple of
//   pixels (a jump in depth: an outline over a farther surface);
// - they are on different faces (another primitive, another use of it
//   placed by an instance, or another face of it) whose normals differ by
//   more than the crease angle.
// Faces that meet flush or tangentially (a union of two boxes side by
// side, a fillet) get no line, nor do the triangles of a smooth mesh.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>

#include "engine/ray.h"

namespace csgray::detail {

// What the ray through a pixel's centre meets first.
struct SurfaceSample {
  const void* surface = nullptr;  // the primitive or open surface; null: nothing
  std::uintptr_t use = 0;         // which use of a shared primitive (BoundarySurface::use)
  int face = 0;                   // the primitive's face
  float t = 0.0f;                 // distance along the unit ray
  glm::vec3 normal{0.0f};         // unit, turned to face the eye
};

struct EdgeStyle {
  double creaseDegrees = 30.0;  // faces meeting at a sharper angle get a line
  double jumpPixels = 2.0;      // a step in depth of more pixels than this is an outline
  dvec3 color{0.02};            // linear
  double opacity = 0.85;
};

// Whether an edge lies between two samples, and which of them is on the
// nearer surface (the first on a tie). a and b are the samples, pa and pb
// the points they hit, and footprint the width of a pixel at their
// distance. The renderer draws a line one pixel wide centred on the edge,
// each pixel darkened by the share of the line that falls within it, so
// that the lines are smooth and lie where the edges are to a fraction of a
// pixel: it finds where the edge crosses the step between two pixel
// centres by bisection with this test.
enum class EdgeSide { None, First, Second };
EdgeSide edgeBetween(const SurfaceSample& a, const dvec3& pa, const SurfaceSample& b,
                     const dvec3& pb, double footprint, const EdgeStyle& style = {});

// The colour of a pixel that the line covers by the share coverage (0 to 1).
inline dvec3 withEdge(const dvec3& color, double coverage = 1.0, const EdgeStyle& style = {}) {
  return color + coverage * style.opacity * (style.color - color);
}

}  // namespace csgray::detail
