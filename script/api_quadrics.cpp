// The named quadrics (docs/theory.md, "Quadrics") as script functions, and clip,
// which bounds an unbounded solid. Reference: docs/script.md, "Named
// quadrics". The shapes and their checks are in scene/quadric_shapes.h.
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/boolean.h"
#include "scene/quadric_shapes.h"
#include "script/api.h"
#include "script/lua_args.h"
#include "script/lua_values.h"

namespace csgray::detail {

namespace {

// ---- Named quadrics -----------------------------------------------------------

// The semi-axes a, b (and c), or p, are read with LuaArgs::number (which
// rejects NaN and ±inf) and checked after LuaArgs::finish, so that a
// misspelt name is reported as such rather than as a missing parameter.
template <NamedQuadric kind>
int namedQuadric(lua_State* L) {
  checkArgumentCount(L, quadricName(kind), 1);
  LuaArgs args(L, 1, quadricName(kind));
  QuadricAxes axes;
  if (takesP(kind)) {
    axes.p = args.number("p");
  } else {
    axes.a = args.number("a");
    axes.b = args.number("b");
    if (takesC(kind)) axes.c = args.number("c");
  }
  args.finish();
  pushSolid(L, namedQuadricShape(kind, axes));
  return 1;
}

// ---- clip -----------------------------------------------------------------------

// The box {lo=, hi=} at stack index 2.
SolidPtr clipBox(lua_State* L) {
  LuaArgs args(L, 2, "clip");
  std::optional<dvec3> lo = args.vec3("lo");
  std::optional<dvec3> hi = args.vec3("hi");
  args.finish();
  return clipBoxShape(lo, hi);
}

// clip(solid, {lo=, hi=}), clip(solid, other) or clip(solid, {a, b, ...}):
// the solid intersected with the box, the other solid, or all of the list.
int clip(lua_State* L) {
  if (lua_gettop(L) > 2)
    throw std::invalid_argument("clip: takes two arguments, a solid and {lo=, hi=} or solids");
  if (lua_isnoneornil(L, 1)) throw std::invalid_argument("clip: needs a solid to clip");
  const SolidPtr& solid = checkValue<SolidPtr>(L, 1, "clip: the first argument");
  std::vector<SolidPtr> cutters;
  if (lua_isnoneornil(L, 2)) {
    throw std::invalid_argument("clip: needs a box {lo=, hi=}, a solid or a list of solids");
  } else if (lua_type(L, 2) == LUA_TUSERDATA) {
    cutters.push_back(checkValue<SolidPtr>(L, 2, "clip: the second argument"));
  } else if (lua_type(L, 2) == LUA_TTABLE && hasStringKey(L, 2)) {
    cutters.push_back(clipBox(L));
  } else if (lua_type(L, 2) == LUA_TTABLE) {
    lua_Unsigned count = lua_rawlen(L, 2);
    if (count == 0)
      throw std::invalid_argument("clip: the second argument is empty; give {lo=, hi=} or solids");
    for (lua_Unsigned i = 1; i <= count; ++i) {
      lua_rawgeti(L, 2, static_cast<lua_Integer>(i));
      cutters.push_back(checkValue<SolidPtr>(L, -1, "clip: cutter " + std::to_string(i)));
      lua_pop(L, 1);
    }
  } else {
    throw std::invalid_argument(
        std::string("clip: the second argument must be {lo=, hi=}, a solid or a list of solids, "
                    "got ") +
        shownType(L, 2));
  }
  // The new intersection node, the box and the cutters that took the
  // solid's material (copies) are counted as pushSolid finds them.
  pushSolid(L, clippedShape(solid, cutters));
  return 1;
}

}  // namespace

void registerQuadricApi(lua_State* L) {
  static const luaL_Reg globals[] = {
      {"hyperboloid1", guarded<namedQuadric<NamedQuadric::Hyperboloid1>>},
      {"hyperboloid2", guarded<namedQuadric<NamedQuadric::Hyperboloid2>>},
      {"elliptic_cone", guarded<namedQuadric<NamedQuadric::EllipticCone>>},
      {"elliptic_paraboloid", guarded<namedQuadric<NamedQuadric::EllipticParaboloid>>},
      {"hyperbolic_paraboloid", guarded<namedQuadric<NamedQuadric::HyperbolicParaboloid>>},
      {"elliptic_cylinder", guarded<namedQuadric<NamedQuadric::EllipticCylinder>>},
      {"hyperbolic_cylinder", guarded<namedQuadric<NamedQuadric::HyperbolicCylinder>>},
      {"parabolic_cylinder", guarded<namedQuadric<NamedQuadric::ParabolicCylinder>>},
      {"clip", guarded<clip>},
  };
  for (const luaL_Reg& g : globals) lua_register(L, g.name, g.func);
}

}  // namespace csgray::detail
