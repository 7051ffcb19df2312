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

bool GroundShadowGrid::holds(const dvec3& p) const {
  const double u = (p.x - lo_.x) / cell_, v = (p.y - lo_.y) / cell_;
  return corners_ && u >= 0.0 && v >= 0.0 && u < nx_ - 1 && v < ny_ - 1;
}

std::optional<double> GroundShadowGrid::at(const dvec3& p, double groundZ,
                                           const std::function<double(const dvec3&)>& trace) const {
  if (!holds(p)) return std::nullopt;
  const double u = (p.x - lo_.x) / cell_, v = (p.y - lo_.y) / cell_;
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
  // The corners the cell's smoothed corners are made of: the 4 × 4 block
  // about the cell, as far as the grid reaches.
  const int i0 = std::max(i - 1, 0), i1 = std::min(i + 2, nx_ - 1);
  const int j0 = std::max(j - 1, 0), j1 = std::min(j + 2, ny_ - 1);
  double block[4][4];
  for (int cj = j0; cj <= j1; ++cj)
    for (int ci = i0; ci <= i1; ++ci) block[cj - j0][ci - i0] = corner(ci, cj);
  auto smoothed = [&](int ci, int cj) {
    double sum = 0.0;
    int n = 0;
    for (int bj = std::max(cj - 1, j0); bj <= std::min(cj + 1, j1); ++bj)
      for (int bi = std::max(ci - 1, i0); bi <= std::min(ci + 1, i1); ++bi)
        sum += block[bj - j0][bi - i0], ++n;
    return sum / n;
  };
  const double c00 = smoothed(i, j), c10 = smoothed(i + 1, j), c01 = smoothed(i, j + 1),
               c11 = smoothed(i + 1, j + 1);
  // A sharp step about the cell (where the part stands on the ground) is
  // neither smoothed nor interpolated: the point is traced. The mean keeps
  // a share that changes linearly, however steeply, and moves a corner's
  // share only by its grain there; next to a step of s between two
  // columns of the block it moves the corners on that side by s / 3. A
  // step runs along the ground, so it moves two corners or more; grain
  // seldom moves two at once.
  const double moved[4] = {c00 - block[j - j0][i - i0], c10 - block[j - j0][i + 1 - i0],
                           c01 - block[j + 1 - j0][i - i0], c11 - block[j + 1 - j0][i + 1 - i0]};
  int far = 0;
  for (double m : moved) far += std::abs(m) > kSharpStep;
  if (far >= 2) return std::nullopt;
  const double fu = u - i, fv = v - j;
  return (1.0 - fv) * ((1.0 - fu) * c00 + fu * c10) + fv * ((1.0 - fu) * c01 + fu * c11);
}

}  // namespace csgray::detail
