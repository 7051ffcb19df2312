#include "raytrace/renderer.h"

#include <oneapi/tbb/blocked_range2d.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "modeler/primitive.h"

namespace csgray {

namespace {

const Material& materialOf(const Boundary& b) {
  static const Material fallback;
  const MaterialPtr& m = b.primitive->material();
  return m ? *m : fallback;
}

CameraSpec cameraFor(const Scene& scene, const RenderOptions& options) {
  if (scene.camera) return *scene.camera;
  return frameBounds(scene.bounds(), double(options.width) / options.height);
}

// A length that stands for the scene's size, to scale the surface offset.
double sceneScale(const Scene& scene, const CameraSpec& camera) {
  Bounds b = scene.bounds();
  double scale = glm::length(camera.lookAt - camera.eye);
  if (b.finite()) scale = std::max(scale, glm::length(b.size()));
  return scale;
}

}  // namespace

Renderer::Renderer(const Scene& scene, const RenderOptions& options)
    : scene_(scene),
      options_(options),
      cameraSpec_(cameraFor(scene, options)),
      camera_(cameraSpec_, options.width, options.height),
      lights_(scene.lights) {
  if (lights_.empty()) lights_.push_back(defaultLight(cameraSpec_));
  scale_ = sceneScale(scene, cameraSpec_);
}

std::optional<SurfaceHit> Renderer::firstHit(const Ray& ray) const {
  std::optional<SurfaceHit> best;
  SpanList spans;
  for (const SolidPtr& object : scene_.objects) {
    if (!object->bounds().hitBy(ray)) continue;
    object->spans(ray, spans);
    // The first boundary beyond tMin: an entry, or an exit when the ray
    // starts inside the solid.
    for (const Span& s : spans) {
      const Boundary* b = s.in.t > ray.tMin ? &s.in : s.out.t > ray.tMin ? &s.out : nullptr;
      if (!b) continue;
      if (b->primitive && (!best || b->t < best->t)) best = SurfaceHit{b->t, *b};
      break;
    }
  }
  return best;
}

bool Renderer::occluded(const dvec3& from, const dvec3& to) const {
  Ray ray(from, to - from, 0.0, 1.0);
  SpanList spans;
  for (const SolidPtr& object : scene_.objects) {
    if (!object->bounds().hitBy(ray)) continue;
    object->spans(ray, spans);
    for (const Span& s : spans)
      if (s.out.t > 0.0 && s.in.t < 1.0) return true;
  }
  return false;
}

dvec3 Renderer::shade(const Ray& ray, const SurfaceHit& hit) const {
  const Boundary& b = hit.boundary;
  const Material& m = materialOf(b);
  dvec3 p = ray.at(hit.t);
  dvec3 n = b.primitive->normal(p, b.face);
  if (b.flip) n = -n;
  // Light the side the viewer sees.
  if (glm::dot(n, ray.dir) > 0.0) n = -n;
  // Start shadow rays just off the surface: far above the rounding of a hit
  // point (~1e-16 relative), far below any feature a part could have.
  dvec3 origin = p + (1e-9 * (scale_ + glm::length(p))) * n;

  // I = Koh·O + Σ Kod·O·Fᵢ·(lᵢ·n) over the lights that a shadow ray reaches
  // (seed 001, 2.2.1 and 2.3; seed 000, 17.4.2).
  dvec3 color = m.ambient * m.color;
  for (const PointLight& light : lights_) {
    dvec3 toLight = light.position - p;
    double cosine = glm::dot(n, glm::normalize(toLight));
    if (cosine <= 0.0) continue;
    if (occluded(origin, light.position)) continue;
    color += m.diffuse * cosine * light.intensity * light.color * m.color;
  }
  return color;
}

dvec3 Renderer::trace(const Ray& ray) const {
  std::optional<SurfaceHit> hit = firstHit(ray);
  return hit ? shade(ray, *hit) : scene_.background;
}

dvec3 Renderer::shadePixel(int x, int y) const { return trace(camera_.ray(x + 0.5, y + 0.5)); }

Image Renderer::render() const {
  Image image(options_.width, options_.height);
  auto tile = [&](const tbb::blocked_range2d<int>& r) {
    for (int y = r.rows().begin(); y < r.rows().end(); ++y)
      for (int x = r.cols().begin(); x < r.cols().end(); ++x) image.set(x, y, shadePixel(x, y));
  };
  tbb::blocked_range2d<int> all(0, options_.height, 16, 0, options_.width, 16);
  if (options_.threads > 0) {
    tbb::task_arena arena(options_.threads);
    arena.execute([&] { tbb::parallel_for(all, tile); });
  } else {
    tbb::parallel_for(all, tile);
  }
  return image;
}

}  // namespace csgray
