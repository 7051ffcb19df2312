// The script API: primitives, booleans, transforms, materials and scene
// description as Lua functions and methods. Reference: docs/script.md.
#pragma once

#include <lua.hpp>

#include "modeler/scene.h"

namespace csgray {

// Registers the API's globals and metatables in a sandboxed state.
void registerScriptApi(lua_State* L);

// Turns the script's return value at index into a scene. Throws
// std::invalid_argument if it is neither a solid nor a scene.
Scene sceneFromValue(lua_State* L, int index);

}  // namespace csgray
