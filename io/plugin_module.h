// Modules that csgray loads on first use (dlopen), so that the libraries
// only some commands need cost the others nothing at start-up: the image
// formats of OpenImageIO, the mesh export and import.
#pragma once

#include <mutex>
#include <stdexcept>
#include <string>

namespace csgray::detail {

// The address that the module's function `entry` returns. The module is
// looked for beside the executable (where the build puts it next to
// csgray), where cmake --install puts it (lib/csgray/, found from the
// executable and from the shared library that holds this code), else at
// builtPath when this code runs from the build tree (the test programs;
// never an installed copy). Throws
// std::runtime_error, naming `what` the module is needed for, if it cannot
// be loaded.
const void* loadPluginModule(const std::string& fileName, const std::string& builtPath,
                             const char* entry, const std::string& what);

// The plugin table of type T that the module's `entry` returns, loaded on
// the first call (thread-safe; once per T). A module that failed to load
// fails every call with the same message.
template <class T>
const T& pluginOf(const char* fileName, const char* builtPath, const char* entry,
                  const char* what) {
  static std::once_flag once;
  static const T* plugin = nullptr;
  static std::string error;
  std::call_once(once, [&] {
    try {
      plugin = static_cast<const T*>(loadPluginModule(fileName, builtPath, entry, what));
    } catch (const std::exception& e) {
      error = e.what();
    }
  });
  if (!plugin) throw std::runtime_error(error);
  return *plugin;
}

}  // namespace csgray::detail
