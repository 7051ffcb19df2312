#include "io/plugin_module.h"

#include <dlfcn.h>

#include <filesystem>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace csgray::detail {

const void* loadPluginModule(const std::string& fileName, const std::string& builtPath,
                             const char* entry, const std::string& what) {
  std::vector<std::string> paths;
  std::error_code error;
  std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) paths.push_back((exe.parent_path() / fileName).string());
  // Installed (cmake --install), the library (libcsgray.so) finds them in
  // csgray/ beside it, and the executable in lib/csgray/.
  Dl_info self;
  const bool found = ::dladdr(reinterpret_cast<const void*>(&loadPluginModule), &self) != 0 &&
                     self.dli_fname != nullptr;
  if (found)
    paths.push_back(
        (std::filesystem::path(self.dli_fname).parent_path() / "csgray" / fileName).string());
  if (!error) paths.push_back((exe.parent_path() / CSGRAY_MODULES_FROM_BIN / fileName).string());
  // The build's own module only for code that runs from the build tree (the
  // test programs): an installed copy must not load a build's module, of
  // another version perhaps, that happens to be where it was built.
  // (dli_fname may be relative for the executable: its path from
  // /proc/self/exe is asked too.)
  const auto inBuild = [](const std::string& path) {
    return std::string_view(path).starts_with(CSGRAY_BUILD_DIR);
  };
  std::error_code absoluteError;
  if ((found && inBuild(std::filesystem::absolute(self.dli_fname, absoluteError).string())) ||
      (!exe.empty() && inBuild(exe.string())))
    paths.push_back(builtPath);
  std::string why;
  for (const std::string& path : paths) {
    if (!std::filesystem::exists(path)) continue;
    void* module = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!module) {
      why = ::dlerror();
      continue;
    }
    auto get = reinterpret_cast<const void* (*)()>(::dlsym(module, entry));
    if (get) return get();
    why = path + " has no " + entry;
  }
  throw std::runtime_error("cannot load csgray's " + fileName + " (needed for " + what + ")" +
                           (why.empty() ? std::string() : ": " + why));
}

}  // namespace csgray::detail
