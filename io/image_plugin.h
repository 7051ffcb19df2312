// The image formats that go through OpenImageIO, in a module loaded on first
// use (see oiio_plugin.cpp for why). The module and csgray are built
// together, so C++ types and exceptions cross between them.
#pragma once

#include <string>
#include <thread>

#include "io/image_file.h"

namespace csgray::detail {

struct ImagePlugin {
  // Why an image of this format cannot be written, or "".
  std::string (*outputProblem)(const std::string& path);
  // Writes to tempPath (whose extension picks the format); messages name
  // path. Throws std::runtime_error.
  void (*write)(const std::string& tempPath, const std::string& path, int width, int height,
                const float* rgb, ImageData data);
  // readTextureImage (image_file.h).
  TextureImage (*read)(const std::string& path);
};

// The plugin, loaded on the first call (thread-safe). Throws
// std::runtime_error if it cannot be loaded.
const ImagePlugin& imagePlugin();

// Loads the plugin on a thread of its own, so that a render that will need
// it does not wait for it at the end; joins on destruction.
class ImagePluginPreload {
 public:
  ImagePluginPreload();
  ~ImagePluginPreload() { thread_.join(); }
  ImagePluginPreload(const ImagePluginPreload&) = delete;
  ImagePluginPreload& operator=(const ImagePluginPreload&) = delete;

 private:
  std::thread thread_;
};

}  // namespace csgray::detail

extern "C" const csgray::detail::ImagePlugin* csgray_image_plugin();
