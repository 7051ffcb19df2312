// The sweeps as script functions: linear_extrude and rotate_extrude, which
// turn a region (api_region.cpp) into a solid. Reference: docs/script.md,
// "Sweeps". The shapes and their checks are in primitives/linear_extrusion.h
// and primitives/revolution.h.
#include <optional>
#include <stdexcept>
#include <string>

#include "primitives/linear_extrusion.h"
#include "primitives/revolution.h"
#include "script/api.h"
#include "script/lua_args.h"
#include "script/lua_values.h"

namespace csgray::detail {

namespace {

// The arguments of f{region, name = value, ...} or f(region, {name =
// value, ...}): the region, and on top of the stack a table of the named
// parameters alone (a copy, so the script's table is left as it was), for
// LuaArgs. Any other unnamed value is an error.
RegionPtr regionAndOptions(lua_State* L, const char* function) {
  const int given = lua_gettop(L);
  if (given == 0 || lua_isnil(L, 1))
    throw std::invalid_argument(std::string(function) + ": needs a region");
  if (given > 2)
    throw std::invalid_argument(std::string(function) + ": takes a region and a table of options");
  if (lua_type(L, 1) == LUA_TUSERDATA) {
    RegionPtr region = regionArg(L, 1, std::string(function) + ": argument 1");
    if (given == 2 && !lua_isnil(L, 2) && lua_type(L, 2) != LUA_TTABLE)
      throw std::invalid_argument(std::string(function) +
                                  ": the second argument must be a table of options, got " +
                                  shownType(L, 2));
    if (given == 2 && !lua_isnil(L, 2)) {
      lua_pushvalue(L, 2);
    } else {
      lua_newtable(L);
    }
    return region;
  }
  if (lua_type(L, 1) != LUA_TTABLE)
    throw std::invalid_argument(std::string(function) + ": needs a region, got " + shownType(L, 1));
  if (given == 2)
    throw std::invalid_argument(std::string(function) +
                                ": give the region and the options in one table, or the region "
                                "and then a table of options");
  lua_rawgeti(L, 1, 1);
  if (lua_isnil(L, -1))
    throw std::invalid_argument(std::string(function) +
                                ": needs a region as the table's first value");
  RegionPtr region =
      regionArg(L, lua_gettop(L), std::string(function) + ": the table's first value");
  lua_pop(L, 1);
  lua_newtable(L);
  const int copy = lua_gettop(L);
  lua_pushnil(L);
  while (lua_next(L, 1)) {
    if (lua_type(L, -2) == LUA_TSTRING) {
      lua_pushvalue(L, -2);
      lua_insert(L, -2);
      lua_rawset(L, copy);
    } else {
      const bool first = lua_type(L, -2) == LUA_TNUMBER && lua_tonumber(L, -2) == 1.0;
      lua_pop(L, 1);
      if (!first) {
        lua_pop(L, 1);
        throw std::invalid_argument(std::string(function) +
                                    ": unexpected value without a name after the region; use "
                                    "name=value");
      }
    }
  }
  return region;
}

// scale = s or {sx, sy}.
dvec2 scaleArg(lua_State* L, LuaArgs& args) {
  if (!args.push("scale")) return dvec2(1.0);
  const int index = lua_gettop(L);
  dvec2 scale(1.0);
  if (lua_type(L, index) == LUA_TTABLE) {
    if (lua_rawlen(L, index) != 2)
      throw std::invalid_argument("linear_extrude: scale must be a number or {sx, sy}");
    for (int i = 0; i < 2; ++i) {
      lua_rawgeti(L, index, i + 1);
      scale[i] = toNumber(L, -1, "linear_extrude: scale");
      lua_pop(L, 1);
    }
  } else {
    scale = dvec2(toNumber(L, index, "linear_extrude: scale"));
  }
  lua_pop(L, 1);
  return scale;
}

int linearExtrude(lua_State* L) {
  RegionPtr region = regionAndOptions(L, "linear_extrude");
  LuaArgs args(L, lua_gettop(L), "linear_extrude");
  std::optional<double> height = args.number("height");
  const bool center = args.boolean("center").value_or(false);
  const double twist = args.number("twist").value_or(0.0);
  const dvec2 scale = scaleArg(L, args);
  args.number("convexity");  // OpenSCAD's hint for its preview; rays need none
  args.finish();
  if (!height) throw std::invalid_argument("linear_extrude: needs height");
  pushSolid(L,
            Primitive::create<LinearExtrusion>(std::move(region), *height, center, twist, scale));
  return 1;
}

int rotateExtrude(lua_State* L) {
  RegionPtr region = regionAndOptions(L, "rotate_extrude");
  LuaArgs args(L, lua_gettop(L), "rotate_extrude");
  const double angle = args.number("angle").value_or(360.0);
  args.number("convexity");  // as linear_extrude's
  args.finish();
  pushSolid(L, revolutionSolid(std::move(region), angle));
  return 1;
}

}  // namespace

void registerSweepApi(lua_State* L) {
  static const luaL_Reg globals[] = {
      {"linear_extrude", guarded<linearExtrude>},
      {"rotate_extrude", guarded<rotateExtrude>},
  };
  for (const luaL_Reg& g : globals) lua_register(L, g.name, g.func);
}

}  // namespace csgray::detail
