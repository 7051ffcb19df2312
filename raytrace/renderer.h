// Whitted-style recursive ray tracing of a scene (Whitted, "An Improved
// Illumination Model for Shaded Display", 1980; docs/theory.md): a primary
// ray through each pixel; at the first surface, ambient, Lambert and Phong
// terms from every light that shadow rays reach (dimmed, not blocked, by
// transparent solids), plus the colours of the mirrored and the refracted
// ray, traced the same way up to a depth and weight limit.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <vector>

#include "engine/bvh.h"
#include "raytrace/cad_look.h"
#include "raytrace/ground_shadow_grid.h"
#include "raytrace/image.h"
#include "raytrace/render_threads.h"
#include "raytrace/section_plane.h"
#include "scene/camera.h"
#include "scene/scene.h"

namespace csgray::detail {
class Sampler;
struct TraceContext;
}  // namespace csgray::detail

namespace csgray::detail {

struct RenderOptions {
  RenderOptions(int w = 800, int h = 600, int threadCount = 0)
      : width(w), height(h), threads(threadCount) {}

  int width;
  int height;
  int threads;  // 0: one per core (RenderThreads::cores)
  // The threads to render on, made beforehand (the command line makes them
  // before the script runs); if null, the render makes its own, as many as
  // threads says.
  RenderThreads* threadPool = nullptr;
  // Rays per pixel, jittered within the pixel on a stratified grid.
  int samples = 1;
  // Spend the samples only on pixels whose colour differs from a
  // neighbour's by more than adaptiveThreshold (edges); others keep one.
  bool adaptive = false;
  double adaptiveThreshold = 0.02;
  // Also produce depth and normal images (arbitrary output values).
  bool depthAov = false;
  bool normalAov = false;
  // Draw edge lines (raytrace/edge_lines.h), as scene.edges does too.
  bool edges = false;
  // Cut every solid by this plane, the cut faces in the section colour
  // (raytrace/section_plane.h); the camera, the CAD look's ground and the
  // framing stay those of the whole part.
  std::optional<SectionPlane> section;
  // Called from worker threads with the share of the image done, in [0, 1].
  std::function<void(double)> progress;
  // Called once for each band of bandRows rows of the colour image, rows
  // [first, last) (the last band may be shorter), as soon as its pixels
  // are final, on the worker thread that finished it, while the render
  // goes on: so a PNG file can be compressed band by band meanwhile. Tiles
  // are rendered in rows from the top, so bands finish from the top down.
  int bandRows = 0;
  std::function<void(const Image& color, int first, int last)> rowsDone;
  // When set, read before each pixel: once it is true the threads stop
  // and renderAll throws RenderCancelled (a time limit sets it from a
  // timer). A pixel is the unit because one may take seconds.
  const std::atomic<bool>* cancel = nullptr;
};

// A render stopped by RenderOptions::cancel; its image is not made.
class RenderCancelled : public std::runtime_error {
 public:
  RenderCancelled() : std::runtime_error("the render was cancelled") {}
};

// What the renderer makes: the colour image, and the AOVs asked for. Depth
// is the distance from the eye along the view direction to the surface a
// pixel's centre ray meets first (+inf where it meets nothing); normal the
// unit normal there, facing the eye (0 where it meets nothing).
// How many rays a render traced: through pixels, to lights, and mirrored or
// refracted.
struct RayCounts {
  std::uint64_t primary = 0, shadow = 0, secondary = 0;
};

struct RenderResult {
  Image color, depth, normal;
  RayCounts rays;
};

// A ray's first surface: a boundary of a solid's spans, or an open surface.
struct SurfaceHit {
  double t;
  Boundary boundary;                 // a solid's; primitive is null for an open surface
  const Surface* surface = nullptr;  // an open surface's
  int object = -1;                   // index of the solid in scene.objects
  bool entering = true;              // the ray enters the solid here (a span's start)
  int face = 0;                      // an open surface's face (a mesh's triangle)
};

// The media a ray is in: the solids it has entered, innermost (last
// entered) on top, each with the material of the face the ray entered by
// (its index of refraction, and how it dims light with depth).
struct Media {
  static constexpr int kMax = 8;
  int count = 0;
  int object[kMax];
  const Material* material[kMax];

  // The innermost medium's material, or null outside every solid.
  const Material* innermost() const { return count ? material[count - 1] : nullptr; }
  double current() const { return count ? material[count - 1]->ior : 1.0; }
  Media entered(int solid, const Material& m) const;
  Media left(int solid) const;
  bool holds(int solid) const { return std::find(object, object + count, solid) != object + count; }
};

class Renderer {
 public:
  // Scenes without camera or lights get the defaults of scene.h.
  Renderer(const Scene& scene, const RenderOptions& options);

  Image render() const { return renderAll().color; }
  RenderResult renderAll() const;

