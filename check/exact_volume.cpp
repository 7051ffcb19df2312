#include "check/exact_volume.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "check/check_report.h"
#include "engine/span_list.h"

namespace csgray::detail {

namespace {

// splitmix64 (Steele, Lea and Flood, "Fast splittable pseudorandom number
// generators", OOPSLA 2014): a jitter per ray that does not depend on
// which thread traces it, so every run gives the same figures.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}
double unit(std::uint64_t bits) { return double(bits >> 11) * 0x1.0p-53; }

}  // namespace

RayGrid::RayGrid(const Bounds& box, int axis, int n, std::uint64_t seed)
    : lo_(box.lo), axis_(axis), u_((axis + 1) % 3), v_((axis + 2) % 3), seed_(seed) {
  along_[axis] = 1.0;
  du_ = box.size()[u_] / n;
  length_ = box.size()[axis];
  dv_ = box.size()[v_] / n;
}

Ray RayGrid::ray(int i, int j) const {
  const std::uint64_t key =
      mix(seed_ ^ mix((std::uint64_t(axis_) << 60) ^ (std::uint64_t(i) << 30) ^ j));
  dvec3 origin = lo_;
  origin[u_] += (i + unit(key)) * du_;
  origin[v_] += (j + unit(mix(key))) * dv_;
  return Ray(origin, along_, -kInfinity, kInfinity);
}

RayGrid::Volume RayGrid::volume(const std::vector<double>& lengths) const {
  const double cell = du_ * dv_;
  Volume made;
  for (double length : lengths) made.volume += cell * length;
  // Collapsed strata (Cochran, Sampling Techniques, 3rd ed., §5A.12):
  // with one sample per cell, neighbouring cells in pairs give an upper
  // estimate of the variance, Σ (a·L₁ − a·L₂)².
  double variance = 0.0;
  for (std::size_t k = 0; k + 1 < lengths.size(); k += 2)
    variance += std::pow(cell * (lengths[k] - lengths[k + 1]), 2);
  made.sigma = std::max(std::sqrt(variance), cell * length_);
  return made;
}

double exactVolume(const Solid& solid, int grid) {
  const Bounds box = solid.bounds();
  if (box.empty()) return 0.0;
  solid.prepare();
  const int n = grid;
  double sum = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    const RayGrid rays(box, axis, n, CheckOptions().seed);
    std::vector<double> lengths(std::size_t(n) * n);
    tbb::parallel_for(0, n, [&](int i) {
      SpanList spans;
      for (int j = 0; j < n; ++j) {
        solid.spans(rays.ray(i, j), spans);
        lengths[std::size_t(i) * n + j] = spans.lengthWithin(-kInfinity, kInfinity);
      }
    });
    sum += rays.volume(lengths).volume;
  }
  return sum / 3.0;
}

}  // namespace csgray::detail
