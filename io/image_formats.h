// The image formats that go through OpenImageIO, in a module loaded on
// first use (see image_formats_module.cpp for why). The module and csgray
// are built together, so C++ types and exceptions cross between them.
#pragma once

#include <string>
#include <thread>

#include "io/image_file.h"

namespace csgray::detail {

// The most pixels a texture image may have, checked before its data are
// read, so that a bad or hostile file cannot ask for gigabytes: 4096 ×
// 4096 RGB floats are 192 MiB.
constexpr long kMaxTexturePixels = 4096L * 4096;

struct ImageFormats {
  // Why an image of this format cannot be written, or "".
  std::string (*outputProblem)(const std::string& path);
  // Writes to tempPath (whose extension picks the format); messages name
  // path. Throws std::runtime_error.
  void (*write)(const std::string& tempPath, const std::string& path, int width, int height,
                const float* rgb, ImageData data);
  // readTextureImage (image_file.h), given a path that names a regular
  // file.
  TextureImage (*read)(const std::string& path);
};

// The module's table, loaded on the first call (thread-safe). Throws
// std::runtime_error if it cannot be loaded.
const ImageFormats& imageFormats();

// Loads the module on a thread of its own, so that a render that will
// need it does not wait for it at the end; joins on destruction.
class ImageFormatsPreload {
 public:
  ImageFormatsPreload();
  ~ImageFormatsPreload() { thread_.join(); }
  ImageFormatsPreload(const ImageFormatsPreload&) = delete;
  ImageFormatsPreload& operator=(const ImageFormatsPreload&) = delete;

 private:
  std::thread thread_;
};

}  // namespace csgray::detail

extern "C" const csgray::detail::ImageFormats* csgray_image_formats();
