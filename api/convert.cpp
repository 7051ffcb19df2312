#include "api/convert.h"

#include <utility>

#include "api/access.h"
#include "scene/camera.h"

namespace csgray::detail {

namespace {

// The fields that the public and the internal material share by name and
// type: one list for both directions.
template <class From, class To>
void copyShared(const From& from, To& to) {
  to.ambient = from.ambient;
  to.diffuse = from.diffuse;
  to.specular = from.specular;
  to.shininess = from.shininess;
  to.reflection = from.reflection;
  to.transparency = from.transparency;
  to.filterDistance = from.filterDistance;
  to.transmittedSpecular = from.transmittedSpecular;
  to.ior = from.ior;
  to.fresnel = from.fresnel;
  to.gloss = from.gloss;
  to.bumpDepth = from.bumpDepth;
}

// The kinds of light, public and internal: one table for both directions.
constexpr std::pair<csgray::Light::Kind, Light::Kind> kLightKinds[] = {
    {csgray::Light::Kind::Point, Light::Kind::Point},
    {csgray::Light::Kind::Spot, Light::Kind::Spot},
    {csgray::Light::Kind::Area, Light::Kind::Rectangle},
    {csgray::Light::Kind::Sphere, Light::Kind::Sphere},
};

Light::Kind kindOf(csgray::Light::Kind kind) {
  for (const auto& [publicKind, internalKind] : kLightKinds)
    if (publicKind == kind) return internalKind;
  return Light::Kind::Point;
}

csgray::Light::Kind kindOf(Light::Kind kind) {
  for (const auto& [publicKind, internalKind] : kLightKinds)
    if (internalKind == kind) return publicKind;
  return csgray::Light::Kind::Point;
}

}  // namespace

MaterialPtr toDetail(const csgray::Material& m) {
  auto made = std::make_shared<Material>();
  made->color = toDetail(m.color);
  if (m.texture) made->texture = Access::of(*m.texture);
  if (m.bumps) made->bumps = Access::of(*m.bumps);
  made->filter = toDetail(m.filter);
  made->emission = toDetail(m.emission);
  copyShared(m, *made);
  checkMaterial(*made);
  return made;
}

csgray::Material toPublic(const Material& m) {
  csgray::Material made;
  made.color = toPublic(m.color);
  if (m.texture) made.texture = Access::texture(m.texture);
  if (m.bumps) made.bumps = Access::texture(m.bumps);
  made.filter = toPublic(m.filter);
  made.emission = toPublic(m.emission);
  copyShared(m, made);
  return made;
}

LightParams toDetail(const csgray::Light& light) {
  LightParams p;
  p.kind = kindOf(light.kind);
  p.position = toDetail(light.position);
  p.color = toDetail(light.color);
  p.intensity = light.intensity;
  p.falloff = light.falloff;
  p.lookAt = toDetail(light.lookAt);
  p.direction = toDetail(light.direction);
  p.angle = light.angle;
  p.inner = light.inner;
  p.exponent = light.exponent;
  p.u = toDetail(light.u);
  p.v = toDetail(light.v);
  p.radius = light.radius;
  p.samples = light.samples;
  return p;
}

csgray::Light toPublic(const Light& light) {
  csgray::Light made;
  made.kind = kindOf(light.kind);
  made.position = toPublic(light.position);
  made.color = toPublic(light.color);
  made.intensity = light.intensity;
  made.falloff = light.inverseSquare;
  if (light.kind == Light::Kind::Spot) made.direction = toPublic(light.direction);
  made.angle = light.coneDegrees;
  if (light.kind == Light::Kind::Spot && light.innerDegrees < light.coneDegrees)
    made.inner = light.innerDegrees;
  made.exponent = light.exponent;
  made.u = toPublic(light.edgeU);
  made.v = toPublic(light.edgeV);
  made.radius = light.radius;
  made.samples = light.samples;
  return made;
}

CameraSpec toDetail(const csgray::Camera& camera) {
  CameraSpec spec;
  spec.eye = toDetail(camera.eye);
  spec.lookAt = toDetail(camera.lookAt);
  spec.up = toDetail(camera.up);
  spec.fovDegrees = camera.fov;
  spec.orthographic = camera.projection == csgray::Camera::Projection::Orthographic;
  spec.aperture = camera.aperture;
  if (camera.focalPoint) spec.focalPoint = toDetail(*camera.focalPoint);
  spec.blurSamples = camera.blurSamples;
  return checkedCamera(spec, camera.width);
}

csgray::Camera toPublic(const CameraSpec& spec) {
  csgray::Camera camera;
  camera.eye = toPublic(spec.eye);
  camera.lookAt = toPublic(spec.lookAt);
  camera.up = toPublic(spec.up);
  camera.fov = spec.fovDegrees;
  if (spec.orthographic) {
    camera.projection = csgray::Camera::Projection::Orthographic;
    if (spec.orthoWidth > 0.0) camera.width = spec.orthoWidth;
  }
  camera.aperture = spec.aperture;
  if (spec.focalPoint) camera.focalPoint = toPublic(*spec.focalPoint);
  camera.blurSamples = spec.blurSamples;
  return camera;
}

}  // namespace csgray::detail
