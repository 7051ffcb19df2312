#include "cli/aov_images.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "io/image_file.h"

namespace csgray::detail {

std::string aovPath(const std::string& output, const std::string& aov) {
  std::filesystem::path p(output);
  return (p.parent_path() / (p.stem().string() + "." + aov + p.extension().string())).string();
}

void writeAov(AtomicFile& file, const std::string& path, Image image, bool isDepth, int threads) {
  if (!keepsFloatValues(path)) {
    if (isDepth) {
      // nearest / depth: 1 at the nearest surface, fading with distance,
      // so an infinite floor does not squeeze the part into one grey.
      float nearest = INFINITY;
      for (float v : image.rgb)
        if (v > 0.0f) nearest = std::min(nearest, v);
      for (float& v : image.rgb) v = v > 0.0f && std::isfinite(v) ? nearest / v : 0.0f;
    } else {
      // (n + 1) / 2, black where nothing was hit (a normal of 0, 0, 0): a
      // face's normal has components of 0 too, which stay 0.5.
      for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3) {
        float* n = &image.rgb[i];
        if (n[0] == 0.0f && n[1] == 0.0f && n[2] == 0.0f) continue;
        for (int k = 0; k < 3; ++k) n[k] = 0.5f * (n[k] + 1.0f);
      }
    }
  }
  writeImageUncommitted(file, path, image.width, image.height, image.rgb.data(), ImageData::Values,
                        threads);
}

}  // namespace csgray::detail
