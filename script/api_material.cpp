// material{...} on solids and open surfaces (docs/script.md, Materials):
// every key is optional, and color may be a texture.
#include <memory>
#include <stdexcept>

#include "script/api.h"
#include "script/lua_args.h"
#include "script/lua_values.h"

namespace csgray::detail {

MaterialPtr materialArg(lua_State* L, int index) {
  LuaArgs args(L, index, "material");
  auto m = std::make_shared<Material>();
  if (args.push("color")) {
    if (TexturePtr* texture = toValue<TexturePtr>(L, -1)) {
      m->texture = *texture;
      lua_pop(L, 1);
    } else {
      // OpenSCAD's [r, g, b, a] and POV-Ray's rgbf: in a material the
      // fourth number has a parameter of its own.
      if (lua_type(L, -1) == LUA_TTABLE && lua_rawlen(L, -1) == 4)
        throw std::invalid_argument(
            "material: color must be {r, g, b}: a fourth number (OpenSCAD's alpha, POV-Ray's "
            "filter or transmit) is transparency= here, with filter={r, g, b} for a tint");
      lua_pop(L, 1);
      m->color = *args.color("color");
    }
  }
  m->ambient = args.number("ambient").value_or(m->ambient);
  m->diffuse = args.number("diffuse").value_or(m->diffuse);
  m->specular = args.number("specular").value_or(m->specular);
  m->shininess = args.number("shininess").value_or(m->shininess);
  m->reflection = args.number("reflection").value_or(m->reflection);
  m->transparency = args.number("transparency").value_or(m->transparency);
  m->filter = args.color("filter").value_or(m->filter);
  m->filterDistance = args.number("filter_distance").value_or(m->filterDistance);
  m->transmittedSpecular = args.number("transmitted_specular").value_or(m->transmittedSpecular);
  m->ior = args.number("ior").value_or(m->ior);
  m->fresnel = args.boolean("fresnel").value_or(false);
  m->gloss = args.number("gloss").value_or(m->gloss);
  m->emission = args.color("emission").value_or(m->emission);
  // bumps=: a pattern (any texture) whose brightness is the height.
  if (args.push("bumps")) {
    const TexturePtr* bumps = toValue<TexturePtr>(L, -1);
    if (!bumps)
      throw std::invalid_argument(
          "material: bumps must be a texture, such as perlin{scale=0.2}: its brightness is the "
          "height, and bump_depth= sets how high");
    m->bumps = *bumps;
    lua_pop(L, 1);
  }
  m->bumpDepth = args.number("bump_depth").value_or(m->bumpDepth);
  checkMaterial(*m);
  args.finish();
  return m;
}

int solidMaterial(lua_State* L) {
  const SolidPtr& solid = methodReceiver(L, "material");
  checkArgumentCount(L, "material", 1, 2);
  MaterialPtr m = materialArg(L, 2);
  pushSolid(L, solidWithMaterial(solid, m));
  return 1;
}

}  // namespace csgray::detail
