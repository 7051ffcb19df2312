// The files a script may name (image textures, meshes): scripts are
// untrusted, so they may not read /etc/passwd as a texture.
#pragma once

#include <lua.hpp>
#include <string>

namespace csgray::detail {

// A file named by the script for `function` (e.g. "mesh"): relative to the
// script's folder, and not outside it or the --allow-path folders; throws
// std::invalid_argument otherwise.
std::string scriptFile(lua_State* L, const std::string& function, const std::string& name);

}  // namespace csgray::detail
