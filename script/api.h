// The script API: primitives, booleans, transforms, materials and scene
// description as Lua functions and methods. Reference: docs/script.md.
#pragma once

#include <lua.hpp>

#include "scene/scene.h"
#include "script/script.h"

namespace csgray::detail {

// Registers the API's globals and metatables in a sandboxed state. The
// options must outlive the script's run.
void registerScriptApi(lua_State* L, const ScriptOptions& options);
// The options registerScriptApi was given.
const ScriptOptions& scriptOptionsOf(lua_State* L);

// A file named by the script for `function` (e.g. "mesh"): relative to the
// script's folder, and not outside it or the --allow-path folders; throws
// std::invalid_argument otherwise.
std::string scriptFile(lua_State* L, const std::string& function, const std::string& name);

// The part of the API in api_scene.cpp: materials, textures, lights, open
// surfaces (which take the given transform methods), camera and scene.
void registerSceneApi(lua_State* L, const luaL_Reg* transformMethods);
// Shape families, each in its own file: the named quadrics of seed 000's
// table 17.1 and clip (api_quadrics.cpp), convex polyhedra and the Platonic
// solids (api_convex.cpp), polyhedra from points and faces (api_mesh.cpp).
void registerQuadricApi(lua_State* L);
void registerConvexApi(lua_State* L);
void registerMeshApi(lua_State* L);
// check(solid, options) (api_check.cpp): ScriptOptions::checkSolid's report as a table.
void registerCheckApi(lua_State* L);
// s:material{...} on a solid.
int solidMaterial(lua_State* L);

// Turns the script's return value at index into a scene. Throws
// std::invalid_argument if it is not a solid, a surface or a scene.
Scene sceneFromValue(lua_State* L, int index);

}  // namespace csgray::detail
