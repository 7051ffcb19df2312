#include "io/image_formats.h"

#include <stdexcept>

#include "io/plugin_module.h"

namespace csgray::detail {

const ImageFormats& imageFormats() {
  return pluginOf<ImageFormats>("libcsgray_image_formats.so", CSGRAY_IMAGE_FORMATS_MODULE,
                                "csgray_image_formats", "formats other than PNG and for textures");
}

ImageFormatsPreload::ImageFormatsPreload()
    : thread_([] {
        try {
          imageFormats();
        } catch (const std::exception&) {
          // Reported where the module is used.
        }
      }) {}

}  // namespace csgray::detail
