#include "scene/resize.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

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

}  // namespace csgray::detail
