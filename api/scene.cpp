// csgray::Scene: what the script's scene{} holds, checked as it checks it
// (scene/scene.h, light.h, camera.h).
#include "csgray/scene.h"

#include "api/access.h"
#include "api/convert.h"
#include "api/errors.h"
#include "engine/boolean.h"

namespace csgray {

using detail::Access;
using detail::guarded;
using detail::toDetail;

Scene::Scene() : impl_(std::make_unique<Impl>()) {}

Scene::Scene(const Solid& part) : Scene() {
  add(part);
  impl_->scene.cadLook = true;  // as a script's bare solid (sceneOfValue)
}

Scene::Scene(const Scene& other) : impl_(std::make_unique<Impl>(*other.impl_)) {}

Scene& Scene::operator=(const Scene& other) {
  if (this != &other) impl_ = std::make_unique<Impl>(*other.impl_);
  return *this;
}

// A moved-from scene is empty again, not broken: it gets a new state
// before it gives up its own (so not noexcept: that may not allocate).
Scene::Scene(Scene&& other) : impl_(std::make_unique<Impl>()) { std::swap(impl_, other.impl_); }

Scene& Scene::operator=(Scene&& other) noexcept {
  std::swap(impl_, other.impl_);
  return *this;
}

Scene::~Scene() = default;

// Objects are named as the entries of scene{objects={...}} are.
namespace {
std::string objectName(const detail::Scene& scene) {
  return "scene: objects[" + std::to_string(scene.objects.size() + scene.surfaces.size() + 1) + "]";
}
}  // namespace

Scene& Scene::add(const Solid& object) {
  guarded([&] {
    const detail::SolidPtr& solid = Access::of(object);
    impl_->tally.add(solid->primitiveCount(), objectName(impl_->scene));
    impl_->scene.objects.push_back(solid);
  });
  return *this;
}

Scene& Scene::add(const Surface& surface) {
  guarded([&] {
    impl_->tally.add(1, objectName(impl_->scene));
    impl_->scene.surfaces.push_back(Access::of(surface));
  });
  return *this;
}

Scene& Scene::add(const Light& light) {
  guarded([&] { impl_->scene.lights.push_back(detail::makeLight(toDetail(light))); });
  return *this;
}

Scene& Scene::setDefaultLight(bool enabled) {
  impl_->scene.defaultLight = enabled;
  return *this;
}

Scene& Scene::setCamera(const Camera& camera) {
  guarded([&] { impl_->scene.camera = toDetail(camera); });
  return *this;
}

Scene& Scene::setBackground(const Vec3& color) {
  guarded([&] {
    detail::checkBackground(toDetail(color));
    impl_->scene.background = toDetail(color);
    impl_->scene.sky = nullptr;
    impl_->scene.cadLook = false;  // its background would be drawn over
  });
  return *this;
}

Scene& Scene::setBackground(const Texture& sky) {
  impl_->scene.sky = Access::of(sky);
  impl_->scene.cadLook = false;
  return *this;
}

Scene& Scene::setDefaultLook(bool enabled) {
  impl_->scene.cadLook = enabled;
  return *this;
}

bool Scene::defaultLook() const { return impl_->scene.cadLook; }

Scene& Scene::setMaxDepth(int depth) {
  guarded([&] { impl_->scene.limits.maxDepth = detail::checkedMaxDepth(depth); });
  return *this;
}

Scene& Scene::setIndirectLight(int samples, int bounces) {
  guarded([&] {
    const detail::IndirectLight indirect{samples, bounces};
    detail::checkIndirectLight(indirect);
    impl_->scene.indirect = indirect;
  });
  return *this;
}

Scene& Scene::setAmbientOcclusion(int samples, double distance) {
  guarded([&] {
    const detail::AmbientOcclusion occlusion{samples, distance};
    detail::checkAmbientOcclusion(occlusion);
    impl_->scene.ambientOcclusion = occlusion;
  });
  return *this;
}

Scene& Scene::setFog(const std::optional<Fog>& fog) {
  guarded([&] {
    detail::Fog made;  // distance 0: off
    if (fog) {
      made = detail::Fog{detail::toDetail(fog->color), fog->distance, fog->offset, fog->altitude};
      detail::checkFog(made);
    }
    impl_->scene.fog = made;
  });
  return *this;
}

Scene& Scene::setMinWeight(double weight) {
  guarded([&] {
    detail::checkMinWeight(weight);
    impl_->scene.limits.minWeight = weight;
  });
  return *this;
}

std::vector<Solid> Scene::objects() const {
  std::vector<Solid> out;
  for (const detail::SolidPtr& s : impl_->scene.objects) out.push_back(Access::solid(s));
  return out;
}

std::vector<Surface> Scene::surfaces() const {
  std::vector<Surface> out;
  for (const detail::SurfacePtr& s : impl_->scene.surfaces) out.push_back(Access::surface(s));
  return out;
}

std::vector<Light> Scene::lights() const {
  std::vector<Light> out;
  for (const detail::Light& l : impl_->scene.lights) out.push_back(detail::toPublic(l));
  return out;
}

bool Scene::defaultLight() const { return impl_->scene.defaultLight; }

std::optional<Camera> Scene::camera() const {
  if (!impl_->scene.camera) return std::nullopt;
  return detail::toPublic(*impl_->scene.camera);
}

Vec3 Scene::background() const { return detail::toPublic(impl_->scene.background); }

std::optional<Texture> Scene::backgroundTexture() const {
  if (!impl_->scene.sky) return std::nullopt;
  return Access::texture(impl_->scene.sky);
}

int Scene::maxDepth() const { return impl_->scene.limits.maxDepth; }

double Scene::minWeight() const { return impl_->scene.limits.minWeight; }

int Scene::indirectSamples() const { return impl_->scene.indirect.samples; }

int Scene::indirectBounces() const { return impl_->scene.indirect.bounces; }

int Scene::ambientOcclusionSamples() const { return impl_->scene.ambientOcclusion.samples; }

double Scene::ambientOcclusionDistance() const { return impl_->scene.ambientOcclusion.distance; }

std::optional<Fog> Scene::fog() const {
  const detail::Fog& fog = impl_->scene.fog;
  if (fog.distance <= 0.0) return std::nullopt;
  return Fog{detail::toPublic(fog.color), fog.distance, fog.offset, fog.altitude};
}

Bounds Scene::bounds() const { return detail::toPublic(impl_->scene.bounds()); }

Solid Scene::part() const {
  const std::vector<detail::SolidPtr>& objects = impl_->scene.objects;
  if (objects.empty())
    throw Error(ErrorCode::InvalidArgument,
                "the scene has no solid (open surfaces cannot be printed)");
  return guarded(
      [&] { return Access::solid(objects.size() == 1 ? objects[0] : detail::unionOf(objects)); });
}

}  // namespace csgray
