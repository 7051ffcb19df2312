#include "scene/light.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

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
    if (!(cosine >= std::cos(coneDegrees * std::numbers::pi / 180.0))) return dvec3(0.0);
    scale *= std::pow(cosine, exponent);
  }
  return scale * color;
}

}  // namespace csgray::detail
