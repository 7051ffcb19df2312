// Hulls and Minkowski sums of solids, and the rounded shapes they most
// often make (docs/script.md, "Hull and Minkowski"): the script's side of
// scene/hull_shapes.h.
#include <optional>
#include <stdexcept>
#include <vector>

#include "scene/hull_shapes.h"
#include "script/api.h"
#include "script/lua_args.h"
#include "script/lua_values.h"

namespace csgray::detail {

namespace {

// hull(a, b, ...) or hull{a, b, ...} of solids (regions go to the 2D hull,
// api_region.cpp).
int hull(lua_State* L) {
  std::vector<SolidPtr> operands = solidOperands(L, "hull");
  if (operands.empty()) throw std::invalid_argument("hull: needs at least one solid or region");
  pushSolid(L, hullShape(operands));
  return 1;
}

// minkowski(a, b, ...) or minkowski{a, b, ...}.
int minkowski(lua_State* L) {
  pushSolid(L, minkowskiShape(solidOperands(L, "minkowski")));
  return 1;
}

// rounded_box{size={x, y, z}, r=, center=}
int roundedBox(lua_State* L) {
  checkArgumentCount(L, "rounded_box", 1);
  LuaArgs args(L, 1, "rounded_box");
  std::optional<dvec3> size = args.vec3("size");
  std::optional<double> r = args.number("r");
  bool center = args.boolean("center").value_or(false);
  args.finish();
  pushSolid(L, roundedBoxShape(size, r, center));
  return 1;
}

// rounded_cylinder{r=, h=, fillet=, center=}
int roundedCylinder(lua_State* L) {
  checkArgumentCount(L, "rounded_cylinder", 1);
  LuaArgs args(L, 1, "rounded_cylinder");
  std::optional<double> r = args.number("r"), h = args.number("h");
  std::optional<double> fillet = args.number("fillet");
  bool center = args.boolean("center").value_or(false);
  args.finish();
  pushSolid(L, roundedCylinderShape(r, h, fillet, center));
  return 1;
}

}  // namespace

void registerHullApi(lua_State* L) {
  static const luaL_Reg globals[] = {
      {"hull", guarded<hull>},
      {"minkowski", guarded<minkowski>},
      {"rounded_box", guarded<roundedBox>},
      {"rounded_cylinder", guarded<roundedCylinder>},
  };
  for (const luaL_Reg& g : globals) lua_register(L, g.name, g.func);
}

}  // namespace csgray::detail
