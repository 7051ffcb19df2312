#include "scene/light.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <stdexcept>

#include "scene/value_checks.h"

namespace csgray::detail {

namespace {

// Area lights are sampled on a k × k grid of strata, one jittered point in
// each, so that a penumbra is smooth with few samples.
int gridSide(int samples) { return std::max(1, int(std::lround(std::sqrt(double(samples))))); }

// Two unit vectors that make a right-handed frame with the unit vector w.
void basisAround(const dvec3& w, dvec3& a, dvec3& b) {
  a = glm::normalize(glm::cross(std::abs(w.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0), w));
  b = glm::cross(w, a);
}

}  // namespace

int Light::sampleCount() const {
  if (!isArea()) return 1;
  int k = gridSide(samples);
  return k * k;
}

dvec3 Light::samplePoint(int i, double u, double v, const dvec3& p) const {
  if (!isArea()) return position;
  int k = gridSide(samples);
  double s = ((i % k) + u) / k, t = ((i / k) + v) / k;
  if (kind == Kind::Rectangle) return position + (s - 0.5) * edgeU + (t - 0.5) * edgeV;
  // A sphere seen from p is a disc facing p: sample that disc, uniform in
  // area (r = R·√t), so the penumbra is the one of the sphere's silhouette.
  dvec3 w = p - position;
  double d = glm::length(w);
  dvec3 a, b;
  basisAround(d > 0.0 ? w / d : dvec3(0, 0, 1), a, b);
  double r = radius * std::sqrt(t), phi = 2.0 * std::numbers::pi * s;
  return position + r * (std::cos(phi) * a + std::sin(phi) * b);
}

dvec3 Light::radianceAt(const dvec3& p, const dvec3& s) const {
  dvec3 toPoint = p - s;
  double d2 = glm::dot(toPoint, toPoint);
  double scale = intensity / sampleCount();
  if (inverseSquare) scale /= std::max(d2, 1e-300);
  if (kind == Kind::Spot) {
    double cosine = glm::dot(toPoint, direction) / std::sqrt(d2 * glm::dot(direction, direction));
    const double cosCone = std::cos(coneDegrees * std::numbers::pi / 180.0);
    if (!(cosine >= cosCone)) return dvec3(0.0);
    scale *= std::pow(cosine, exponent);
    // The soft edge: smoothstep (3t² − 2t³) of the cosine between the
    // cone's and the inner angle's, as POV-Ray fades a spotlight between
    // its falloff and radius angles.
    const double cosInner = std::cos(innerDegrees * std::numbers::pi / 180.0);
    if (cosine < cosInner) {
      const double t = (cosine - cosCone) / (cosInner - cosCone);
      scale *= t * t * (3.0 - 2.0 * t);
    }
  }
  return scale * color;
}

const char* lightFunction(Light::Kind kind) {
  switch (kind) {
    case Light::Kind::Point:
      return "point_light";
    case Light::Kind::Spot:
      return "spot_light";
    case Light::Kind::Rectangle:
      return "area_light";
    case Light::Kind::Sphere:
      return "sphere_light";
  }
  return "light";
}

Light makeLight(const LightParams& p) {
  const std::string f = lightFunction(p.kind);
  Light light;
  light.kind = p.kind;
  checkFinite(f, "pos", p.position);
  light.position = p.position;
  switch (p.kind) {
    case Light::Kind::Point:
      break;
    case Light::Kind::Spot:
      if (p.lookAt && p.direction)
        throw std::invalid_argument("spot_light: give look_at or direction, not both");
      if (p.lookAt) checkFinite(f, "look_at", *p.lookAt);
      if (p.direction) checkFinite(f, "direction", *p.direction);
      light.direction = p.direction ? *p.direction
                        : p.lookAt  ? *p.lookAt - light.position
                                    : dvec3(0, 0, -1);
      if (!(glm::length(light.direction) > 0.0))
        throw std::invalid_argument(
            "spot_light: the direction is the zero vector (look_at = pos?)");
      if (!(p.angle > 0.0 && p.angle < 90.0))
        throw std::invalid_argument("spot_light: angle must be between 0 and 90 degrees");
      light.coneDegrees = p.angle;
      light.innerDegrees = p.inner.value_or(p.angle);
      if (!(light.innerDegrees > 0.0 && light.innerDegrees <= p.angle))
        throw std::invalid_argument(
            "spot_light: inner must be more than 0 degrees and at most angle");
      checkNonNegative(f, "exponent", p.exponent);
      light.exponent = p.exponent;
      break;
    case Light::Kind::Rectangle:
      checkNonZero(f, "u", p.u);
      checkNonZero(f, "v", p.v);
      // Parallel edges span no rectangle: its samples would all lie on a
      // line. (Relative to the edges' lengths, so that a scale of the scene
      // keeps it.)
      if (!(glm::length(glm::cross(p.u, p.v)) > 1e-9 * glm::length(p.u) * glm::length(p.v)))
        throw std::invalid_argument(
            "area_light: u and v must not be parallel (they are the rectangle's edges)");
      light.edgeU = p.u;
      light.edgeV = p.v;
      light.samples = checkWhole(f, "samples", p.samples, 1, 1024);
      break;
    case Light::Kind::Sphere:
      checkPositive(f, "r", p.radius);
      light.radius = p.radius;
      light.samples = checkWhole(f, "samples", p.samples, 1, 1024);
      break;
  }
  checkColor(f, "color", p.color);
  light.color = p.color;
  checkNonNegative(f, "intensity", p.intensity);
  light.intensity = p.intensity;
  light.inverseSquare = p.falloff;
  return light;
}

}  // namespace csgray::detail
