// Convex polyhedra in the script (docs/script.md, Polyhedra): the five
// Platonic solids by circumradius, and convex{} from half-spaces.
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "primitives/convex_polyhedron.h"
#include "script/api.h"
#include "script/lua_args.h"
#include "script/lua_values.h"

namespace csgray::detail {

namespace {

// tetrahedron{r=5} or tetrahedron(5): r is the circumradius.
template <Platonic solid>
int platonic(lua_State* L) {
  const char* name = platonicInfo(solid).name;
  checkArgumentCount(L, name, 1);
  double r = 0.0;
  if (lua_type(L, 1) == LUA_TNUMBER) {
    r = toNumber(L, 1, std::string(name) + ": r");
  } else {
    LuaArgs args(L, 1, name);
    std::optional<double> given = args.number("r");
    args.finish();
    if (!given) throw std::invalid_argument(std::string(name) + ": needs r (circumradius)");
    r = *given;
  }
  // platonicSolid checks r > 0 and names the function and r.
  pushSolid(L, platonicSolid(solid, r));
  return 1;
}

bool hasNonListKey(lua_State* L, int index) {
  lua_Unsigned n = lua_rawlen(L, index);
  lua_pushnil(L);
  while (lua_next(L, index)) {
    lua_pop(L, 1);
    bool listKey = lua_isinteger(L, -1) && lua_tointeger(L, -1) >= 1 &&
                   static_cast<lua_Unsigned>(lua_tointeger(L, -1)) <= n;
    if (!listKey) {
      lua_pop(L, 1);
      return true;
    }
  }
  return false;
}

// convex{planes={{normal={x, y, z}, offset=d}, ...}}: all points p with
// normal·p <= offset for every plane.
int convex(lua_State* L) {
  checkArgumentCount(L, "convex", 1);
  LuaArgs args(L, 1, "convex");
  if (!args.push("planes"))
    throw std::invalid_argument("convex: needs planes={{normal={x, y, z}, offset=d}, ...}");
  int list = lua_gettop(L);
  if (lua_type(L, list) != LUA_TTABLE || lua_rawlen(L, list) == 0 || hasNonListKey(L, list))
    throw std::invalid_argument(
        "convex: planes must be a list of planes {normal={x, y, z}, offset=d}");
  lua_Unsigned count = lua_rawlen(L, list);
  // Refused before reading them: a huge list would take long to check.
  if (count > ConvexPolyhedron::kMaxPlanes) {
    throw std::invalid_argument("convex: at most " + std::to_string(ConvexPolyhedron::kMaxPlanes) +
                                " planes (got " + std::to_string(count) + ")");
  }
  std::vector<ConvexPolyhedron::Plane> planes;
  planes.reserve(count);
  for (lua_Unsigned i = 1; i <= count; ++i) {
    lua_rawgeti(L, list, static_cast<lua_Integer>(i));
    std::string what = "convex: plane " + std::to_string(i);
    if (lua_type(L, -1) != LUA_TTABLE) {
      throw std::invalid_argument(what + " must be a table {normal={x, y, z}, offset=d}, got " +
                                  shownType(L, -1));
    }
    LuaArgs plane(L, -1, what);
    std::optional<dvec3> normal = plane.vec3("normal");
    double offset = plane.number("offset").value_or(0.0);
    plane.finish();
    if (!normal) throw std::invalid_argument(what + ": needs normal={x, y, z}");
    planes.push_back({*normal, offset});
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  args.finish();
  // The planes are held once, however often the solid is copied, and
  // charged for the rest of the run: copies may outlive this value.
  auto solid = Primitive::create<ConvexPolyhedron>(planes, "convex");
  Sandbox::of(L).charge(L, count * sizeof(ConvexPolyhedron::Plane));
  pushSolid(L, solid);
  return 1;
}

}  // namespace

void registerConvexApi(lua_State* L) {
  static const luaL_Reg globals[] = {
      {"tetrahedron", guarded<platonic<Platonic::Tetrahedron>>},
      {"hexahedron", guarded<platonic<Platonic::Hexahedron>>},
      {"octahedron", guarded<platonic<Platonic::Octahedron>>},
      {"dodecahedron", guarded<platonic<Platonic::Dodecahedron>>},
      {"icosahedron", guarded<platonic<Platonic::Icosahedron>>},
      {"convex", guarded<convex>},
  };
  for (const luaL_Reg& g : globals) lua_register(L, g.name, g.func);
}

}  // namespace csgray::detail
