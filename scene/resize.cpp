#include "scene/resize.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "profile/region_evaluation.h"

namespace csgray::detail {

dvec3 resizeFactors(const Bounds& box, const dvec3& newSize, const std::array<bool, 3>& autoAxes,
                    int dims) {
  static const char* const kAxes[] = {"x", "y", "z"};
  for (int i = 0; i < dims; ++i)
    if (!(std::isfinite(newSize[i]) && newSize[i] >= 0.0))
      throw std::invalid_argument(std::string("resize: the size along ") + kAxes[i] +
                                  " must be a finite number >= 0 (0 keeps the axis)");
  if (box.empty()) throw std::invalid_argument("resize: the shape is empty");
  const dvec3 size = box.size();
  dvec3 factors(1.0);
  double largest = 0.0;
  for (int i = 0; i < dims; ++i) {
    if (newSize[i] == 0.0) continue;
    if (!std::isfinite(size[i]))
      throw std::invalid_argument(std::string("resize: the shape is unbounded along ") + kAxes[i]);
    if (!(size[i] > 0.0))
      throw std::invalid_argument(std::string("resize: the shape is flat along ") + kAxes[i] +
                                  ", so no scale gives it a size there");
    factors[i] = newSize[i] / size[i];
    largest = std::max(largest, factors[i]);
  }
  if (largest == 0.0) return factors;  // every size 0: nothing to resize
  for (int i = 0; i < dims; ++i)
    if (newSize[i] == 0.0 && autoAxes[i]) factors[i] = largest;
  return factors;
}

Affine2 regionResizeMap(const Region& region, const dvec2& newSize,
                        const std::array<bool, 2>& autoAxes) {
  const ProfileBounds b = tightBounds(region);
  Bounds box;
  if (!b.empty()) box = Bounds{dvec3(b.lo, 0.0), dvec3(b.hi, 0.0)};
  const dvec3 factors =
      resizeFactors(box, dvec3(newSize, 0.0), {autoAxes[0], autoAxes[1], false}, 2);
  Affine2 map;
  map.linear = dmat2(factors.x, 0.0, 0.0, factors.y);
  return map;
}

}  // namespace csgray::detail
