#include "raytrace/cad_look.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <numbers>

#include "raytrace/sampler.h"
#include "scene/color_names.h"

namespace csgray::detail {

namespace {

// The background's colours at the top and the bottom of the picture, as
// sRGB (a pale blue-grey over near white), decoded to linear light.
const dvec3 kTop = srgbToLinear(dvec3(0.80, 0.84, 0.89));
const dvec3 kBottom = srgbToLinear(dvec3(0.97, 0.97, 0.98));

}  // namespace

CadLook::CadLook(const CameraSpec& camera, double aspect, const Bounds& bounds)
    : eye_(camera.eye), lookAt_(camera.lookAt), orthographic_(camera.orthographic) {
  forward_ = glm::normalize(camera.lookAt - camera.eye);
  right_ = glm::normalize(glm::cross(forward_, camera.up));
  up_ = glm::cross(right_, forward_);
  tanHalfHeight_ = std::tan(0.5 * camera.fovDegrees * std::numbers::pi / 180.0) / aspect;
  halfHeight_ = 0.5 * camera.orthoWidth / aspect;

  if (!bounds.finite()) return;
  groundZ_ = bounds.lo.z;
  // Seen from below, the ground would hide the part.
  hasGround_ = camera.eye.z > groundZ_ && (!orthographic_ || forward_.z < 0.0);
  // The sky disc: centred high over the part, as wide as the part, so the
  // penumbra grows with the height of what casts it. A point of the part
  // at height h over the ground casts its shadow within r·h / (H − h) of
  // the point under it, for a disc of radius r at height H.
  const dvec3 size = bounds.size();
  const double width = std::max({size.x, size.y, size.z, 1e-9});
  const double radius = 0.5 * width, height = size.z + 3.0 * width;
  const dvec3 centre(bounds.center().x, bounds.center().y, groundZ_ + height);
  // Vogel, "A better way to construct the sunflower head", Mathematical
  // Biosciences 44 (1979): point i at radius √((i + ½)/n), turned by the
  // golden angle from the one before, spreads n points evenly over a disc.
  // The probes are the first points of a spiral of their own, turned so
  // that they lie on four sides.
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < kSkyPoints; ++i) {
    const bool probe = i < kProbes;
    const int k = probe ? i : i - kProbes, n = probe ? kProbes : kSkyPoints - kProbes;
    const double phi = probe ? 0.5 * std::numbers::pi * k + 0.25 * std::numbers::pi : golden * k;
    spiral_[i] = {std::cos(phi), std::sin(phi), k, n};
  }
  bounds_ = bounds;
  skyCentre_ = centre;
  skyRadius_ = radius;
  topShare_ = size.z / height;
}

std::vector<Light> CadLook::lights() const {
  // The three lights of a photographer's portrait, about the camera: the
  // key above and to the left, the fill low on the right to lift the key's
  // shadows, the rim high behind the part to pick out its outline. The
  // faces that a box turns to the default camera (top, front, right) come
  // out about 0.64, 0.47 and 0.31 (linear) in the default grey.
  const double d = glm::length(lookAt_ - eye_);
  Light key, fill, rim;
  key.position = eye_ + d * (0.55 * up_ - 0.5 * right_);
  key.intensity = 0.75;
  fill.position = eye_ + d * (-0.2 * up_ + 0.8 * right_);
  fill.intensity = 0.35;
  fill.castsShadows = false;
  rim.position = lookAt_ + d * (0.8 * up_ + 0.3 * right_ + 0.9 * forward_);
  rim.intensity = 0.45;
  rim.castsShadows = false;
  return {key, fill, rim};
}

dvec3 CadLook::background(const Ray& ray) const {
  // The height on the screen, -1 at the bottom edge and 1 at the top, of
  // where the ray crosses it: from its direction for a perspective camera
  // (or a ray mirrored off a surface), from where it starts for an
  // orthographic one.
  const dvec3 dir = glm::normalize(ray.dir);
  double v;
  if (orthographic_ && glm::dot(dir, forward_) > 1.0 - 1e-9)
    v = glm::dot(ray.origin - eye_, up_) / halfHeight_;
  else
    v = glm::dot(dir, up_) / std::max(glm::dot(dir, forward_), 1e-3) / tanHalfHeight_;
  const double s = std::clamp(0.5 + 0.5 * v, 0.0, 1.0);
  return kBottom + s * (kTop - kBottom);
}

std::optional<dvec3> CadLook::groundPoint(const Ray& ray) const {
  if (!hasGround_ || !(ray.dir.z < 0.0) || !(ray.origin.z > groundZ_)) return std::nullopt;
  const double t = (groundZ_ - ray.origin.z) / ray.dir.z;
  dvec3 p = ray.at(t);
  p.z = groundZ_;
  // The segments from p to the sky disc cross the height share s of the
  // way up in a disc of radius r·s about p + s·(c − p). Up to the top of
  // the bounds (s ≤ topShare_) they stay within the box of the discs at 0
  // and topShare_: if it misses the bounds across, nothing hides the sky.
  const double s = topShare_, reach = skyRadius_ * s;
  const dvec3 far = p + s * (skyCentre_ - p);
  if (std::max(p.x, far.x + reach) < bounds_.lo.x || std::min(p.x, far.x - reach) > bounds_.hi.x ||
      std::max(p.y, far.y + reach) < bounds_.lo.y || std::min(p.y, far.y - reach) > bounds_.hi.y)
    return std::nullopt;
  return p;
}

std::array<dvec3, CadLook::kSkyPoints> CadLook::skyPointsFor(const dvec3& p, bool drawn) const {
  // Vogel's point k of n lies at radius √((k + ½)/n); moved out by a
  // share u of its ring's spacing it lies at √((k + u)/n), and with u
  // uniform over [0, 1) the n rings cover the disc's area evenly (a
  // random shift of a lattice: Cranley and Patterson, "Randomization of
  // number theoretic methods for multiple integration", SIAM J. Numer.
  // Anal. 13, 1976). The turn keeps the spiral's spread.
  auto fold = [](double v) {
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(v);
    return std::uint32_t(bits ^ (bits >> 32));
  };
  Sampler draw(fold(p.x), fold(p.y));
  const double turn = drawn ? 2.0 * std::numbers::pi * draw.next() : 0.0;
  const double shift = drawn ? draw.next() : 0.5;
  const double c = std::cos(turn), s = std::sin(turn);
  std::array<dvec3, kSkyPoints> points;
  for (int i = 0; i < kSkyPoints; ++i) {
    const SpiralPoint& q = spiral_[i];
    const double rho = skyRadius_ * std::sqrt((q.ring + shift) / q.rings);
    points[i] =
        skyCentre_ + dvec3(rho * (q.cos * c - q.sin * s), rho * (q.sin * c + q.cos * s), 0.0);
  }
  return points;
}

bool CadLook::groundRegion(dvec3& lo, dvec3& hi) const {
  if (!hasGround_) return false;
  // groundPoint's test solved for p: along x, a point left of the bounds
  // is kept while far.x + reach >= lo.x, far.x = (1 − s)·p.x + s·c.x; and
  // likewise on the other sides and along y.
  const double s = topShare_, reach = skyRadius_ * s;
  for (int axis = 0; axis < 2; ++axis) {
    lo[axis] = (bounds_.lo[axis] - reach - s * skyCentre_[axis]) / (1.0 - s);
    hi[axis] = (bounds_.hi[axis] + reach - s * skyCentre_[axis]) / (1.0 - s);
  }
  lo.z = hi.z = groundZ_;
  return true;
}

}  // namespace csgray::detail
