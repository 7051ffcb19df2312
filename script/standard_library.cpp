#include "script/standard_library.h"

#include <stdexcept>
#include <string>
#include <string_view>

#include "script/sandbox.h"

namespace csgray::detail {

extern const std::string_view kLibrarySource;  // library_source.cpp, made by the build

namespace {

// The functions the library defines, called through callThrough.
constexpr const char* kLibraryFunctions[] = {"graph",
                                             "parametric",
                                             "fractal_mountain",
                                             "sierpinski_triangle",
                                             "sierpinski_tetrahedron",
                                             "pythagoras_tree",
                                             "pythagoras_tree_3d"};

// Calls the library's Lua function (the upvalue) with the arguments. A
// message the library raised for the script ("\1name: ...") gets the
// script's file and line in front: this C function's caller, which is
// there also when the script's call was a tail call (Lua 5.4 keeps the
// calling frame for a C function in tail position).
int callThrough(lua_State* L) {
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  const int status = lua_pcall(L, lua_gettop(L) - 1, LUA_MULTRET, 0);
  if (status == LUA_OK) return lua_gettop(L);
  if (lua_type(L, -1) == LUA_TSTRING) {
    std::string_view message = lua_tostring(L, -1);
    if (message.starts_with('\1')) {
      const std::string placed = Sandbox::of(L).where(L, 1) + std::string(message.substr(1));
      lua_pop(L, 1);
      lua_pushstring(L, placed.c_str());
    }
  }
  return lua_error(L);
}

}  // namespace

void loadStandardLibrary(lua_State* L) {
  int status =
      luaL_loadbufferx(L, kLibrarySource.data(), kLibrarySource.size(), kLibraryChunkName, "t");
  if (status == LUA_OK) status = lua_pcall(L, 0, 0, 0);
  if (status != LUA_OK) {
    std::string message = lua_tostring(L, -1) ? lua_tostring(L, -1) : "?";
    lua_pop(L, 1);
    throw std::logic_error("the script library does not load: " + message);
  }
  for (const char* name : kLibraryFunctions) {
    if (lua_getglobal(L, name) != LUA_TFUNCTION)
      throw std::logic_error(std::string("the script library does not define ") + name);
    lua_pushcclosure(L, callThrough, 1);
    lua_setglobal(L, name);
  }
}

}  // namespace csgray::detail
