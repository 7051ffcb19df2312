// The files a script may name (image textures, meshes): scripts are
// untrusted, so they may not read /etc/passwd as a texture.
#pragma once

#include <functional>
#include <lua.hpp>
#include <string>

#include "script/script.h"

namespace csgray::detail {

// A file named by the script for `function` (e.g. "mesh"): relative to the
// script's folder, and not outside it or the --allow-path folders; throws
// std::invalid_argument otherwise.
std::string scriptFile(lua_State* L, const std::string& function, const std::string& name);

// The script's image loader (ScriptOptions::loadImage) for the image the
// script named `name`, found at path (scriptFile): its
// errors name the file as the script did, "name: why", not by the
// absolute path the loader is given (std::invalid_argument). Empty if the
// program has none.
std::function<TextureImage(const std::string& path)> scriptImageLoader(lua_State* L,
                                                                       const std::string& name);

// The same rule without a script running: name relative to the folder
// `relativeTo`, which must lead into options.folder or one of
// options.allowedFolders (a file named in a .csg file).
std::string allowedFile(const std::string& function, const std::string& name,
                        const std::string& relativeTo, const ScriptOptions& options);

}  // namespace csgray::detail
