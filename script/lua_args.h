// Reading the arguments of a script function from a Lua table of named
// parameters, with messages that name the function and the parameter.
// Unknown parameter names are errors: a typo must not be silently ignored.
#pragma once

#include <array>
#include <glm/vec2.hpp>
#include <lua.hpp>
#include <optional>
#include <set>
#include <string>

#include "engine/ray.h"

namespace csgray::detail {

using glm::dvec2;

class LuaArgs {
 public:
  // index: a table of named parameters, or nil/none for no parameters.
  LuaArgs(lua_State* L, int index, std::string function);

  std::optional<double> number(const char* key);
  std::optional<dvec3> vec3(const char* key);
  // A colour: a linear {r, g, b}, or a name or hex code (toColor).
  std::optional<dvec3> color(const char* key);
  std::optional<bool> boolean(const char* key);
  std::optional<std::string> string(const char* key);
  // True if the key is present; leaves its value on top of the stack.
  bool push(const char* key);
  // Throws if the table has a key that no getter asked for.
  void finish();

  const std::string& function() const { return function_; }

 private:
  lua_State* L_;
  int index_;
  std::string function_;
  std::set<std::string> used_;
};

// A value of the script's (a name, a file name) as a message shows it: at
// most `length` characters, cut with "...".
inline constexpr std::size_t kShownLength = 60;
std::string shortened(const std::string& text, std::size_t length = kShownLength);

// Refuses arguments past the first `count`, counted from index `first`
// (2 for a method, whose receiver is 1): "sphere: takes 1 argument (got
// 2)". An extra argument is a mistake, never something to ignore.
void checkArgumentCount(lua_State* L, const std::string& function, int count, int first = 1);

// The arguments of s:resize: the new sizes (dims of them; 0 keeps an
// axis) and which axes `auto` scales with the others, from f(x, y[, z]) or
// f{x, y[, z], auto=true or {bx, by[, bz]}} at index 2 on. The method is
// "resize" in messages.
struct ResizeArgs {
  dvec3 size{0.0};
  std::array<bool, 3> autoAxes{false, false, false};
};
ResizeArgs resizeArgs(lua_State* L, int dims);

// What the value at index is, for messages: "a light" for csgray's own
// values (all "userdata" to Lua), Lua's type name ("number") for the rest.
std::string shownType(lua_State* L, int index);

// Does the table at index have a key that is a string (a named parameter)?
bool hasStringKey(lua_State* L, int index);

// Values at a stack index, with errors that name what was expected.
double toNumber(lua_State* L, int index, const std::string& what);
dvec2 toVec2(lua_State* L, int index, const std::string& what);  // {x, y}
dvec3 toVec3(lua_State* L, int index, const std::string& what);
// A colour as linear RGB: a string is a CSS name or a hex code, in sRGB
// (scene/color_names.h); anything else is a linear {r, g, b} (toVec3).
dvec3 toColor(lua_State* L, int index, const std::string& what);
// Pushes {x, y, z}.
void pushVec3(lua_State* L, const dvec3& v);

}  // namespace csgray::detail
