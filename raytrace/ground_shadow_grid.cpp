#include "raytrace/ground_shadow_grid.h"

#include <algorithm>
#include <cmath>

namespace csgray::detail {

GroundShadowGrid::GroundShadowGrid(const dvec2& lo, const dvec2& hi, double cell,
                                   std::size_t maxCorners)
    : lo_(lo), cell_(cell) {
  if (!(cell > 0.0) || !(hi.x >= lo.x) || !(hi.y >= lo.y)) return;
  const double nx = std::ceil((hi.x - lo.x) / cell) + 1, ny = std::ceil((hi.y - lo.y) / cell) + 1;
  if (!(nx * ny <= double(maxCorners))) return;
  nx_ = int(nx);
  ny_ = int(ny);
  corners_ = std::make_unique<std::atomic<float>[]>(std::size_t(nx_) * ny_);
  for (std::size_t i = 0; i < std::size_t(nx_) * ny_; ++i)
    corners_[i].store(-1.0f, std::memory_order_relaxed);
}

std::optional<double> GroundShadowGrid::at(const dvec3& p, double groundZ,
                                           const std::function<double(const dvec3&)>& trace) const {
  if (!corners_) return std::nullopt;
  const double u = (p.x - lo_.x) / cell_, v = (p.y - lo_.y) / cell_;
  if (!(u >= 0.0 && v >= 0.0 && u < nx_ - 1 && v < ny_ - 1)) return std::nullopt;
  const int i = int(u), j = int(v);
  auto corner = [&](int ci, int cj) {
    std::atomic<float>& slot = corners_[std::size_t(cj) * nx_ + ci];
    float value = slot.load(std::memory_order_relaxed);
    if (value < 0.0f) {
      // Two threads may trace one corner at once: they find the same value.
      value = float(trace(dvec3(lo_.x + ci * cell_, lo_.y + cj * cell_, groundZ)));
      slot.store(value, std::memory_order_relaxed);
    }
    return double(value);
  };
  const double c00 = corner(i, j), c10 = corner(i + 1, j), c01 = corner(i, j + 1),
               c11 = corner(i + 1, j + 1);
  // A sharp step within the cell (where the part stands on the ground) is
  // not interpolated: the point is traced.
  if (std::max({c00, c10, c01, c11}) - std::min({c00, c10, c01, c11}) > kSharpStep)
    return std::nullopt;
  const double fu = u - i, fv = v - j;
  return (1.0 - fv) * ((1.0 - fu) * c00 + fu * c10) + fv * ((1.0 - fu) * c01 + fu * c11);
}

}  // namespace csgray::detail
