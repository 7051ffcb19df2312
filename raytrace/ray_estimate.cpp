#include "raytrace/ray_estimate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unordered_set>
#include <vector>

#include "engine/primitive.h"

namespace csgray::detail {

namespace {

// The materials of the scene's primitives and surfaces; a shared part is
// visited once. A primitive without a material has the default one, which
// neither mirrors nor lets light through, and adds nothing here.
std::vector<const Material*> materialsOf(const Scene& scene) {
  std::vector<const Material*> materials;
  std::unordered_set<const Solid*> seen;
  std::vector<const Solid*> stack;
  for (const SolidPtr& object : scene.objects) stack.push_back(object.get());
  while (!stack.empty()) {
    const Solid* solid = stack.back();
    stack.pop_back();
    if (!seen.insert(solid).second) continue;
    if (auto* primitive = dynamic_cast<const Primitive*>(solid))
      if (primitive->material()) materials.push_back(primitive->material().get());
    for (const SolidPtr& child : solid->children()) stack.push_back(child.get());
  }
  for (const SurfacePtr& surface : scene.surfaces)
    if (surface->material()) materials.push_back(surface->material().get());
  return materials;
}

// The rays one camera ray's tree traces at most (Renderer::trace): a ray
// goes on only while depth < maxDepth and its share of the pixel stays at
// or above minWeight. A hit passes on at most k of its share to each ray
// it spawns: reflection + transparency (Fresnel and total internal
// reflection move transparency to the mirrored ray) or transparency × the
// filter. Only a material that lets light through spawns two rays (one
// mirrored, one refracted); mirrors alone make a chain.
double rayTreeSize(const Scene& scene) {
  double k = 0.0;
  bool mirrors = false, passes = false;
  for (const Material* m : materialsOf(scene)) {
    const double filter = std::max({m->filter.x, m->filter.y, m->filter.z});
    k = std::max({k, m->reflection + m->transparency, m->transparency * filter});
    mirrors |= m->reflection > 0.0;
    passes |= m->transparency > 0.0;
  }
  if (!mirrors && !passes) return 1.0;
  double depth = scene.limits.maxDepth;
  const double minWeight = scene.limits.minWeight;
  // k^d >= minWeight bounds the depth d a ray reaches (rounded up: a
  // bound).
  if (k < 1.0 && minWeight > 0.0)
    depth = std::min(depth, std::floor(std::log(minWeight) / std::log(k) + 1e-9));
  const double rays = passes ? std::exp2(depth + 1.0) - 1.0 : depth + 1.0;
  return std::min(rays, double(Renderer::kRaysPerCameraRay));
}

// With indirect light each surface of the tree sends `samples` paths of
// one ray a bounce: `bounces` of them for sure, then as many as Russian
// roulette keeps (at most 0.9 of the time: 10 more on average), 64 at most.
double raysPerCameraRay(const Scene& scene) {
  const double tree = rayTreeSize(scene);
  if (scene.indirect.samples == 0) return tree;
  const double path = std::min(64.0, scene.indirect.bounces + 10.0);
  return tree * (1.0 + scene.indirect.samples * path);
}

}  // namespace

std::string RayEstimate::factors() const {
  char text[200];
  std::snprintf(text, sizeof text,
                "%.0f camera rays × up to %.0f ray%s each × (1 + %.0f shadow ray%s from %zu "
                "light%s)",
                cameraRays, raysPerCameraRay, raysPerCameraRay == 1.0 ? "" : "s", shadowRaysPerHit,
                shadowRaysPerHit == 1.0 ? "" : "s", lights, lights == 1 ? "" : "s");
  return text;
}

RayEstimate estimateRays(const Scene& scene, const RenderOptions& options) {
  RayEstimate estimate;
  const double pixels = double(options.width) * options.height;
  // As Renderer::renderAll: a lens's blur samples at every pixel, and with
  // the adaptive pass --samples in all at those on edges (at most every
  // pixel); without a lens that pass does not keep the first pass's ray.
  const int least = scene.camera && scene.camera->blurs() ? scene.camera->blurSamples : 1;
  const bool refine = options.adaptive && options.samples > least;
  estimate.cameraRays =
      pixels * (refine ? options.samples + (least > 1 ? 0 : 1) : std::max(options.samples, least));
  estimate.raysPerCameraRay = raysPerCameraRay(scene);
  if (!scene.lights.empty()) {
    estimate.lights = scene.lights.size();
    estimate.shadowRaysPerHit = 0.0;
    for (const Light& light : scene.lights) estimate.shadowRaysPerHit += light.sampleCount();
  } else if (!scene.defaultLight) {
    // Lit by ambient light and emission alone: no shadow rays.
    estimate.lights = 0;
    estimate.shadowRaysPerHit = 0.0;
  } else if (scene.cadLook) {
    // Key, fill and rim, of which the key casts shadows; a ray that meets
    // nothing may look for the ground's shadow instead.
    estimate.lights = 3;
    estimate.shadowRaysPerHit = CadLook::kSkyPoints;
  }
  // Ambient occlusion's rays are counted with the shadow rays.
  estimate.shadowRaysPerHit += scene.ambientOcclusion.samples;
  return estimate;
}

}  // namespace csgray::detail
