// Lights in the script (docs/script.md, Lights and shadows): point_light{},
// spot_light{}, area_light{} and sphere_light{}.
#include <stdexcept>
#include <string>

#include "script/api.h"
#include "script/lua_args.h"
#include "script/lua_values.h"

namespace csgray::detail {

namespace {

// The light of kind from the table of named parameters at index 1.
template <Light::Kind kind>
int light(lua_State* L) {
  checkArgumentCount(L, lightFunction(kind), 1);
  LuaArgs args(L, 1, lightFunction(kind));
  LightParams p;
  p.kind = kind;
  std::optional<dvec3> position = args.vec3("pos");
  if (kind == Light::Kind::Spot) {
    p.lookAt = args.vec3("look_at");
    p.direction = args.vec3("direction");
    p.angle = args.number("angle").value_or(p.angle);
    p.inner = args.number("inner");
    p.exponent = args.number("exponent").value_or(p.exponent);
  }
  if (kind == Light::Kind::Rectangle) {
    p.u = args.vec3("u").value_or(p.u);
    p.v = args.vec3("v").value_or(p.v);
  }
  if (kind == Light::Kind::Sphere) p.radius = args.number("r").value_or(p.radius);
  if (kind == Light::Kind::Rectangle || kind == Light::Kind::Sphere)
    p.samples = args.number("samples").value_or(p.samples);
  p.color = args.color("color").value_or(p.color);
  p.intensity = args.number("intensity").value_or(p.intensity);
  // POV-Ray's spot falloff is an angle, where csgray's is a switch.
  if (args.push("falloff")) {
    const bool number = lua_type(L, -1) == LUA_TNUMBER;
    lua_pop(L, 1);
    if (number)
      throw std::invalid_argument(
          args.function() +
          ": falloff must be true or false (divide by the squared "
          "distance); POV-Ray's falloff angle of a spot is angle= here, its radius inner=");
  }
  p.falloff = args.boolean("falloff").value_or(false);
  args.finish();  // an unknown name (location=) before "needs pos"
  if (!position) throw std::invalid_argument(args.function() + ": needs pos={x, y, z}");
  p.position = *position;
  pushValue(L, makeLight(p));
  return 1;
}

}  // namespace

void registerLightApi(lua_State* L) {
  newMetatable<Light>(L);
  lua_pop(L, 1);
  static const luaL_Reg globals[] = {
      {"point_light", guarded<light<Light::Kind::Point>>},
      {"spot_light", guarded<light<Light::Kind::Spot>>},
      {"area_light", guarded<light<Light::Kind::Rectangle>>},
      {"sphere_light", guarded<light<Light::Kind::Sphere>>},
  };
  for (const luaL_Reg& g : globals) lua_register(L, g.name, g.func);
}

}  // namespace csgray::detail
