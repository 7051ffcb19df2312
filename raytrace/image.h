// A linear-light RGB image in floats, row-major from the top left.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "engine/ray.h"

namespace csgray::detail {

// Vectors that leave their new elements uninitialised when no value is
// given (resize(n)), and construct them as std::allocator does otherwise.
template <class T>
struct UninitializedAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = UninitializedAllocator<U>;
  };
  UninitializedAllocator() = default;
  template <class U>
  UninitializedAllocator(const UninitializedAllocator<U>&) noexcept {}
  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

struct Image {
  int width = 0, height = 0;
  std::vector<float, UninitializedAllocator<float>> rgb;  // width · height · 3

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgb(static_cast<size_t>(w) * h * 3, 0.0f) {}
  // An image whose every pixel will be set: its memory is not written
  // here, so the render's threads, not this one, take its page faults.
  static Image uninitialized(int w, int h) {
    Image image;
    image.width = w;
    image.height = h;
    image.rgb.resize(static_cast<size_t>(w) * h * 3);
    return image;
  }

  dvec3 at(int x, int y) const {
    const float* p = &rgb[(static_cast<size_t>(y) * width + x) * 3];
    return {p[0], p[1], p[2]};
  }
  void set(int x, int y, const dvec3& c) {
    float* p = &rgb[(static_cast<size_t>(y) * width + x) * 3];
    p[0] = static_cast<float>(c.x), p[1] = static_cast<float>(c.y), p[2] = static_cast<float>(c.z);
  }
};

}  // namespace csgray::detail
