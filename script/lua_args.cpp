#include "script/lua_args.h"

#include <cmath>
#include <map>
#include <stdexcept>
#include <string_view>

#include "scene/color_names.h"
#include "scene/value_checks.h"

namespace csgray::detail {

LuaArgs::LuaArgs(lua_State* L, int index, std::string function)
    : L_(L), index_(lua_absindex(L, index)), function_(std::move(function)) {
  int type = lua_type(L, index_);
  if (type != LUA_TTABLE && type != LUA_TNIL && type != LUA_TNONE)
    throw std::invalid_argument(function_ + ": expected a table of named parameters, got " +
                                shownType(L, index_));
  if (type == LUA_TTABLE && lua_rawlen(L, index_) > 0)
    throw std::invalid_argument(function_ + ": unexpected value without a name; use name=value");
}

bool LuaArgs::push(const char* key) {
  used_.insert(key);
  if (lua_type(L_, index_) != LUA_TTABLE) return false;
  lua_getfield(L_, index_, key);
  if (lua_isnil(L_, -1)) {
    lua_pop(L_, 1);
    return false;
  }
  return true;
}

std::optional<double> LuaArgs::number(const char* key) {
  if (!push(key)) return std::nullopt;
  double v = toNumber(L_, -1, function_ + ": " + key);
  lua_pop(L_, 1);
  return v;
}

std::optional<dvec3> LuaArgs::vec3(const char* key) {
  if (!push(key)) return std::nullopt;
  dvec3 v = toVec3(L_, -1, function_ + ": " + key);
  lua_pop(L_, 1);
  return v;
}

std::optional<dvec3> LuaArgs::color(const char* key) {
  if (!push(key)) return std::nullopt;
  dvec3 v = toColor(L_, -1, function_ + ": " + key);
  lua_pop(L_, 1);
  return v;
}

std::optional<bool> LuaArgs::boolean(const char* key) {
  if (!push(key)) return std::nullopt;
  if (!lua_isboolean(L_, -1))
    throw std::invalid_argument(function_ + ": " + key + " must be true or false");
  bool v = lua_toboolean(L_, -1);
  lua_pop(L_, 1);
  return v;
}

std::optional<std::string> LuaArgs::string(const char* key) {
  if (!push(key)) return std::nullopt;
  if (lua_type(L_, -1) != LUA_TSTRING)
    throw std::invalid_argument(function_ + ": " + key + " must be a string, got " +
                                shownType(L_, -1));
  std::size_t length = 0;
  const char* text = lua_tolstring(L_, -1, &length);
  std::string v(text, length);
  lua_pop(L_, 1);
  // What reads these strings (the file system, fontconfig, HarfBuzz'
  // languages) would stop at a NUL byte and take the rest for the whole.
  if (v.find('\0') != std::string::npos)
    throw std::invalid_argument(function_ + ": " + key +
                                (std::string_view(key) == "file" ? " name" : "") +
                                " contains a NUL byte");
  return v;
}

namespace {

// "; did you mean 'fov'?" for an unknown parameter: the known one that
// POV-Ray or OpenSCAD name `key` (a camera's angle is its fov), else the
// one a typo or two away.
std::string parameterHint(const std::string& key, const std::set<std::string>& known) {
  static const std::multimap<std::string, std::string> kOtherNames = {
      {"angle", "fov"},
      {"location", "eye"},
      {"location", "pos"},
      {"position", "pos"},
      {"point_at", "look_at"},
      {"tightness", "exponent"},
      {"colour", "color"},
      {"rgb", "color"},
      {"radius", "r"},
      {"diameter", "d"},
      {"radius1", "r1"},
      {"radius2", "r2"},
      {"a", "angle"},
      {"v", "axis"},  // OpenSCAD's rotate(a=, v=)
      // POV-Ray's.
      {"pigment", "color"},
      {"texture", "color"},  // a texture is given as a material's colour
      {"normal", "bumps"},   // normal { bumps 0.5 }
      {"bump_map", "bumps"},
      {"bump_size", "bump_depth"},
      {"fog_offset", "offset"},
      {"fog_alt", "altitude"},
      {"sky_sphere", "background"},
      {"color_map", "colors"},
      {"colour_map", "colors"},
      {"confidence", "blur_samples"},
      {"variance", "blur_samples"},
      {"phong", "specular"},
      {"phong_size", "shininess"},
      {"roughness", "shininess"},
      {"transmit", "transparency"},
      {"interior", "ior"},
      {"sky", "up"},
      {"radius", "inner"},
      {"axis1", "u"},
      {"axis2", "v"},
      {"fade_distance", "falloff"},
      {"fade_power", "falloff"},
      {"max_trace_level", "max_depth"},
      {"turbulence", "strength"},
  };
  for (auto [it, end] = kOtherNames.equal_range(key); it != end; ++it)
    if (known.count(it->second)) return "; did you mean '" + it->second + "'?";
  // POV-Ray's shapes placed by their points: here a shape is made about
  // the origin and then moved.
  if ((key == "center" || key == "base" || key == "cap" || key == "corner1" || key == "corner2") &&
      !known.count(key))
    return "; shapes are made at the origin here and placed with :translate(x, y, z) (and "
           ":rotate for a cylinder's axis)";
  if (key == "fog_type" && known.count("altitude"))
    return "; ground fog (POV-Ray's fog_type 2) is given by offset= and altitude= here";
  // OpenSCAD's facet counts have nothing to set here.
  if (key == "slices" || key == "segments" || key == "fn")
    return "; OpenSCAD's " + key +
           " is not needed here: shapes are exact, and an export's facets "
           "follow --tolerance (leave it out)";
  std::string nearest;
  std::size_t best = key.size() >= 5 ? 3 : 2;
  for (const std::string& name : known)
    if (std::size_t d = editDistance(key, name); d < best) best = d, nearest = name;
  return nearest.empty() ? "" : "; did you mean '" + nearest + "'?";
}

}  // namespace

void LuaArgs::finish() {
  if (lua_type(L_, index_) != LUA_TTABLE) return;
  lua_pushnil(L_);
  while (lua_next(L_, index_)) {
    lua_pop(L_, 1);  // value
    std::string key = lua_type(L_, -1) == LUA_TSTRING ? lua_tostring(L_, -1) : "";
    if (key.empty()) {
      lua_pop(L_, 1);
      throw std::invalid_argument(function_ + ": unexpected value without a name; use name=value");
    }
    if (!used_.count(key)) {
      lua_pop(L_, 1);
      throw std::invalid_argument(function_ + ": unknown parameter '" + shortened(key) + "'" +
                                  parameterHint(key, used_));
    }
  }
}

std::string shortened(const std::string& text, std::size_t length) {
  if (text.size() <= length) return text;
  // Cut at the start of a UTF-8 character, not inside one.
  std::size_t cut = length - 3;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
  return text.substr(0, cut) + "...";
}

void checkArgumentCount(lua_State* L, const std::string& function, int count, int first) {
  const int given = lua_gettop(L) - first + 1;
  if (given <= count) return;
  throw std::invalid_argument(
      function + ": takes " +
      (count == 0 ? std::string("no arguments")
                  : std::to_string(count) + (count == 1 ? " argument" : " arguments")) +
      " (got " + std::to_string(given) + ")");
}

ResizeArgs resizeArgs(lua_State* L, int dims) {
  const std::string forms =
      dims == 3 ? "x, y, z or {x, y, z, auto=...}" : "x, y or {x, y, auto=...}";
  ResizeArgs r;
  const int given = lua_gettop(L) - 1;
  if (given == dims) {
    for (int i = 0; i < dims; ++i) r.size[i] = toNumber(L, 2 + i, "resize: size");
    return r;
  }
  if (given != 1 || lua_type(L, 2) != LUA_TTABLE)
    throw std::invalid_argument("resize: takes " + forms);
  if (lua_rawlen(L, 2) != lua_Unsigned(dims))
    throw std::invalid_argument("resize: takes " + forms + " (" + std::to_string(dims) + " sizes)");
  for (int i = 0; i < dims; ++i) {
    lua_rawgeti(L, 2, i + 1);
    r.size[i] = toNumber(L, -1, "resize: size[" + std::to_string(i + 1) + "]");
    lua_pop(L, 1);
  }
  // The sizes are the list part; auto is the one named parameter.
  lua_getfield(L, 2, "auto");
  if (lua_type(L, -1) == LUA_TBOOLEAN) {
    r.autoAxes.fill(lua_toboolean(L, -1));
  } else if (lua_type(L, -1) == LUA_TTABLE && lua_rawlen(L, -1) == lua_Unsigned(dims)) {
    for (int i = 0; i < dims; ++i) {
      lua_rawgeti(L, -1, i + 1);
      if (lua_type(L, -1) != LUA_TBOOLEAN)
        throw std::invalid_argument("resize: auto must be true, false or a list of them");
      r.autoAxes[i] = lua_toboolean(L, -1);
      lua_pop(L, 1);
    }
  } else if (!lua_isnil(L, -1)) {
    throw std::invalid_argument("resize: auto must be true, false or a list of them");
  }
  lua_pop(L, 1);
  lua_pushnil(L);
  while (lua_next(L, 2)) {
    lua_pop(L, 1);
    if (lua_type(L, -1) == LUA_TSTRING && std::string(lua_tostring(L, -1)) != "auto")
      throw std::invalid_argument("resize: unknown parameter '" + shortened(lua_tostring(L, -1)) +
                                  "' (it takes auto=)");
  }
  return r;
}

std::string shownType(lua_State* L, int index) {
  std::string shown = luaL_typename(L, index);
  if (lua_type(L, index) != LUA_TUSERDATA) return shown;
  // Each of csgray's metatables is named by its kind, "light"
  // (newMetatable in script/lua_values.h).
  const int field = luaL_getmetafield(L, index, "__name");
  if (field == LUA_TSTRING) shown = std::string("a ") + lua_tostring(L, -1);
  if (field != LUA_TNIL) lua_pop(L, 1);
  return shown;
}

// Does the table at index have a string key (a named parameter)?
bool hasStringKey(lua_State* L, int index) {
  lua_pushnil(L);
  while (lua_next(L, index)) {
    lua_pop(L, 1);
    if (lua_type(L, -1) == LUA_TSTRING) {
      lua_pop(L, 1);
      return true;
    }
  }
  return false;
}

double toNumber(lua_State* L, int index, const std::string& what) {
  int isNumber = 0;
  double v = lua_tonumberx(L, index, &isNumber);
  if (!isNumber || lua_type(L, index) != LUA_TNUMBER)
    throw std::invalid_argument(what + " must be a number, got " + shownType(L, index));
  if (!std::isfinite(v)) throw std::invalid_argument(what + " must be finite");
  return v;
}

namespace {

// The list of n numbers at index (a table, its length checked) into out.
void readList(lua_State* L, int index, int n, double* out, const std::string& what,
              const char* shape) {
  if (lua_type(L, index) != LUA_TTABLE)
    throw std::invalid_argument(what + " must be " + shape + ", got " + shownType(L, index));
  // A list one short: often a value that is nil (a variable never set),
  // which ends a Lua list where it stands.
  if (const lua_Unsigned length = lua_rawlen(L, index); length != lua_Unsigned(n))
    throw std::invalid_argument(what + " must be " + shape + ", got a list of " +
                                std::to_string(length) +
                                (length < lua_Unsigned(n) ? " (is a value in it nil?)" : ""));
  for (int k = 0; k < n; ++k) {
    lua_rawgeti(L, index, k + 1);
    out[k] = toNumber(L, -1, what + "[" + std::to_string(k + 1) + "]");
    lua_pop(L, 1);
  }
}

}  // namespace

dvec2 toVec2(lua_State* L, int index, const std::string& what) {
  dvec2 v;
  readList(L, lua_absindex(L, index), 2, &v.x, what, "{x, y}");
  return v;
}

dvec3 toVec3(lua_State* L, int index, const std::string& what) {
  index = lua_absindex(L, index);
  if (lua_type(L, index) == LUA_TNUMBER) return dvec3(toNumber(L, index, what));
  dvec3 v;
  readList(L, index, 3, &v.x, what, "a list of three numbers {x, y, z}");
  return v;
}

dvec3 toColor(lua_State* L, int index, const std::string& what) {
  const int type = lua_type(L, index);
  // OpenSCAD's [r, g, b, a] and POV-Ray's rgbf: a light's, a fog's or a
  // pattern's colour has no such thing (a material's colour says where it
  // goes, api_material.cpp).
  if (type == LUA_TTABLE && lua_rawlen(L, index) == 4)
    throw std::invalid_argument(
        what +
        " must be {r, g, b}: a fourth number (alpha, filter or transmit) has no meaning here");
  if (type == LUA_TNUMBER || (type == LUA_TTABLE && lua_rawlen(L, index) == 3))
    return toVec3(L, index, what);
  if (type != LUA_TSTRING)
    throw std::invalid_argument(
        what + " must be a colour: {r, g, b}, a name such as \"red\" or \"#rrggbb\"");
  std::size_t length = 0;
  const char* text = lua_tolstring(L, index, &length);
  return parseColor(std::string_view(text, length), what);
}

void pushVec3(lua_State* L, const dvec3& v) {
  lua_createtable(L, 3, 0);
  for (int i = 0; i < 3; ++i) {
    lua_pushnumber(L, v[i]);
    lua_rawseti(L, -2, i + 1);
  }
}

}  // namespace csgray::detail
