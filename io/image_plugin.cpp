#include "io/image_plugin.h"

#include <mutex>
#include <stdexcept>

#include "io/plugin_module.h"

namespace csgray::detail {

const ImagePlugin& imagePlugin() {
  return pluginOf<ImagePlugin>("libcsgray_images.so", CSGRAY_IMAGE_PLUGIN, "csgray_image_plugin",
                               "formats other than PNG and for textures");
}

ImagePluginPreload::ImagePluginPreload()
    : thread_([] {
        try {
          imagePlugin();
        } catch (const std::exception&) {
          // Reported where the plugin is used.
        }
      }) {}

}  // namespace csgray::detail
