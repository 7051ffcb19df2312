// A linear-light RGB image in floats, row-major from the top left.
#pragma once

#include <vector>

#include "modeler/ray.h"

namespace csgray {

struct Image {
  int width = 0, height = 0;
  std::vector<float> rgb;  // width · height · 3

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgb(static_cast<size_t>(w) * h * 3, 0.0f) {}

  dvec3 at(int x, int y) const {
    const float* p = &rgb[(static_cast<size_t>(y) * width + x) * 3];
    return {p[0], p[1], p[2]};
  }
  void set(int x, int y, const dvec3& c) {
    float* p = &rgb[(static_cast<size_t>(y) * width + x) * 3];
    p[0] = static_cast<float>(c.x), p[1] = static_cast<float>(c.y), p[2] = static_cast<float>(c.z);
  }
};

}  // namespace csgray
