#include "api/convert.h"

#include "api/access.h"
#include "scene/camera.h"

namespace csgray::detail {

MaterialPtr toDetail(const csgray::Material& m) {
  auto made = std::make_shared<Material>();
  made->color = toDetail(m.color);
  if (m.texture) made->texture = Access::of(*m.texture);
  made->ambient = m.ambient;
  made->diffuse = m.diffuse;
  made->specular = m.specular;
  made->shininess = m.shininess;
  made->reflection = m.reflection;
  made->transparency = m.transparency;
  made->filter = toDetail(m.filter);
  made->ior = m.ior;
  made->fresnel = m.fresnel;
  checkMaterial(*made);
  return made;
}

csgray::Material toPublic(const Material& m) {
  csgray::Material made;
  made.color = toPublic(m.color);
  if (m.texture) made.texture = Access::texture(m.texture);
  made.ambient = m.ambient;
  made.diffuse = m.diffuse;
  made.specular = m.specular;
  made.shininess = m.shininess;
  made.reflection = m.reflection;
  made.transparency = m.transparency;
  made.filter = toPublic(m.filter);
  made.ior = m.ior;
  made.fresnel = m.fresnel;
  return made;
}

namespace {

Light::Kind kindOf(csgray::Light::Kind kind) {
  switch (kind) {
    case csgray::Light::Kind::Point:
      return Light::Kind::Point;
    case csgray::Light::Kind::Spot:
      return Light::Kind::Spot;
    case csgray::Light::Kind::Area:
      return Light::Kind::Rectangle;
    case csgray::Light::Kind::Sphere:
      return Light::Kind::Sphere;
  }
  return Light::Kind::Point;
}

csgray::Light::Kind kindOf(Light::Kind kind) {
  switch (kind) {
    case Light::Kind::Point:
      return csgray::Light::Kind::Point;
    case Light::Kind::Spot:
      return csgray::Light::Kind::Spot;
    case Light::Kind::Rectangle:
      return csgray::Light::Kind::Area;
    case Light::Kind::Sphere:
      return csgray::Light::Kind::Sphere;
  }
  return csgray::Light::Kind::Point;
}

}  // namespace

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
  return camera;
}

}  // namespace csgray::detail
