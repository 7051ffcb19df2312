// Open surfaces in the script (docs/script.md, Open surfaces): planes,
// discs, triangles and parallelograms. They enclose no volume, so they
// take no part in booleans. square{} and rectangle{} are 2D regions
// (api_region.cpp), shown as flat surfaces like these.
#include <stdexcept>
#include <string>

#include "script/api.h"
#include "script/lua_args.h"
#include "script/lua_values.h"

namespace csgray::detail {

namespace {

void pushSurface(lua_State* L, SurfacePtr surface) {
  pushShared<SurfacePtr>(L, std::move(surface));
}

int plane(lua_State* L) {
  checkArgumentCount(L, "plane", 1);
  LuaArgs args(L, 1, "plane");
  dvec3 normal = args.vec3("normal").value_or(dvec3(0, 0, 1));
  double offset = args.number("offset").value_or(0.0);
  SurfacePtr surface = planeOf(normal, offset);
  args.finish();
  pushSurface(L, std::move(surface));
  return 1;
}

int disc(lua_State* L) {
  checkArgumentCount(L, "disc", 1);
  LuaArgs args(L, 1, "disc");
  std::optional<double> r = args.number("r"), d = args.number("d");
  dvec3 center = args.vec3("center").value_or(dvec3(0.0));
  dvec3 normal = args.vec3("normal").value_or(dvec3(0, 0, 1));
  SurfacePtr surface = discOf(r, d, center, normal);
  args.finish();
  pushSurface(L, std::move(surface));
  return 1;
}

int triangle(lua_State* L) {
  checkArgumentCount(L, "triangle", 1);
  LuaArgs args(L, 1, "triangle");
  if (!args.push("points")) throw std::invalid_argument("triangle: needs points={a, b, c}");
  if (lua_type(L, -1) != LUA_TTABLE || lua_rawlen(L, -1) != 3)
    throw std::invalid_argument("triangle: points must be a list of three points");
  dvec3 p[3];
  for (int i = 0; i < 3; ++i) {
    lua_rawgeti(L, -1, i + 1);
    p[i] = toVec3(L, -1, "triangle: points[" + std::to_string(i + 1) + "]");
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  args.finish();
  pushSurface(L, Surface::triangle(p[0], p[1], p[2]));
  return 1;
}

int parallelogram(lua_State* L) {
  checkArgumentCount(L, "parallelogram", 1);
  LuaArgs args(L, 1, "parallelogram");
  dvec3 origin = args.vec3("origin").value_or(dvec3(0.0));
  std::optional<dvec3> u = args.vec3("u"), v = args.vec3("v");
  args.finish();
  if (!u || !v) throw std::invalid_argument("parallelogram: needs the edges u={...} and v={...}");
  pushSurface(L, Surface::parallelogram(origin, *u, *v));
  return 1;
}

int surfaceMaterial(lua_State* L) {
  const SurfacePtr& surface = checkValue<SurfacePtr>(L, 1, "material: the receiver");
  checkArgumentCount(L, "material", 1, 2);
  MaterialPtr m = materialArg(L, 2);
  pushSurface(L, surface->withMaterial(m));
  return 1;
}

// s:bounds(), s:contains(p) and the modifiers (s:ghost(), ...) on a
// surface: methods of solids only.
template <const char* method>
int solidMethod(lua_State* L) {
  methodReceiver(L, method);  // throws for a surface
  return 0;
}
constexpr char kBounds[] = "bounds";
constexpr char kContains[] = "contains";
constexpr char kHighlight[] = "highlight";
constexpr char kGhost[] = "ghost";
constexpr char kDisable[] = "disable";

int surfaceBooleanError(lua_State* L) {
  SurfacePtr* s = toValue<SurfacePtr>(L, 1);
  if (!s) s = toValue<SurfacePtr>(L, 2);
  std::string kind = s ? (*s)->kind() : "surface";
  throw std::invalid_argument(
      "a " + kind +
      " is a surface, not a solid: it encloses no volume, so it cannot take part in a boolean "
      "(put it in scene{objects=...} instead)" +
      halfSpaceHint(kind));
}

}  // namespace

void registerSurfaceApi(lua_State* L, const luaL_Reg* transformMethods) {
  newMetatable<SurfacePtr>(L);
  static const luaL_Reg surfaceMethods[] = {{"material", guarded<surfaceMaterial>},
                                            {"bounds", guarded<solidMethod<kBounds>>},
                                            {"contains", guarded<solidMethod<kContains>>},
                                            {"highlight", guarded<solidMethod<kHighlight>>},
                                            {"ghost", guarded<solidMethod<kGhost>>},
                                            {"disable", guarded<solidMethod<kDisable>>},
                                            {nullptr, nullptr}};
  luaL_newlib(L, surfaceMethods);
  luaL_setfuncs(L, transformMethods, 0);
  lua_setfield(L, -2, "__index");
  static const luaL_Reg surfaceOperators[] = {{"__add", guarded<surfaceBooleanError>},
                                              {"__sub", guarded<surfaceBooleanError>},
                                              {"__mul", guarded<surfaceBooleanError>},
                                              {nullptr, nullptr}};
  luaL_setfuncs(L, surfaceOperators, 0);
  lua_pop(L, 1);

  static const luaL_Reg globals[] = {
      {"plane", guarded<plane>},
      {"disc", guarded<disc>},
      {"triangle", guarded<triangle>},
      {"parallelogram", guarded<parallelogram>},
  };
  for (const luaL_Reg& g : globals) lua_register(L, g.name, g.func);
}

}  // namespace csgray::detail
