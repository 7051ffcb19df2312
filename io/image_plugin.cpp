#include "io/image_plugin.h"

#include <dlfcn.h>
#include <unistd.h>

#include <filesystem>
#include <mutex>
#include <stdexcept>

namespace csgray {

namespace {

// Beside the executable (where the build puts it next to csgray), else
// where it was built (for the test programs).
std::vector<std::string> pluginPaths() {
  std::vector<std::string> paths;
  std::error_code error;
  std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) paths.push_back((exe.parent_path() / "libcsgray_images.so").string());
  paths.push_back(CSGRAY_IMAGE_PLUGIN);
  return paths;
}

const ImagePlugin* load() {
  std::string why;
  for (const std::string& path : pluginPaths()) {
    if (!std::filesystem::exists(path)) continue;
    void* module = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!module) {
      why = ::dlerror();
      continue;
    }
    auto entry = reinterpret_cast<const ImagePlugin* (*)()>(::dlsym(module, "csgray_image_plugin"));
    if (entry) return entry();
    why = path + " has no csgray_image_plugin";
  }
  throw std::runtime_error(
      "cannot load csgray's image library (libcsgray_images.so, needed for "
      "formats other than PNG and for textures)" +
      (why.empty() ? std::string() : ": " + why));
}

}  // namespace

const ImagePlugin& imagePlugin() {
  static std::once_flag once;
  static const ImagePlugin* plugin = nullptr;
  static std::string error;
  std::call_once(once, [] {
    try {
      plugin = load();
    } catch (const std::exception& e) {
      error = e.what();
    }
  });
  if (!plugin) throw std::runtime_error(error);
  return *plugin;
}

ImagePluginPreload::ImagePluginPreload()
    : thread_([] {
        try {
          imagePlugin();
        } catch (const std::exception&) {
          // Reported where the plugin is used.
        }
      }) {}

}  // namespace csgray
