// The most rays a render can trace, counted before it starts, so that a
// request that would run for days (thousands of area lights of a thousand
// samples each) is refused with the figure rather than traced.
#pragma once

#include <string>

#include "raytrace/renderer.h"

namespace csgray::detail {

// Each factor is an upper bound; their product is what the worst pixel
// would cost if every pixel were as bad.
struct RayEstimate {
  double cameraRays = 0.0;  // pixels × samples (and the first pass of --adaptive)
  // Rays each camera ray's tree of mirrored and refracted rays traces at
  // most, itself included (Renderer::kRaysPerCameraRay at most).
  double raysPerCameraRay = 1.0;
  // Shadow rays at each point shaded: the sum over the lights (the default
  // one when there are none) of their samples.
  double shadowRaysPerHit = 1.0;
  std::size_t lights = 1;

  double total() const { return cameraRays * raysPerCameraRay * (1.0 + shadowRaysPerHit); }
  // The factors as a message shows them: "480000 camera rays × up to 1 ray
  // each × (1 + 2048000 shadow rays from 2000 lights)".
  std::string factors() const;
};

RayEstimate estimateRays(const Scene& scene, const RenderOptions& options);

}  // namespace csgray::detail