  // At most this many rays trace a camera ray's colour: it and the rays
  // reflected and refracted from it. A material that mirrors all light and
  // passes all of it too (reflection = transparency = 1) keeps every ray's
  // weight at 1, so min_weight never stops the tree from doubling at each
  // bounce: 2^64 rays at max_depth 64. (The default max_depth of 8 stays
  // within it: 511 rays at most.)
  static constexpr int kRaysPerCameraRay = 1024;

  // The colour seen along a ray from the camera's medium.
  dvec3 trace(const Ray& ray) const;
  std::optional<SurfaceHit> firstHit(const Ray& ray) const;
  // The unit normal where firstHit(ray) met a surface, outward from the
  // primitive or the open surface's own (a subtracted solid's flip not
  // applied). use, when given, is set to which use of a shared primitive
  // it is (BoundarySurface::use).
  dvec3 normalAt(const SurfaceHit& hit, const Ray& ray, std::uintptr_t* use = nullptr) const;
  // The share of light that passes from one point to another: 0 where
  // something opaque lies between, the transparency and filter colour of
  // each stretch of a transparent solid (and each transparent surface)
  // on the way multiplied otherwise. Rays are not bent on the way. An
  // opaque solid that `from` is inside of (one of `inside`'s: a room the
  // camera stands in) stops the light only where the way leaves it, as
  // its walls would.
  dvec3 transmittance(const dvec3& from, const dvec3& to, const Media& inside = {}) const;

  const CameraSpec& camera() const { return cameraSpec_; }
  const std::vector<Light>& lights() const { return lights_; }

 private:
  struct ShadingPoint;
  // raysLeft: how many rays the tree below this one may trace.
  dvec3 trace(const Ray& ray, int depth, double weight, const Media& media, TraceContext& ctx,
              int raysLeft = kRaysPerCameraRay - 1) const;
  // media: those the point is in (transmittance's `inside`).
  dvec3 direct(const ShadingPoint& sp, const dvec3& viewDir, const Media& media,
               TraceContext& ctx) const;
  // Hall's transmitted highlight: the lights beyond a transparent face
  // seen through it, about `onward`, the way the eye ray goes on past it.
  dvec3 transmittedHighlight(const ShadingPoint& sp, const dvec3& onward, TraceContext& ctx) const;
  // The light that reaches a point from other surfaces (the scene's
  // indirect light): the mean of what diffusely scattered rays see.
  dvec3 indirect(const ShadingPoint& sp, const Media& media, int depth, double weight,
                 TraceContext& ctx) const;
  // The share of diffusely scattered rays from a point that meet nothing
  // within the ambient occlusion's distance.
  double unoccluded(const ShadingPoint& sp, TraceContext& ctx) const;
  dvec3 pixel(int x, int y, int samples, TraceContext& ctx) const;
  // What a ray that meets nothing sees: the background, and in the CAD
  // look the ground's shadow.
  dvec3 missed(const Ray& ray, TraceContext& ctx) const;
  // The share of the CAD look's sky that the scene hides from a ground point.
  // From the ground shadow's grid where it has the point, else traced.
  double skyHidden(const dvec3& ground, TraceContext& ctx) const;
  // Traced: the sky points' shadow rays from the ground point, to the
  // points drawn for it (a grid corner: every point) or, unless drawn, to
  // the spiral itself, the probes first (CadLook::skyPointsFor).
  double skyHiddenAt(const dvec3& ground, bool drawn, TraceContext& ctx) const;
  // The width of a pixel at distance t along a camera ray.
  double footprint(double t) const;
  // The colour a camera ray sees with the scene's highlighted solids laid
  // over it (OpenSCAD's `#`): drawn on top, whatever is in front.
  dvec3 withHighlights(const Ray& ray, const dvec3& color) const;
  // How far off the surface at point rays start that leave it (shadow,
  // mirrored, refracted and scattered rays), so that they do not meet it.
  double offOf(const dvec3& point) const;

  std::shared_ptr<const Scene> sectioned_;  // the scene cut, when options.section says
  const Scene& scene_;                      // the scene rendered: the given one, or sectioned_
  // The scene's objects, then its ghosts in their see-through grey (items
  // ghostsFrom_ on), which take no part in shadows.
  std::vector<SolidPtr> objects_;
  std::size_t ghostsFrom_;
  // Over the objects_ (items 0 .. n−1) and then the surfaces.
  Bvh bvh_;
  RenderOptions options_;
  Bounds framed_;  // what the camera frames, where it needs it (needsFraming)
  CameraSpec cameraSpec_;
  Camera camera_;
  std::vector<Light> lights_;
  std::optional<CadLook> cadLook_;                        // for a bare solid's scene
  std::shared_ptr<const GroundShadowGrid> groundShadow_;  // its shadow, where it has a ground
  Media cameraMedia_;
  std::vector<bool> seeThrough_;  // per object: does any of it let light through?
  double scale_;                  // a length for the size of the scene
};

}  // namespace csgray::detail
