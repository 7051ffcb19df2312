#include "script/script_path.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "script/api.h"
#include "script/lua_args.h"

namespace csgray::detail {

std::string scriptFile(lua_State* L, const std::string& function, const std::string& name) {
  const ScriptOptions& options = scriptOptionsOf(L);
  return allowedFile(function, name, options.folder, options);
}

std::function<TextureImage(const std::string& path)> scriptImageLoader(lua_State* L,
                                                                       const std::string& name) {
  const ScriptOptions& options = scriptOptionsOf(L);
  if (!options.loadImage) return {};
  return [load = options.loadImage, name](const std::string& path) {
    try {
      return load(path);
    } catch (const std::runtime_error& e) {
      // csgray's loader says "cannot read texture image <path>: why";
      // another program's may say anything about the path.
      std::string message = e.what();
      const std::string own = "cannot read texture image " + path + ": ";
      if (message.starts_with(own)) message = name + ": " + message.substr(own.size());
      for (std::size_t at = message.find(path); !path.empty() && at != std::string::npos;
           at = message.find(path, at + name.size()))
        message.replace(at, path.size(), name);
      throw std::invalid_argument(message);
    }
  };
}

std::string allowedFile(const std::string& function, const std::string& name,
                        const std::string& relativeTo, const ScriptOptions& options) {
  namespace fs = std::filesystem;
  if (name.empty()) throw std::invalid_argument(function + ": file is empty");
  // The file system would stop at a NUL byte: "a.png\0/../../x" would open
  // a.png, and messages would be cut short there.
  if (name.find('\0') != std::string::npos)
    throw std::invalid_argument(function + ": file name contains a NUL byte");
  try {
    fs::path folder = fs::weakly_canonical(fs::absolute(options.folder));
    fs::path file = fs::weakly_canonical(fs::absolute(relativeTo) / fs::path(name));
    auto inside = [&file](const fs::path& dir) {
      auto [end, _] = std::mismatch(dir.begin(), dir.end(), file.begin(), file.end());
      return end == dir.end();
    };
    // Symbolic links are followed before the check (weakly_canonical), so a
    // link cannot lead out either.
    auto allowed = [&]() {
      if (options.fileRead) options.fileRead(file.string());
      return file.string();
    };
    if (!fs::path(name).is_absolute() && inside(folder)) return allowed();
    for (const std::string& extra : options.allowedFolders)
      if (inside(fs::weakly_canonical(fs::absolute(extra)))) return allowed();
  } catch (const fs::filesystem_error& e) {
    // A name the file system refuses (too long, a loop of links): said in
    // the script's words rather than the library's.
    throw std::invalid_argument(function + ": cannot use the file name \"" + shortened(name) +
                                "\": " + e.code().message());
  }
  throw std::invalid_argument(function + ": file " + name +
                              " is outside the script's folder; give a path relative to it" +
                              (options.allowedFolders.empty()
                                   ? std::string(", or allow its folder with --allow-path")
                                   : std::string(" or inside a folder given with --allow-path")));
}

}  // namespace csgray::detail
