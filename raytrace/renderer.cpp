#include "raytrace/renderer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <optional>
#include <unordered_set>
#include <vector>

#include "engine/instance_surface.h"
#include "engine/primitive.h"
#include "raytrace/bumps.h"
#include "raytrace/edge_lines.h"
#include "raytrace/fog.h"
#include "raytrace/optics.h"
#include "raytrace/sampler.h"
#include "raytrace/scattering.h"

namespace csgray::detail {

// What one pixel's rays share: their random numbers and the ray counts.
struct TraceContext {
  explicit TraceContext(const Sampler& sampler) : rng(sampler) {}

  Sampler rng;
  RayCounts counts{};
  // The CAD look's ground shadow where the pixel's first ray met the
  // ground: it changes slowly, so the pixel's other rays take it too
  // instead of tracing up to 24 shadow rays each.
  std::optional<double> skyHidden;
  // Diffuse bounces on the path so far (indirect light).
  int bounces = 0;
  // Where the last shaded boundary's use was found, on this thread
  // (engine/instance_surface.h), if kept.
  UseHint* useHint = nullptr;
  // Where to keep what the camera ray (depth 0) met, if anywhere: the
  // edge lines and the depth and normal images take it from the colour's
  // own trace rather than tracing the ray again. (Kept apart: a context is
  // made for every pixel.)
  struct CameraHit* cameraHit = nullptr;
};

// What the camera ray met, its normal as normalAt gives it, and the use of
// the boundary's primitive.
struct CameraHit {
  std::optional<SurfaceHit> hit;
  dvec3 normal{0.0};
  std::uintptr_t use = 0;
};

namespace {

const Material kDefaultMaterial;

const Material& materialOf(const MaterialPtr& m) { return m ? *m : kDefaultMaterial; }

// The material of a boundary; a boundary at infinity (no primitive) is opaque.
const Material& materialOf(const Boundary& b) {
  return b.primitive ? materialOf(b.primitive->material()) : kDefaultMaterial;
}

double largest(const dvec3& c) { return std::max({c.x, c.y, c.z}); }

// Calls visit(light, point) for each point a shading point samples of each
// light: a point or spot light's one, an area light's drawn ones.
template <class Visit>
void forEachLightSample(const std::vector<Light>& lights, const dvec3& at, Sampler& rng,
                        Visit&& visit) {
  for (const Light& light : lights) {
    for (int i = 0, n = light.sampleCount(); i < n; ++i) {
      double u = 0.5, v = 0.5;  // a point or spot light draws no random numbers
      if (light.isArea()) u = rng.next(), v = rng.next();
      visit(light, light.samplePoint(i, u, v, at));
    }
  }
}

// The filter of a material with a filter distance over `depth` of it.
dvec3 filterOver(const Material& m, double depth) {
  return glm::pow(m.filter, dvec3(depth / m.filterDistance));
}

// What a stretch of a transparent material `depth` long lets through: its
// transparency, and its filter once or, with a filter distance, raised to
// the depth over that distance (the transmissivity T^d of Hall and
// Greenberg, "A Testbed for Realistic Image Synthesis", IEEE CG&A 3(8),
// 1983: light in an absorbing medium falls exponentially with the way it
// travels, the Beer-Lambert law).
dvec3 stretchPass(const Material& m, double depth) {
  if (m.filterDistance <= 0.0) return m.transparency * m.filter;
  return m.transparency * filterOver(m, depth);
}

// Does any primitive of the solid let light through? A shadow ray needs all
// the spans of such a solid (each stretch dims it), and of any other only
// the first boundary (an opaque stretch stops it). A subtree shared by many
// uses (an instance's child) is looked at once: `opaque` holds those found
// to let none through (a million uses of the Sierpinski tetrahedron of
// level 10 took 0.1 s otherwise).
bool letsLightThrough(const Solid& solid, std::unordered_set<const Solid*>& opaque) {
  if (auto* primitive = dynamic_cast<const Primitive*>(&solid))
    return materialOf(primitive->material()).transparency > 0.0;
  if (opaque.count(&solid)) return false;
  for (const SolidPtr& s : solid.children())
    if (letsLightThrough(*s, opaque)) return true;
  opaque.insert(&solid);
  return false;
}

// Does the scene need the box of what it shows (Scene::framedBounds, some
// rays)? A camera without a place, the CAD look's ground, an orthographic
// camera without a width.
bool needsFraming(const Scene& scene) {
  return !scene.camera || scene.cadLook ||
         (scene.camera->orthographic && !(scene.camera->orthoWidth > 0.0));
}

// framed: the scene's framedBounds, where it needsFraming.
CameraSpec cameraFor(const Scene& scene, const RenderOptions& options, const Bounds& framed) {
  // Only unbounded surfaces (planes) and no solid of any size: the bounds
  // are empty, but not because a solid is. (Or only surfaces of nothing:
  // a region offset inwards past its width.)
  if (!scene.camera && scene.bounds().empty() && !scene.surfaces.empty()) {
    const bool unbounded = std::any_of(scene.surfaces.begin(), scene.surfaces.end(),
                                       [](const SurfacePtr& s) { return !s->bounds().empty(); });
    if (!unbounded) throw std::invalid_argument("nothing to frame: the region is empty");
    throw std::invalid_argument(
        "cannot frame an unbounded surface such as a plane: return scene{objects=..., "
        "camera=camera{...}}");
  }
  CameraSpec camera =
      scene.camera ? *scene.camera : frameBounds(framed, double(options.width) / options.height);
  // An orthographic camera without a width shows the whole scene.
  if (camera.orthographic && !(camera.orthoWidth > 0.0))
    camera.orthoWidth =
        framed.finite() && !framed.empty() ? 1.1 * glm::length(framed.size()) : 10.0;
  return camera;
}

// The scene's objects and ghosts as rays walk them (Solid::forRays).
// OpenSCAD's `%`: a ghost is drawn light grey and mostly see-through.
std::vector<SolidPtr> objectsAndGhosts(const Scene& scene) {
  static const MaterialPtr ghost = [] {
    auto m = std::make_shared<Material>();
    m->color = dvec3(0.45);
    m->ambient = 0.4;
    m->diffuse = 0.6;
    m->transparency = 0.75;
    return m;
  }();
  std::vector<SolidPtr> objects;
  for (const SolidPtr& s : scene.objects) objects.push_back(s->forRays());
  for (const SolidPtr& s : scene.ghosts) {
    Solid::SharedMap done;
    objects.push_back(
        s->mapSharedPrimitives([&](const Primitive& p) { return p.withMaterial(ghost); }, done)
            ->forRays());
  }
  return objects;
}

// OpenSCAD's `#`: highlighted solids are laid over the image in a
// translucent pink (sRGB #ff5078), shaded a little so that their shape shows.
constexpr dvec3 kHighlightColor{1.0, 0.0802, 0.1878};
constexpr double kHighlightOpacity = 0.5;

// A length that stands for the scene's size, to scale the surface offset.
double sceneScale(const Scene& scene, const CameraSpec& camera) {
  Bounds b = scene.bounds();
  double scale = glm::length(camera.lookAt - camera.eye);
  if (b.finite()) scale = std::max(scale, glm::length(b.size()));
  return scale;
}

// What a ray met first, as the edge lines compare it; n is the normal there.
SurfaceSample surfaceSample(const SurfaceHit& hit, dvec3 n, std::uintptr_t use, const dvec3& dir) {
  SurfaceSample sample;
  sample.use = use;
  if (glm::dot(n, dir) > 0.0) n = -n;
  sample.surface = hit.surface ? static_cast<const void*>(hit.surface)
                               : static_cast<const void*>(hit.boundary.primitive);
  sample.face = hit.surface ? 0 : hit.boundary.face;
  sample.t = float(hit.t);
  sample.normal = glm::vec3(glm::normalize(n));
  return sample;
}

// The ground shadow's grid (raytrace/ground_shadow_grid.h): cells of this
// many pixels at the camera's target, and at most this many corners (4 MB).
constexpr double kGroundCellPixels = 3.0;
constexpr std::size_t kMaxGroundCorners = std::size_t(1) << 20;

// Bisections that place an edge between two pixel centres: to 1/32 of a pixel.
constexpr int kEdgeBisections = 4;

}  // namespace

Media Media::entered(int solid, const Material& medium) const {
  Media m = *this;
  if (m.count == kMax) {  // deeper nesting than any part needs: forget the outermost
    std::copy(m.object + 1, m.object + kMax, m.object);
    std::copy(m.material + 1, m.material + kMax, m.material);
    --m.count;
  }
  m.object[m.count] = solid;
  m.material[m.count] = &medium;
  ++m.count;
  return m;
}

Media Media::left(int solid) const {
  Media m;
  for (int i = 0; i < count; ++i) {
    if (object[i] == solid) continue;
    m.object[m.count] = object[i];
    m.material[m.count] = material[i];
    ++m.count;
  }
  return m;
}

// Where a ray meets a surface, with what the shading needs.
struct Renderer::ShadingPoint {
  dvec3 point;
  dvec3 normal;  // unit, facing the incoming ray
  const Material* material;
  dvec3 color;  // the material's colour or texture here
};

Renderer::Renderer(const Scene& scene, const RenderOptions& options)
    : sectioned_(options.section ? std::make_shared<const Scene>(sectioned(scene, *options.section))
                                 : nullptr),
      scene_(sectioned_ ? *sectioned_ : scene),
      objects_(objectsAndGhosts(scene_)),
      ghostsFrom_(scene_.objects.size()),
      bvh_([&] {
        std::vector<Bounds> boxes;
        for (const SolidPtr& s : objects_) boxes.push_back(s->bounds());
        for (const SurfacePtr& s : scene_.surfaces) boxes.push_back(s->bounds());
        return Bvh(boxes);
      }()),
      options_(options),
      framed_(!needsFraming(scene) ? Bounds()
              : scene.framedBox    ? *scene.framedBox
                                   : scene.framedBounds()),
      cameraSpec_(cameraFor(scene, options, framed_)),
      camera_(cameraSpec_, options.width, options.height),
      lights_(scene.lights) {
  if (scene.cadLook) {
    cadLook_.emplace(cameraSpec_, double(options.width) / options.height, framed_);
    if (lights_.empty() && scene.defaultLight) lights_ = cadLook_->lights();
    // The ground shadow's cells: a few pixels wide where the camera looks.
    dvec3 lo, hi;
    if (cadLook_->groundRegion(lo, hi)) {
      auto grid = std::make_shared<GroundShadowGrid>(
          dvec2(lo), dvec2(hi),
          kGroundCellPixels * footprint(glm::length(cameraSpec_.lookAt - cameraSpec_.eye)),
          kMaxGroundCorners);
      if (grid->made()) groundShadow_ = grid;
    }
  }
  if (lights_.empty() && scene.defaultLight) lights_.push_back(defaultLight(cameraSpec_));
  std::unordered_set<const Solid*> opaque;
  for (const SolidPtr& s : objects_) {
    s->prepare();
    seeThrough_.push_back(letsLightThrough(*s, opaque));
  }
  for (const SolidPtr& s : scene_.highlights) s->prepare();
  scale_ = sceneScale(scene, cameraSpec_);
  // A camera inside a solid looks out of it: the solid's index holds
  // until its rays leave it. The boundary where the view ray leaves tells
  // which leaf, and so which material, the eye is in.
  SpanList spans;
  Ray view(cameraSpec_.eye, camera_.forward());
  for (std::size_t i = 0; i < objects_.size(); ++i) {
    if (!objects_[i]->contains(cameraSpec_.eye)) continue;
    objects_[i]->spans(view, spans);
    for (const Span& s : spans)
      if (s.in.t <= 0.0 && s.out.t >= 0.0)
        cameraMedia_ = cameraMedia_.entered(int(i), materialOf(s.out));
  }
}

std::optional<SurfaceHit> Renderer::firstHit(const Ray& ray) const {
  std::optional<SurfaceHit> best;
  SpanList spans;
  const std::uint32_t solids = std::uint32_t(objects_.size());
  double tMax = ray.tMax;
  bvh_.traverse(ray, tMax, [&](std::uint32_t i, double) {
    if (i >= solids) {
      const Surface& surface = *scene_.surfaces[i - solids];
      int face = 0;
      std::optional<double> t = surface.hit(ray, &face);
      if (t && *t < tMax) best = SurfaceHit{*t, Boundary{}, &surface, -1, true, face}, tMax = *t;
      return true;
    }
    // The first boundary beyond tMin: an entry, or an exit when the ray
    // starts inside the solid. Nothing beyond the best so far matters.
    if (tMax == ray.tMax) {
      objects_[i]->spansToFirstBoundary(ray, spans);
    } else {
      Ray window = ray;
      window.tMax = tMax;
      objects_[i]->spansToFirstBoundary(window, spans);
    }
    for (const Span& s : spans) {
      bool entering = s.in.t > ray.tMin;
      const Boundary* b = entering ? &s.in : s.out.t > ray.tMin ? &s.out : nullptr;
      if (!b) continue;
      if (b->primitive && b->t < tMax)
        best = SurfaceHit{b->t, *b, nullptr, int(i), entering}, tMax = b->t;
      break;
    }
    return true;
  });
  return best;
}

dvec3 Renderer::normalAt(const SurfaceHit& hit, const Ray& ray, std::uintptr_t* use) const {
  if (hit.surface) return hit.surface->normalAt(ray.at(hit.t), hit.face);
  const BoundarySurface s = boundarySurface(*objects_[std::size_t(hit.object)], ray, hit.boundary);
  if (use) *use = s.use;
  return s.normal;
}

dvec3 Renderer::transmittance(const dvec3& from, const dvec3& to, const Media& inside) const {
  Ray ray(from, to - from, 0.0, 1.0);
  dvec3 pass(1.0);
  SpanList spans;
  const std::uint32_t solids = std::uint32_t(objects_.size());
  double tMax = 1.0;
  // Each stretch inside a transparent solid, and each transparent
  // surface (which has no depth: its filter counts once), dims the light;
  // anything opaque ends the search.
  auto dim = [&](const Material& m, const dvec3& share) {
    pass *= share;
    return m.transparency > 0.0;
  };
  bvh_.traverse(ray, tMax, [&](std::uint32_t i, double) {
    if (i >= solids) {
      const Surface& surface = *scene_.surfaces[i - solids];
      const Material& m = materialOf(surface.material());
      return !surface.hit(ray) || dim(m, m.transparency * m.filter);
    }
    if (i >= ghostsFrom_) return true;  // ghosts cast no shadows
    // A stretch inside the solid: its material is the one of the face
    // where the light enters it (or leaves, if the segment starts inside).
    auto material = [](const Span& s) -> const Material& {
      return materialOf(s.in.t > 0.0 || !s.out.primitive ? s.in : s.out);
    };
    // An opaque solid stops the light wherever it meets the segment: any
    // hit will do, not the nearest. (Its stretch's material would dim the
    // light by a transparency of 0: to nothing.) A transparent solid dims
    // it by every stretch.
    if (!seeThrough_[i]) {
      if (inside.holds(int(i))) {
        // From within: stopped where the way first leaves the solid
        // before the light (POV-Ray's rule, that surfaces cast shadows;
        // the camera in the same solid sees its inner walls).
        objects_[i]->spansToFirstBoundary(ray, spans);
        for (const Span& s : spans) {
          const Boundary& b = s.in.t > 0.0 ? s.in : s.out;
          if (!(b.t > 0.0)) continue;
          if (!(b.primitive && b.t < 1.0)) return true;
          pass = dvec3(0.0);
          return false;
        }
        return true;
      }
      if (!objects_[i]->meetsWindow(ray, spans)) return true;
      pass = dvec3(0.0);
      return false;
    }
    objects_[i]->spans(ray, spans);
    for (const Span& s : spans) {
      if (s.out.t <= 0.0 || s.in.t >= 1.0) continue;
      const Material& m = material(s);
      // (The stretch's length only where the filter depends on it: a
      // square root spared on every other shadow ray.)
      const double depth =
          m.filterDistance > 0.0
              ? (std::min(s.out.t, 1.0) - std::max(s.in.t, 0.0)) * glm::length(to - from)
              : 0.0;
      if (!dim(m, stretchPass(m, depth))) return false;
    }
    return true;
  });
  return pass;
}

double Renderer::offOf(const dvec3& point) const {
  // Far above the rounding of a hit point, far below any feature a part
  // could have: a billionth of the scene's size, and a ten-trillionth of
  // the distance from the origin, about 450 units in the last place of the
  // point's coordinates (a point far off is rounded to them). A billionth
  // of that distance, as it was, is a thousandth at 10⁶: as large as a
  // small part placed there, whose shadows then started beyond it.
  return 1e-9 * scale_ + 1e-13 * glm::length(point);
}

dvec3 Renderer::direct(const ShadingPoint& sp, const dvec3& viewDir, const Media& media,
                       TraceContext& ctx) const {
  const Material& m = *sp.material;
  dvec3 origin = sp.point + offOf(sp.point) * sp.normal;
  // I = Koh·O + Σ Fᵢ·(Kod·O·cos α + r·cos^f β) over the light that shadow
  // rays let through: Lambert's diffuse term and Phong's highlight (Phong,
  // "Illumination for Computer Generated Pictures", 1975; docs/theory.md).
  // The ambient term stands in for the light from other surfaces: left
  // out when indirect light computes that, dimmed where ambient occlusion
  // finds the point hidden.
  dvec3 color(0.0);
  if (scene_.indirect.samples == 0 && m.ambient > 0.0)
    color =
        m.ambient * sp.color * (scene_.ambientOcclusion.samples > 0 ? unoccluded(sp, ctx) : 1.0);
  // A surface with neither term (a pure mirror, a self-coloured target)
  // takes nothing from the lights, so it sends them no shadow rays: each
  // would add radiance · pass · 0.
  if (m.diffuse <= 0.0 && m.specular <= 0.0) return color;
  forEachLightSample(lights_, sp.point, ctx.rng, [&](const Light& light, const dvec3& s) {
    dvec3 l = glm::normalize(s - sp.point);
    double cosAlpha = glm::dot(sp.normal, l);
    if (cosAlpha <= 0.0) return;
    dvec3 radiance = light.radianceAt(sp.point, s);
    if (largest(radiance) <= 0.0) return;
    dvec3 pass(1.0);
    if (light.castsShadows) {
      ++ctx.counts.shadow;
      pass = transmittance(origin, s, media);
      if (largest(pass) <= 0.0) return;
    }
    double highlight = 0.0;
    if (m.specular > 0.0) {
      double cosBeta = glm::dot(reflect(-l, sp.normal), -viewDir);
      if (cosBeta > 0.0) highlight = m.specular * std::pow(cosBeta, m.shininess);
    }
    color += radiance * pass * (m.diffuse * cosAlpha * sp.color + highlight);
  });
  return color;
}

// Hall's transmitted highlight (Hall and Greenberg 1983): the light that
// reaches the point from beyond the surface and passes through it toward
// the eye shows as a highlight where the eye ray, going on through the
// surface (refracted), points near the light: Phong's lobe
// cos^shininess β' with β' the angle between that ray and the light, as
// Phong's highlight takes the angle about the mirrored ray. The shadow
// rays start on the far side: the caller dims what comes through the
// surface itself.
dvec3 Renderer::transmittedHighlight(const ShadingPoint& sp, const dvec3& onward,
                                     TraceContext& ctx) const {
  const Material& m = *sp.material;
  const dvec3 origin = sp.point - offOf(sp.point) * sp.normal;
  const dvec3 along = glm::normalize(onward);
  dvec3 color(0.0);
  forEachLightSample(lights_, sp.point, ctx.rng, [&](const Light& light, const dvec3& s) {
    const dvec3 l = glm::normalize(s - sp.point);
    if (glm::dot(sp.normal, l) >= 0.0) return;  // on the eye's side: direct's
    const double cosBeta = glm::dot(along, l);
    if (cosBeta <= 0.0) return;
    const double highlight = m.transmittedSpecular * std::pow(cosBeta, m.shininess);
    const dvec3 radiance = light.radianceAt(sp.point, s);
    if (highlight <= 0.0 || largest(radiance) <= 0.0) return;
    dvec3 pass(1.0);
    if (light.castsShadows) {
      ++ctx.counts.shadow;
      pass = transmittance(origin, s);
    }
    color += radiance * pass * highlight;
  });
  return color;
}

// Diffuse inter-reflection by path tracing (Kajiya, "The rendering
// equation", SIGGRAPH 1986; docs/theory.md, "Indirect light"): the light a
// Lambertian surface gets from other surfaces is the mean of what rays
// scattered with density cos θ / π see, the albedo applied by the caller.
// What those rays see is shaded as any surface is, so each bounce adds the
// lights' direct part at the point it reaches (next-event estimation) and
// its emission. The camera's surfaces send `samples` rays, each later
// bounce one; past `bounces` bounces a path goes on with probability q
// (its share of the light from here, at most 0.9) and what it brings is
// divided by q (Russian roulette: Arvo and Kirk, "Particle transport and
// image synthesis", SIGGRAPH 1990), so the estimate stays unbiased; 64
// bounces end any path.
dvec3 Renderer::indirect(const ShadingPoint& sp, const Media& media, int depth, double weight,
                         TraceContext& ctx) const {
  constexpr int kMostBounces = 64;
  if (ctx.bounces >= kMostBounces) return dvec3(0.0);
  // Each ray's own roulette: one decision for all of a surface's rays
  // would be as unbiased, but far noisier.
  const double keep = ctx.bounces >= scene_.indirect.bounces
                          ? std::min(0.9, largest(sp.material->diffuse * sp.color))
                          : 1.0;
  const int rays = ctx.bounces == 0 ? scene_.indirect.samples : 1;
  const dvec3 origin = sp.point + offOf(sp.point) * sp.normal;
  dvec3 sum(0.0);
  ++ctx.bounces;
  for (int i = 0; i < rays; ++i) {
    if (keep < 1.0 && !(ctx.rng.next() < keep)) continue;
    const double u = ctx.rng.next(), v = ctx.rng.next();
    sum += trace(Ray(origin, cosineDirection(sp.normal, u, v)), depth + 1, weight, media, ctx);
  }
  --ctx.bounces;
  return sum / (double(rays) * keep);
}

double Renderer::unoccluded(const ShadingPoint& sp, TraceContext& ctx) const {
  const int rays = scene_.ambientOcclusion.samples;
  const double reach =
      scene_.ambientOcclusion.distance > 0.0 ? scene_.ambientOcclusion.distance : 0.1 * scale_;
  const dvec3 origin = sp.point + offOf(sp.point) * sp.normal;
  int open = 0;
  for (int i = 0; i < rays; ++i) {
    const double u = ctx.rng.next(), v = ctx.rng.next();
    ++ctx.counts.shadow;
    open += !firstHit(Ray(origin, cosineDirection(sp.normal, u, v), 0.0, reach));
  }
  return double(open) / rays;
}

dvec3 Renderer::missed(const Ray& ray, TraceContext& ctx) const {
  if (!cadLook_) {
    if (!scene_.sky) return scene_.background;
    const dvec3 direction = glm::normalize(ray.dir);
    return scene_.sky->colorAt(direction, -direction);
  }
  const dvec3 background = cadLook_->background(ray);
  const std::optional<dvec3> ground = cadLook_->groundPoint(ray);
  return ground ? cadLook_->shadowed(background, skyHidden(*ground, ctx)) : background;
}

double Renderer::skyHidden(const dvec3& ground, TraceContext& ctx) const {
  if (ctx.skyHidden) return *ctx.skyHidden;
  std::optional<double> hidden;
  if (groundShadow_)
    hidden = groundShadow_->at(ground, cadLook_->groundZ(),
                               [&](const dvec3& corner) { return skyHiddenAt(corner, true, ctx); });
  // A point the grid does not hold, or one beside a sharp step of the
  // shadow: traced on its own, so to the spiral as it is (no neighbours
  // average it, and drawn points would show their grain), the probes first.
  ctx.skyHidden = hidden ? *hidden : skyHiddenAt(ground, false, ctx);
  return *ctx.skyHidden;
}

double Renderer::footprint(double t) const {
  const double width =
      cameraSpec_.orthographic
          ? cameraSpec_.orthoWidth
          : 2.0 * t * std::tan(0.5 * cameraSpec_.fovDegrees * std::numbers::pi / 180.0);
  return width / options_.width;
}

double Renderer::skyHiddenAt(const dvec3& ground, bool drawn, TraceContext& ctx) const {
  const dvec3 origin = ground + dvec3(0.0, 0.0, offOf(ground));
  const auto sky = cadLook_->skyPointsFor(ground, drawn);
  auto hidden = [&](int i) {
    ++ctx.counts.shadow;
    const dvec3 pass = transmittance(origin, sky[i]);
    return 1.0 - (pass.x + pass.y + pass.z) / 3.0;
  };
  // A grid corner's points drawn for it: every point, since the probes
  // miss where the shadow fades out, and the grid averages the corner with
  // its neighbours, which must agree with it. Not drawn: wholly lit or
  // wholly in shadow when the probes agree, else every point.
  double sum = 0.0;
  for (int i = 0; i < CadLook::kProbes; ++i) sum += hidden(i);
  if (!drawn && (sum == 0.0 || sum == CadLook::kProbes)) return sum / CadLook::kProbes;
  for (int i = CadLook::kProbes; i < CadLook::kSkyPoints; ++i) sum += hidden(i);
  return sum / CadLook::kSkyPoints;
}

dvec3 Renderer::trace(const Ray& ray) const {
  TraceContext ctx{Sampler(0, 0)};
  return trace(ray, 0, 1.0, cameraMedia_, ctx);
}

static_assert((2 << TraceLimits{}.maxDepth) - 1 <= Renderer::kRaysPerCameraRay,
              "the default recursion limits never reach the ray budget");

dvec3 Renderer::trace(const Ray& ray, int depth, double weight, const Media& media,
                      TraceContext& ctx, int raysLeft) const {
  ++(depth == 0 ? ctx.counts.primary : ctx.counts.secondary);
  std::optional<SurfaceHit> hit = firstHit(ray);
  CameraHit* keep = depth == 0 ? ctx.cameraHit : nullptr;
  if (keep) keep->hit = hit;
  // Inside a solid whose filter deepens with depth, what the ray brings
  // back from the next face it meets is dimmed over the way there (the
  // face where it entered applied its transparency alone).
  // In the air (or inside an opaque solid: a room the camera stands in),
  // fog takes its share of what the ray brings back over the way.
  const Material* medium = media.innermost();
  const bool inAir = !medium || medium->transparency == 0.0;
  const auto faded = [&](const dvec3& c) {
    if (inAir ? scene_.fog.distance <= 0.0 : medium->filterDistance <= 0.0) return c;
    const double length = hit ? hit->t * glm::length(ray.dir) : kInfinity;
    if (inAir) return throughFog(scene_.fog, c, ray.origin, glm::normalize(ray.dir), length);
    return c * filterOver(*medium, length);
  };
  if (!hit) return faded(missed(ray, ctx));

  ShadingPoint sp;
  sp.point = ray.at(hit->t);
  double outward = 1.0;  // −1 where the normal was turned to face the ray
  if (hit->surface) {
    const Surface& s = *hit->surface;
    sp.material = &materialOf(s.material());
    sp.normal = s.normalAt(sp.point, hit->face);
    if (keep) keep->normal = sp.normal;
    // A smooth mesh's normal leans away from its triangle's, which is the
    // one that tells the side the ray comes from (both sides are shaded).
    if (glm::dot(s.faceNormal(hit->face), ray.dir) > 0.0) sp.normal = -sp.normal, outward = -1.0;
    const Material& m = *sp.material;
    sp.color = m.color;
    if (m.texture || m.bumps) {
      const dvec3 texturePoint = s.texturePoint(sp.point);
      const dvec3 textureNormal = s.textureNormal(sp.point, hit->face);
      if (m.texture) sp.color = m.texture->colorAt(texturePoint, textureNormal);
      if (m.bumps)
        sp.normal =
            bumpedNormal(m, sp.normal, outward, texturePoint, textureNormal, s.textureFromWorld());
    }
  } else {
    const Boundary& b = hit->boundary;
    sp.material = &materialOf(b);
    const Material& m = *sp.material;
    const bool textured = m.texture || m.bumps;
    const BoundarySurface surface =
        boundarySurface(*objects_[std::size_t(hit->object)], ray, b, textured, ctx.useHint);
    sp.normal = b.flip ? -surface.normal : surface.normal;
    if (keep) keep->normal = surface.normal, keep->use = surface.use;
    sp.color =
        m.texture ? m.texture->colorAt(surface.texturePoint, surface.textureNormal) : m.color;
    if (glm::dot(sp.normal, ray.dir) > 0.0) sp.normal = -sp.normal, outward = -1.0;
    // A subtracted solid's face is raised along the part's outward normal.
    if (m.bumps)
      sp.normal = bumpedNormal(m, sp.normal, outward, surface.texturePoint, surface.textureNormal,
                               surface.textureFromWorld);
  }
  const Material& m = *sp.material;

  // Inside a transparent solid the ray sees the light beyond the face it
  // leaves by: the stretch was dimmed and tinted where the ray entered.
  bool leaving = !hit->surface && !hit->entering && m.transparency > 0.0;
  double kr = leaving ? 0.0 : m.reflection;
  double kt = leaving ? 1.0 : m.transparency;
  // (A solid with a filter distance tints along the way inside instead.)
  const bool tintsInside = !hit->surface && m.filterDistance > 0.0;
  dvec3 tint = leaving || tintsInside ? dvec3(1.0) : m.filter;

  // The media beyond the surface, for a ray that goes on through it (not
  // copied at an opaque one): the span list says whether the ray enters
  // or leaves the solid; an open surface encloses nothing.
  Media beyond;
  if (kt > 0.0)
    beyond = hit->surface    ? media
             : hit->entering ? media.entered(hit->object, m)
                             : media.left(hit->object);
  double n1 = media.current(), n2 = beyond.current();
  // (A surface that passes all light shows none of its own: no shadow rays.)
  dvec3 color(0.0);
  if (!leaving && kt < 1.0) {
    color = direct(sp, ray.dir, media, ctx) + m.emission;
    if (scene_.indirect.samples > 0 && m.diffuse > 0.0)
      color += m.diffuse * sp.color * indirect(sp, media, depth, weight, ctx);
    color *= 1.0 - kt;
  }

  std::optional<dvec3> through = ray.dir;
  if (kt > 0.0 && n1 != n2) {
    through = refract(ray.dir, sp.normal, n1, n2);
    if (!through) {  // total internal reflection: all of it is mirrored
      kr += kt;
      kt = 0.0;
    } else if (m.fresnel) {
      double r = fresnelReflectance(glm::dot(ray.dir, sp.normal), n1, n2);
      kr += kt * r;
      kt *= 1.0 - r;
    }
  }

  // Lights seen through the last face between them and the eye: beyond a
  // transparent surface, or beyond the face by which the ray leaves a
  // transparent solid, so that the light shows where the eye's path,
  // bent at every face before, finally points (through a pane, along the
  // eye ray shifted sideways). Dimmed as what lies beyond: by kt and the
  // tint here, and for a solid by its entry and the way inside.
  if ((leaving || hit->surface) && m.transmittedSpecular > 0.0 && kt > 0.0 && through)
    color += kt * tint * transmittedHighlight(sp, *through, ctx);

  double offset = offOf(sp.point);
  bool deeper = depth < scene_.limits.maxDepth;
  double kTinted = kt * largest(tint);
  bool mirror = kr > 0.0 && deeper && weight * kr >= scene_.limits.minWeight;
  bool onward = kt > 0.0 && deeper && weight * kTinted >= scene_.limits.minWeight;
  // The rays left (kRaysPerCameraRay) go first to the mirrored ray's tree,
  // less one kept for the refracted ray, which gets what that tree leaves:
  // a chain of reflections inside glass takes as many as it needs, as it
  // would without the bound; with room for one only, the ray that carries
  // more of the pixel is traced.
  if (mirror && onward && raysLeft < 2) (kr >= kTinted ? onward : mirror) = false;
  if (raysLeft < 1) mirror = onward = false;
  const std::uint64_t tracedBefore = ctx.counts.secondary;
  // A glossy surface sends each ray into a lobe about the ideal direction.
  auto blurred = [&](const dvec3& ideal, const dvec3& side) {
    if (m.gloss <= 0.0) return ideal;
    const double u = ctx.rng.next(), v = ctx.rng.next();
    return glossyDirection(ideal, side, m.gloss, u, v);
  };
  if (mirror) {
    Ray mirrored(sp.point + offset * sp.normal, blurred(reflect(ray.dir, sp.normal), sp.normal));
    color += kr * trace(mirrored, depth + 1, weight * kr, media, ctx, raysLeft - 1 - int(onward));
  }
  if (onward) {
    const int left = raysLeft - int(ctx.counts.secondary - tracedBefore);
    Ray onwardRay(sp.point - offset * sp.normal, blurred(*through, -sp.normal));
    color += kt * tint * trace(onwardRay, depth + 1, weight * kTinted, beyond, ctx, left - 1);
  }
  return faded(color);
}

dvec3 Renderer::withHighlights(const Ray& ray, const dvec3& color) const {
  std::optional<Boundary> nearest;
  const Solid* nearestSolid = nullptr;
  SpanList spans;
  for (const SolidPtr& s : scene_.highlights) {
    s->spansToFirstBoundary(ray, spans);
    for (const Span& span : spans) {
      const Boundary& b = span.in.t > ray.tMin ? span.in : span.out;
      if (b.primitive && b.t > ray.tMin && (!nearest || b.t < nearest->t))
        nearest = b, nearestSolid = s.get();
      break;
    }
  }
  if (!nearest) return color;
  const dvec3 n = boundarySurface(*nearestSolid, ray, *nearest).normal;
  const double facing = std::abs(glm::dot(glm::normalize(n), glm::normalize(ray.dir)));
  return glm::mix(color, kHighlightColor * (0.6 + 0.4 * facing), kHighlightOpacity);
}

dvec3 Renderer::pixel(int x, int y, int samples, TraceContext& ctx) const {
  auto seen = [&](const Ray& ray) {
    const dvec3 color = trace(ray, 0, 1.0, cameraMedia_, ctx);
    return scene_.highlights.empty() ? color : withHighlights(ray, color);
  };
  const bool blurs = camera_.blurs();
  if (samples <= 1 && !blurs) return seen(camera_.ray(x + 0.5, y + 0.5));
  // Jittered supersampling: one random point in each cell of a k × k grid
  // over the pixel; samples beyond k² fall anywhere in it. Through a lens,
  // each ray also takes a point of the lens from a cell of its own k × k
  // grid: cell i + a shift drawn for the pixel, so that the lens is
  // covered evenly but not in step with the pixel's cells.
  const int k = int(std::sqrt(double(samples))), cells = k * k;
  const int shift = blurs ? int(ctx.rng.next() * cells) : 0;
  dvec3 sum(0.0);
  for (int i = 0; i < samples; ++i) {
    double u = ctx.rng.next(), v = ctx.rng.next();
    if (i < cells) u = (i % k + u) / k, v = (i / k + v) / k;
    if (!blurs) {
      sum += seen(camera_.ray(x + u, y + v));
      continue;
    }
    double lx = ctx.rng.next(), ly = ctx.rng.next();
    if (i < cells) {
      const int cell = (i + shift) % cells;
      lx = (cell % k + lx) / k, ly = (cell / k + ly) / k;
    }
    sum += seen(camera_.ray(x + u, y + v, 2.0 * lx - 1.0, 2.0 * ly - 1.0));
  }
  return sum / double(samples);
}

RenderResult Renderer::renderAll() const {
  const int w = options_.width, h = options_.height;
  RenderResult result;
  result.color = Image::uninitialized(w, h);  // the first pass sets every pixel
  if (options_.depthAov) result.depth = Image(w, h);
  if (options_.normalAov) result.normal = Image(w, h);
  // A lens needs its blur samples at every pixel, the first pass's too.
  const int least = cameraSpec_.blurs() ? cameraSpec_.blurSamples : 1;
  bool refine = options_.adaptive && options_.samples > least;
  // Edge lines need what each pixel's centre ray meets first, all of it,
  // before the last pass draws them.
  const bool edges = options_.edges || scene_.edges;
  std::vector<SurfaceSample> seen(edges ? std::size_t(w) * h : 0);
  const double rows = double(h) * (1 + int(refine) + int(edges));
  std::atomic<int> pixelsDone = 0;
  std::atomic<std::uint64_t> primary = 0, shadow = 0, secondary = 0;
  struct TileWork {
    RayCounts counts;
    UseHint useHint;
  };

  // Runs work(x, y, tile) for every pixel, in tiles of 16 × 16 that the
  // threads take in order, row of tiles by row of tiles from the top; the
  // rays a tile traced are added up once per tile, and its pixels share
  // one hint of where shaded boundaries' uses lie (the tile's TileWork). In the last pass, the
  // tile that finishes a band of rows hands it on (options_.rowsDone).
  constexpr int kTile = 16;
  const int tilesX = (w + kTile - 1) / kTile, tiles = tilesX * ((h + kTile - 1) / kTile);
  const int bandRows = options_.rowsDone ? std::max(options_.bandRows, 0) : 0;
  std::optional<RenderThreads> ownThreads;
  RenderThreads* pool =
      options_.threadPool ? options_.threadPool : &ownThreads.emplace(options_.threads);
  auto cancelled = [this] {
    return options_.cancel && options_.cancel->load(std::memory_order_relaxed);
  };
  auto forEachTile = [&](bool last, auto&& work) {
    // The pixels each band still waits for.
    std::vector<std::atomic<std::int64_t>> waiting(bandRows && last ? (h + bandRows - 1) / bandRows
                                                                    : 0);
    for (std::size_t b = 0; b < waiting.size(); ++b)
      waiting[b] = std::int64_t(std::min(bandRows, h - int(b) * bandRows)) * w;
    auto tile = [&](int i) {
      const int x0 = i % tilesX * kTile, x1 = std::min(w, x0 + kTile);
      const int y0 = i / tilesX * kTile, y1 = std::min(h, y0 + kTile);
      TileWork state;
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
          if (cancelled()) return;  // a band it is in is never handed on
          work(x, y, state);
        }
      primary += state.counts.primary;
      shadow += state.counts.shadow;
      secondary += state.counts.secondary;
      const int pixels = (y1 - y0) * (x1 - x0);
      if (options_.progress) {
        int done = pixelsDone.fetch_add(pixels);
        options_.progress((done + pixels) / (rows * w));
      }
      // A tile's rows may reach into two bands (if bandRows is not a
      // multiple of 16). The atomic counts order the threads' writes: the
      // tile that finishes a band sees the pixels of all the others.
      if (!waiting.empty()) {
        for (int y = y0; y < y1;) {
          const int band = y / bandRows, end = std::min(y1, (band + 1) * bandRows);
          if ((waiting[band] -= std::int64_t(end - y) * (x1 - x0)) == 0)
            options_.rowsDone(result.color, band * bandRows, std::min(h, (band + 1) * bandRows));
          y = end;
        }
      }
    };
    std::atomic<int> next = 0;
    auto take = [&](int) {
      for (int i; (i = next++) < tiles;) tile(i);
    };
    pool->run(take);
    if (cancelled()) throw RenderCancelled();
  };

