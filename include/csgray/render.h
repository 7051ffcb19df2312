// Ray tracing a scene to an image: exact intersections with the solids,
// shading with shadows, reflections and refraction (docs/cli.md, render).
#pragma once

#include <atomic>
#include <cstddef>
#include <string>
#include <vector>

#include "csgray/scene.h"
#include "csgray/types.h"

namespace csgray {

struct RenderOptions {
  // Pixels, 1 to 16384 a side and at most 2²⁶ (67 108 864) in all.
  int width = 800, height = 600;
  int threads = 0;  // 0: one per core
  // Rays per pixel, jittered (antialiasing): 1 to 1024, or 0 for the
  // command's default: 9, adaptive, for a scene in the default look
  // (Scene(part), a script that returns a solid), else 1.
  int samples = 0;
  bool adaptive = false;  // spend the samples only on pixels at edges
  bool edges = false;     // draw edge lines: outlines and creases (--edges)
  // When given, read by the render's threads before each pixel: set it
  // (from another thread: a user's Stop, a time limit) and render throws
  // Error with ErrorCode::Cancelled within a pixel's time.
  const std::atomic<bool>* cancel = nullptr;
};

// Linear RGB floats, row-major from the top left.
struct Image {
  int width = 0, height = 0;
  std::vector<float> rgb;  // width · height · 3

  Vec3 at(int x, int y) const {
    const std::size_t pixel =
        static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
    const float* p = &rgb[pixel * 3];
    return {p[0], p[1], p[2]};
  }
};

// The scene as the csgray command renders it, pixel for pixel.
CSGRAY_API Image render(const Scene& scene, const RenderOptions& options = {});

// Writes the image; the extension picks the format: PNG (8-bit sRGB), or
// through OpenImageIO others such as .jpg, .tif, .exr (EXR keeps the
// floats). The write is atomic: a failed one leaves any old file as it was.
CSGRAY_API void writeImage(const Image& image, const std::string& path);

}  // namespace csgray
