// C++ values held in Lua userdata: solids, surfaces, textures, cameras,
// lights and scenes, with their type names, the charge of their memory
// against the script's cap, and the guard that turns C++ exceptions into
// Lua errors at the script's line. Shared by the files of the script API.
#pragma once

#include <lua.hpp>
#include <new>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <unordered_set>
#include <vector>

#include "engine/boolean.h"
#include "scene/scene.h"
#include "script/lua_args.h"
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
struct TypeName<RegionPtr> {
  static constexpr const char* value = "csgray.region";
  static constexpr const char* shown = "region";
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

// What a value holds on the C++ heap is counted against the script's
// memory cap. A light, a camera or a scene is its userdata's alone: counted
// when made, given back when Lua collects the userdata. Solids, surfaces
// and textures are shared (a union holds its operands, a material its
// texture), so their C++ objects are counted by the sandbox for as long as
// they live, at the sizes of held_objects.h.
inline constexpr std::size_t kBytesPerValue = 512;  // a light, a camera, a scene without lists

template <class T>
struct Held {
  T value;
  std::size_t charge;
};

template <class T>
inline void pushValue(lua_State* L, T value, std::size_t charge = kBytesPerValue) {
  Sandbox::of(L).charge(L, charge);
  void* memory = lua_newuserdatauv(L, sizeof(Held<T>), 0);
  new (memory) Held<T>{std::move(value), charge};
  luaL_setmetatable(L, TypeName<T>::value);
}

// A surface or a texture, counted while it lives.
template <class T>
inline void pushShared(lua_State* L, T value) {
  if (!Sandbox::of(L).holds(value)) Sandbox::of(L).hold(L, {{value, kBytesPerShape}});
  pushValue<T>(L, std::move(value), 0);
}

template <class T>
inline T* toValue(lua_State* L, int index) {
  auto* held = static_cast<Held<T>*>(luaL_testudata(L, index, TypeName<T>::value));
  return held ? &held->value : nullptr;
}

// What a region value was made as ("square", "circle"; "region" for a
// boolean's, an offset's, ...): the user value of its userdata
// (script/api_region.cpp).
inline std::string regionKind(lua_State* L, int index) {
  std::string kind = "region";
  if (lua_getiuservalue(L, index, 1) == LUA_TSTRING) kind = lua_tostring(L, -1);
  lua_pop(L, 1);
  return kind;
}

// " (a square)" for messages; nothing for a plain "region".
inline std::string regionShown(lua_State* L, int index) {
  const std::string kind = regionKind(L, index);
  return kind == "region" ? std::string() : " (a " + kind + ")";
}

// For a plane where a solid was wanted: its solid side is a half-space
// (POV-Ray's plane in CSG). "" for another surface.
inline std::string halfSpaceHint(const std::string& surfaceKind) {
  return surfaceKind == "plane" ? "; the solid side of a plane is half_space{normal=...}" : "";
}

// The value at index, or an error "<what> must be a <type>". A surface
// given for a solid is told apart: what it cannot do is `solidUse`, by
// default take part in a boolean (where a plane gets the half-space
// hint); so is a 2D region.
template <class T>
inline const T& checkValue(lua_State* L, int index, const std::string& what,
                           const char* solidUse = nullptr) {
  if (T* v = toValue<T>(L, index)) return *v;
  if constexpr (std::is_same_v<T, SolidPtr>) {
    if (SurfacePtr* s = toValue<SurfacePtr>(L, index)) {
      const std::string cannot =
          solidUse ? std::string(solidUse)
                   : "take part in a boolean (put it in scene{objects=...} instead)" +
                         halfSpaceHint((*s)->kind());
      throw std::invalid_argument(what + " must be a solid, but a " + (*s)->kind() +
                                  " is a surface: it encloses no volume, so it cannot " + cannot);
    }
    if (toValue<RegionPtr>(L, index))
      throw std::invalid_argument(what + " must be a solid, not a 2D region" +
                                  regionShown(L, index) +
                                  ": it has no volume until it is extruded (linear_extrude, "
                                  "rotate_extrude)");
  }
  // Lights and solids put in each other's lists, as a POV-Ray scene has
  // its light sources among the objects.
  std::string where;
  if (std::is_same_v<T, SolidPtr> && toValue<Light>(L, index))
    where = ": lights go in scene{lights={...}}";
  if (std::is_same_v<T, Light> && toValue<SolidPtr>(L, index))
    where = ": solids go in scene{objects={...}}";
  throw std::invalid_argument(what + " must be a " + TypeName<T>::shown + ", got " +
                              shownType(L, index) + where);
}

// The solid a method was called on, s:method(...). A surface has the
// methods of solids that make sense for it (transforms, material); for the
// others, its metatable has stubs that call this, so that plane{}:bounds()
// says why.
inline const SolidPtr& methodReceiver(lua_State* L, const std::string& method) {
  if (SurfacePtr* s = toValue<SurfacePtr>(L, 1))
    throw std::invalid_argument(method + ": a " + (*s)->kind() +
                                " is a surface, not a solid, and " + method +
                                " is a method of solids only");
  return checkValue<SolidPtr>(L, 1, method + ": the receiver (call it as s:" + method + "(...))");
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
// line. A failed allocation ends the script as the memory limit does: a
// script must not catch it with pcall and go on. (Lua is built as C++
// here, so Lua errors unwind as exceptions that this does not catch, and
// destructors run either way.)
template <int (*F)(lua_State*)>
inline int guarded(lua_State* L) {
  try {
    return F(L);
  } catch (const std::bad_alloc&) {
    Sandbox::of(L).outOfMemory(L);
  } catch (const std::length_error&) {  // a size past what a vector can hold
    Sandbox::of(L).outOfMemory(L);
  } catch (const std::exception& e) {
    Sandbox::of(L).raise(L, e.what());
  }
}

// Memory a call charges while it builds a value, given back when the call
// ends (the value is then charged as a whole by pushValue), also when it
// fails.
class PendingCharge {
 public:
  explicit PendingCharge(lua_State* L) : L_(L) {}
  ~PendingCharge() { Sandbox::of(L_).release(bytes_); }
  PendingCharge(const PendingCharge&) = delete;
  PendingCharge& operator=(const PendingCharge&) = delete;
  void add(std::size_t bytes) {
    bytes_ += bytes;
    Sandbox::of(L_).charge(L_, bytes);
  }
  // Gives the charge back and returns it, for pushValue to charge again.
  std::size_t settle() {
    std::size_t b = bytes_;
    Sandbox::of(L_).release(b);
    bytes_ = 0;
    return b;
  }

 private:
  lua_State* L_;
  std::size_t bytes_ = 0;
};

// The children of a node but those it shares with the node it extends (a
// boolean over a boolean of its operation, the chain s = s - hole of a
// loop: engine/operand_list.h), when that node lives and `done` says its
// children were seen to already. So each step of such a chain costs its
// new operands, not all of them.
template <class Done>
inline std::span<const SolidPtr> newChildren(const Solid& node, Done&& done) {
  const std::span<const SolidPtr> children = node.children();
  if (const Boolean* boolean = node.asBoolean())
    if (const SolidPtr extended = boolean->extended(); extended && done(*extended))
      return children.subspan(extended->children().size());
  return children;
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
    for (const SolidPtr& child :
         newChildren(node, [](const Solid& extended) { return extended.origin().known(); }))
      self(self, *child);
  };
  mark(mark, solid);
}

// Pushes a solid, counting the nodes of its tree that no value held
// before: all of a transformed copy, the one new node of a boolean over
// existing solids. A node shared by many is counted once.
inline void pushSolid(lua_State* L, SolidPtr solid) {
  Sandbox& sandbox = Sandbox::of(L);
  std::vector<Sandbox::HeldObject> fresh;
  // The nodes a call makes may share nodes (a material given to a part
  // of instances maps each shared node once): each is counted once.
  std::unordered_set<const Solid*> seen;
  auto collect = [&](auto& self, const SolidPtr& node) -> void {
    if (sandbox.holds(node) || !seen.insert(node.get()).second) return;
    const std::span<const SolidPtr> children = newChildren(
        *node, [&](const Solid& extended) { return sandbox.holds(extended.shared_from_this()); });
    fresh.push_back({node, node->children().empty() ? kBytesPerShape : kBytesPerBoolean});
    // A boolean's operand list, which the nodes of a chain share, counted
    // once while it lives.
    if (const Boolean* boolean = node->asBoolean();
        boolean && !sandbox.holds(boolean->operands().storage()))
      fresh.push_back({boolean->operands().storage(), boolean->operands().storageBytes()});
    for (const SolidPtr& child : children) self(self, child);
  };
  collect(collect, solid);
  sandbox.hold(L, fresh);
  markOrigin(L, *solid);
  pushValue<SolidPtr>(L, std::move(solid), 0);
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