  auto add = [](RayCounts& sum, const RayCounts& more) {
    sum.primary += more.primary;
    sum.shadow += more.shadow;
    sum.secondary += more.secondary;
  };
  const int samples = refine ? least : std::max(options_.samples, least);
  // What each pixel's centre ray met, for the edge lines and the depth and
  // normal images.
  const bool centre = options_.depthAov || options_.normalAov || edges;
  forEachTile(!refine && !edges, [&](int x, int y, TileWork& tile) {
    TraceContext ctx{Sampler(x, y)};
    ctx.useHint = &tile.useHint;
    if (!centre) {
      result.color.set(x, y, pixel(x, y, samples, ctx));
      add(tile.counts, ctx.counts);
      return;
    }
    // One sample is the centre ray, whose trace keeps what it met.
    std::optional<CameraHit> kept;
    if (samples <= 1 && !camera_.blurs()) ctx.cameraHit = &kept.emplace();
    result.color.set(x, y, pixel(x, y, samples, ctx));
    add(tile.counts, ctx.counts);
    Ray ray = camera_.ray(x + 0.5, y + 0.5);
    const std::optional<SurfaceHit> hit = kept ? kept->hit : firstHit(ray);
    if (options_.depthAov)
      result.depth.set(x, y,
                       dvec3(hit ? hit->t * glm::dot(ray.dir, camera_.forward()) : kInfinity));
    if (!hit) return;
    std::uintptr_t use = kept ? kept->use : 0;
    dvec3 n = kept ? kept->normal : normalAt(*hit, ray, &use);
    if (edges) seen[std::size_t(y) * w + x] = surfaceSample(*hit, n, use, ray.dir);
    if (glm::dot(n, ray.dir) > 0.0) n = -n;
    if (options_.normalAov) result.normal.set(x, y, n);
  });

