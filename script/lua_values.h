// C++ values held in Lua userdata: solids, surfaces, textures, cameras,
// lights and scenes, with their type names, the charge of their memory
// against the script's cap, and the guard that turns C++ exceptions into
// Lua errors at the script's line. Shared by the files of the script API.
#pragma once

#include <lua.hpp>
#include <new>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "scene/scene.h"
#include "script/sandbox.h"

namespace csgray::detail {

// ---- C++ values held in Lua userdata ---------------------------------------

template <class T>
struct TypeName;
template <>
struct TypeName<SolidPtr> {
  static constexpr const char* value = "csgray.solid";
  static constexpr const char* shown = "solid";
};
template <>
struct TypeName<CameraSpec> {
  static constexpr const char* value = "csgray.camera";
  static constexpr const char* shown = "camera";
};
template <>
struct TypeName<Light> {
  static constexpr const char* value = "csgray.light";
  static constexpr const char* shown = "light";
};
template <>
struct TypeName<SurfacePtr> {
  static constexpr const char* value = "csgray.surface";
  static constexpr const char* shown = "surface";
};
template <>
struct TypeName<TexturePtr> {
  static constexpr const char* value = "csgray.texture";
  static constexpr const char* shown = "texture";
};
template <>
struct TypeName<Scene> {
  static constexpr const char* value = "csgray.scene";
  static constexpr const char* shown = "scene";
};

// What a userdata holds on the C++ heap is charged against the script's
// memory cap, and refunded when Lua collects it.
inline constexpr std::size_t kBytesPerNode = 512;  // a primitive with its frame, or a boolean node

template <class T>
struct Held {
  T value;
  std::size_t charge;
};

template <class T>
inline void pushValue(lua_State* L, T value, std::size_t charge = kBytesPerNode) {
  Sandbox::of(L).charge(L, charge);
  void* memory = lua_newuserdatauv(L, sizeof(Held<T>), 0);
  new (memory) Held<T>{std::move(value), charge};
  luaL_setmetatable(L, TypeName<T>::value);
}

template <class T>
inline T* toValue(lua_State* L, int index) {
  auto* held = static_cast<Held<T>*>(luaL_testudata(L, index, TypeName<T>::value));
  return held ? &held->value : nullptr;
}

template <class T>
inline const T& checkValue(lua_State* L, int index, const std::string& what) {
  if (T* v = toValue<T>(L, index)) return *v;
  if constexpr (std::is_same_v<T, SolidPtr>) {
    if (SurfacePtr* s = toValue<SurfacePtr>(L, index))
      throw std::invalid_argument(what + " must be a solid, but a " + (*s)->kind() +
                                  " is a surface: it encloses no volume, so it cannot take part "
                                  "in a boolean (put it in scene{objects=...} instead)");
  }
  throw std::invalid_argument(what + " must be a " + TypeName<T>::shown + ", got " +
                              luaL_typename(L, index));
}

template <class T>
inline int destroyValue(lua_State* L) {
  if (auto* held = static_cast<Held<T>*>(luaL_testudata(L, 1, TypeName<T>::value))) {
    Sandbox::of(L).release(held->charge);
    held->~Held<T>();
  }
  return 0;
}

// Runs a binding and turns a C++ exception into a Lua error at the caller's
// line. (Lua is built as C++ here, so Lua errors unwind as exceptions that
// this does not catch, and destructors run either way.)
template <int (*F)(lua_State*)>
inline int guarded(lua_State* L) {
  try {
    return F(L);
  } catch (const std::bad_alloc&) {
    return luaL_error(L, "out of memory");
  } catch (const std::exception& e) {
    return luaL_error(L, "%s", e.what());
  }
}

// Gives the solid, and every node below it that has none, the line of the
// script that called the running function: the nodes a call builds afresh
// (a shape, the intersection clip{} makes) take the line of that call,
// while copies made by transforms and materials keep the line of their
// original. Stops at a node that has a line, so it costs nothing for the
// copy of a large tree.
inline void markOrigin(lua_State* L, const Solid& solid) {
  if (solid.origin().known()) return;
  SourceLine line = Sandbox::of(L).callerLine(L);
  if (!line.known()) return;
  auto mark = [&](auto& self, const Solid& node) -> void {
    if (node.origin().known()) return;
    node.setOrigin(line);
    for (const SolidPtr& child : node.children()) self(self, *child);
  };
  mark(mark, solid);
}

// A solid that the call built afresh: a transform or material copies the
// whole tree below it, so all of its nodes are charged.
inline void pushSolid(lua_State* L, SolidPtr solid) {
  TreeStats stats = treeStats(*solid);
  std::size_t charge = (stats.primitives + stats.booleans) * kBytesPerNode;
  markOrigin(L, *solid);
  pushValue<SolidPtr>(L, std::move(solid), charge);
}

// A new boolean node over existing solids: one node is new, with its list
// of operands.
inline void pushBoolean(lua_State* L, SolidPtr solid) {
  std::size_t charge = kBytesPerNode + solid->children().size() * sizeof(SolidPtr);
  markOrigin(L, *solid);
  pushValue<SolidPtr>(L, std::move(solid), charge);
}

template <class T>
inline void newMetatable(lua_State* L) {
  luaL_newmetatable(L, TypeName<T>::value);
  lua_pushcfunction(L, &destroyValue<T>);
  lua_setfield(L, -2, "__gc");
  lua_pushstring(L, TypeName<T>::shown);
  lua_setfield(L, -2, "__name");
  // getmetatable() answers this string, so a script cannot reach __gc and
  // destroy a value that is still in use.
  lua_pushstring(L, TypeName<T>::value);
  lua_setfield(L, -2, "__metatable");
}

}  // namespace csgray::detail
