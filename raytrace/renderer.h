// Whitted-style ray tracing of a scene (seed 000, 17.1): a primary ray
// through each pixel, the first boundary of the span lists is shaded with
// ambient and Lambert terms from each light that a shadow ray reaches.
#pragma once

#include <optional>

#include "modeler/scene.h"
#include "raytrace/camera.h"
#include "raytrace/image.h"

namespace csgray {

struct RenderOptions {
  int width = 800;
  int height = 600;
  int threads = 0;  // 0: all cores
};

// The first surface a ray meets at t > ray.tMin.
struct SurfaceHit {
  double t;
  Boundary boundary;
};

class Renderer {
 public:
  // Scenes without camera or lights get the defaults of scene.h.
  Renderer(const Scene& scene, const RenderOptions& options);

  Image render() const;

  // The colour of pixel (x, y), and the colour seen along any ray.
  dvec3 shadePixel(int x, int y) const;
  dvec3 trace(const Ray& ray) const;
  std::optional<SurfaceHit> firstHit(const Ray& ray) const;
  // Is there solid anywhere on the open segment from..to?
  bool occluded(const dvec3& from, const dvec3& to) const;

  const CameraSpec& camera() const { return cameraSpec_; }

 private:
  dvec3 shade(const Ray& ray, const SurfaceHit& hit) const;

  const Scene& scene_;
  RenderOptions options_;
  CameraSpec cameraSpec_;
  Camera camera_;
  std::vector<PointLight> lights_;
  double scale_;  // a length for the size of the scene
};

}  // namespace csgray