  if (refine) {
    // Adaptive antialiasing: where a pixel differs from any of its eight
    // neighbours by more than the threshold, it lies on an edge (of a
    // silhouette, shadow or texture) and gets the full sample count.
    Image first = result.color;
    auto differs = [&](int x, int y) {
      dvec3 c = first.at(x, y);
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
          dvec3 d = glm::abs(glm::min(first.at(nx, ny), 1.0) - glm::min(c, 1.0));
          if (largest(d) > options_.adaptiveThreshold) return true;
        }
      return false;
    };
    forEachTile(!edges, [&](int x, int y, TileWork& tile) {
      if (!differs(x, y)) return;
      TraceContext ctx{Sampler(x, y, 1)};
      ctx.useHint = &tile.useHint;
      if (least > 1) {
        // A lens's first rays are samples of the pixel too: kept, and the
        // pixel takes the rest of its samples now.
        const int more = options_.samples - least;
        result.color.set(x, y,
                         (first.at(x, y) * double(least) + pixel(x, y, more, ctx) * double(more)) /
                             double(options_.samples));
      } else {
        result.color.set(x, y, pixel(x, y, options_.samples, ctx));
      }
      add(tile.counts, ctx.counts);
    });
  }
  if (edges) {
    // Each pixel takes the share of a line one pixel wide, centred on the
    // exact edge between it and a neighbour, that falls within it
    // (raytrace/edge_lines.h): 1 − d, for the edge d pixels from its
    // centre, found by bisection along the step between the two centres.
    auto at = [&](int x, int y) -> const SurfaceSample& { return seen[std::size_t(y) * w + x]; };
    auto sampleAt = [&](double px, double py, dvec3& point) {
      const Ray ray = camera_.ray(px, py);
      const std::optional<SurfaceHit> hit = firstHit(ray);
      SurfaceSample sample;
      if (!hit) return sample;
      point = ray.at(hit->t);
      std::uintptr_t use = 0;
      const dvec3 n = normalAt(*hit, ray, &use);
      sample = surfaceSample(*hit, n, use, ray.dir);
      return sample;
    };
    forEachTile(true, [&](int x, int y, TileWork& tile) {
      const SurfaceSample& here = at(x, y);
      const dvec3 centre(x + 0.5, y + 0.5, 0.0);
      dvec3 herePoint = camera_.ray(centre.x, centre.y).at(here.t);
      double coverage = 0.0;
      static constexpr int kSteps[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
      for (const auto& step : kSteps) {
        const int nx = x + step[0], ny = y + step[1];
        if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
        const SurfaceSample& there = at(nx, ny);
        const double t = here.surface && there.surface ? std::min(here.t, there.t)
                         : here.surface                ? here.t
                                                       : there.t;
        const dvec3 therePoint = camera_.ray(nx + 0.5, ny + 0.5).at(there.t);
        if (edgeBetween(here, herePoint, there, therePoint, footprint(t)) == EdgeSide::None)
          continue;
        double lo = 0.0, hi = 1.0;
        for (int i = 0; i < kEdgeBisections; ++i) {
          const double m = 0.5 * (lo + hi);
          dvec3 probePoint(0.0);
          ++tile.counts.primary;
          const SurfaceSample probe =
              sampleAt(centre.x + m * step[0], centre.y + m * step[1], probePoint);
          const double pt = probe.surface && here.surface ? std::min(here.t, probe.t)
                            : here.surface                ? here.t
                                                          : probe.t;
          (edgeBetween(here, herePoint, probe, probePoint, footprint(pt)) == EdgeSide::None ? lo
                                                                                            : hi) =
              m;
        }
        coverage = std::max(coverage, 1.0 - 0.5 * (lo + hi));
      }
      if (coverage > 0.0) result.color.set(x, y, withEdge(result.color.at(x, y), coverage));
    });
  }
  result.rays = RayCounts{primary, shadow, secondary};
  return result;
}

}  // namespace csgray::detail
