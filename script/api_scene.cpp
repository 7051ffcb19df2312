// The camera and the scene in the script (docs/script.md, Scenes), the
// scene a script's return value stands for (a bare solid's gets the CAD
// look, raytrace/cad_look.h), and srgb(), colours as paint programs give them.
#include <stdexcept>
#include <string>

#include "scene/camera.h"
#include "scene/color_names.h"
#include "scene/region_surface.h"
#include "scene/value_checks.h"
#include "script/api.h"
#include "script/lua_args.h"
#include "script/lua_values.h"

namespace csgray::detail {

namespace {

int camera(lua_State* L) {
  checkArgumentCount(L, "camera", 1);
  LuaArgs args(L, 1, "camera");
  CameraSpec c;
  c.eye = args.vec3("eye").value_or(c.eye);
  c.lookAt = args.vec3("look_at").value_or(c.lookAt);
  c.up = args.vec3("up").value_or(c.up);
  c.fovDegrees = args.number("fov").value_or(c.fovDegrees);
  std::string projection = args.string("projection").value_or("perspective");
  std::optional<double> width = args.number("width");
  c.aperture = args.number("aperture").value_or(c.aperture);
  c.focalPoint = args.vec3("focal_point");
  c.blurSamples = checkWhole("camera", "blur_samples",
                             args.number("blur_samples").value_or(c.blurSamples), 1, 1024);
  args.finish();
  if (projection != "perspective" && projection != "orthographic")
    throw std::invalid_argument("camera: projection must be \"perspective\" or \"orthographic\"");
  c.orthographic = projection == "orthographic";
  pushValue(L, checkedCamera(c, width));
  return 1;
}

// Calls f for a single value under key or for each value of a list.
template <class F>
bool forEachListed(lua_State* L, LuaArgs& args, const char* key, F f) {
  if (!args.push(key)) return false;
  if (lua_type(L, -1) == LUA_TTABLE) {
    lua_Unsigned n = lua_rawlen(L, -1);
    for (lua_Unsigned i = 1; i <= n; ++i) {
      lua_rawgeti(L, -1, static_cast<lua_Integer>(i));
      f(args.function() + ": " + key + "[" + std::to_string(i) + "]");
      lua_pop(L, 1);
    }
  } else {
    f(args.function() + ": " + key);
  }
  lua_pop(L, 1);
  return true;
}

int scene(lua_State* L) {
  checkArgumentCount(L, "scene", 1);
  LuaArgs args(L, 1, "scene");
  Scene s;
  // The lists are copied into the scene: charged as they grow, so that a
  // list of millions of references to one light or part stops at the
  // memory limit instead of exhausting the machine, and counted against
  // the limit on primitives.
  PendingCharge pending(L);
  ObjectTally tally;
  // Objects: solids, open surfaces and 2D regions (shown flat in the plane
  // z = 0), alone or in a list.
  forEachListed(L, args, "objects", [&](const std::string& what) {
    if (RegionPtr* region = toValue<RegionPtr>(L, -1)) {
      tally.add(1, what);
      pending.add(sizeof(SurfacePtr));
      s.surfaces.push_back(regionSurface(*region, regionKind(L, -1)));
    } else if (SurfacePtr* surface = toValue<SurfacePtr>(L, -1)) {
      tally.add(1, what);
      pending.add(sizeof(SurfacePtr));
      s.surfaces.push_back(*surface);
    } else {
      const SolidPtr& solid =
          checkValue<SolidPtr>(L, -1, what + " (a solid, a surface or a region)");
      tally.add(solid->primitiveCount(), what);
      pending.add(sizeof(SolidPtr));
      s.objects.push_back(solid);
    }
  });
  // Lights named, even none, replace the default light.
  s.defaultLight = !forEachListed(L, args, "lights", [&](const std::string& what) {
    pending.add(sizeof(Light));
    s.lights.push_back(checkValue<Light>(L, -1, what));
  });
  if (args.push("camera")) {
    s.camera = checkValue<CameraSpec>(L, -1, "scene: camera");
    lua_pop(L, 1);
  }
  // A colour, or a texture seen by direction (a sky).
  if (args.push("background")) {
    const TexturePtr* sky = toValue<TexturePtr>(L, -1);
    lua_pop(L, 1);
    if (sky)
      s.sky = *sky;
    else
      s.background = *args.color("background");
  }
  checkBackground(s.background);
  s.limits.maxDepth = checkedMaxDepth(args.number("max_depth").value_or(s.limits.maxDepth));
  s.limits.minWeight = args.number("min_weight").value_or(s.limits.minWeight);
  checkMinWeight(s.limits.minWeight);
  s.edges = args.boolean("edges").value_or(false);
  // indirect={samples=, bounces=} and ambient_occlusion={samples=,
  // distance=}; true for the defaults.
  auto lighting = [&](const char* key, const std::string& function, auto&& read) {
    if (!args.push(key)) return;
    if (lua_type(L, -1) == LUA_TBOOLEAN) {
      if (lua_toboolean(L, -1)) {
        lua_newtable(L);
        LuaArgs defaults(L, -1, function);
        read(defaults);
        lua_pop(L, 1);
      }
    } else {
      LuaArgs inner(L, -1, function);
      read(inner);
      inner.finish();
    }
    lua_pop(L, 1);
  };
  lighting("indirect", "scene: indirect", [&](LuaArgs& a) {
    s.indirect.samples =
        checkWhole("scene: indirect", "samples", a.number("samples").value_or(16), 1, 4096);
    s.indirect.bounces =
        checkWhole("scene: indirect", "bounces", a.number("bounces").value_or(2), 0, 64);
  });
  lighting("ambient_occlusion", "scene: ambient_occlusion", [&](LuaArgs& a) {
    s.ambientOcclusion.samples = checkWhole("scene: ambient_occlusion", "samples",
                                            a.number("samples").value_or(16), 1, 4096);
    s.ambientOcclusion.distance = a.number("distance").value_or(0.0);
  });
  // fog={color=, distance=}: both needed, as POV-Ray's fog needs both.
  if (args.push("fog")) {
    LuaArgs fog(L, -1, "scene: fog");
    const std::optional<dvec3> color = fog.color("color");
    const std::optional<double> distance = fog.number("distance");
    const std::optional<double> offset = fog.number("offset");
    const std::optional<double> altitude = fog.number("altitude");
    fog.finish();
    if (!color || !distance)
      throw std::invalid_argument(std::string("scene: fog needs ") +
                                  (color      ? "distance"
                                   : distance ? "color"
                                              : "color and distance") +
                                  " (fog={color={0.7, 0.7, 0.8}, distance=50})");
    // Ground fog: both or neither.
    if (bool(offset) != bool(altitude))
      throw std::invalid_argument(std::string("scene: fog: ") + (offset ? "offset" : "altitude") +
                                  " needs " + (offset ? "altitude" : "offset") +
                                  " (ground fog: full up to offset, thinning above it)");
    if (altitude) checkPositive("scene: fog", "altitude", *altitude);
    s.fog = Fog{*color, *distance, offset.value_or(0.0), altitude.value_or(0.0)};
    checkFog(s.fog);
    lua_pop(L, 1);
  }
  checkIndirectLight(s.indirect);
  checkAmbientOcclusion(s.ambientOcclusion);
  args.finish();
  checkHasObjects(s);
  pushValue(L, std::move(s), kBytesPerValue + pending.settle());
  return 1;
}

// srgb(r, g, b) or srgb{r, g, b}: the linear colour {r, g, b} that the
// sRGB components (each in [0, 1], as a paint program shows them) stand for.
int srgb(lua_State* L) {
  const char* f = "srgb";
  dvec3 c;
  if (lua_gettop(L) == 1 && lua_type(L, 1) == LUA_TTABLE) {
    c = toVec3(L, 1, f);
  } else {
    checkArgumentCount(L, f, 3);
    if (lua_gettop(L) != 3) throw std::invalid_argument("srgb: takes r, g, b or {r, g, b}");
    c = dvec3(toNumber(L, 1, "srgb: r"), toNumber(L, 2, "srgb: g"), toNumber(L, 3, "srgb: b"));
  }
  for (int i = 0; i < 3; ++i)
    if (!(c[i] >= 0.0 && c[i] <= 1.0))
      throw std::invalid_argument(
          "srgb: components must be in [0, 1] (for 0 to 255, divide by 255 or write \"#rrggbb\")");
  pushVec3(L, srgbToLinear(c));
  return 1;
}

}  // namespace

void registerSceneApi(lua_State* L) {
  newMetatable<CameraSpec>(L);
  lua_pop(L, 1);
  newMetatable<Scene>(L);
  lua_pop(L, 1);
  static const luaL_Reg globals[] = {
      {"camera", guarded<camera>},
      {"scene", guarded<scene>},
      {"srgb", guarded<srgb>},
  };
  for (const luaL_Reg& g : globals) lua_register(L, g.name, g.func);
}

namespace {

Scene sceneOfValue(lua_State* L, int index) {
  if (SolidPtr* solid = toValue<SolidPtr>(L, index)) {
    Scene s;
    s.objects.push_back(*solid);
    s.cadLook = true;
    return s;
  }
  if (SurfacePtr* surface = toValue<SurfacePtr>(L, index)) {
    Scene s;
    s.surfaces.push_back(*surface);
    s.cadLook = true;
    return s;
  }
  if (RegionPtr* region = toValue<RegionPtr>(L, index)) {
    Scene s;
    s.surfaces.push_back(regionSurface(*region, regionKind(L, index)));
    s.cadLook = true;
    return s;
  }
  if (Scene* s = toValue<Scene>(L, index)) return *s;
  throw std::invalid_argument(std::string("the script must return a solid, a surface, a region "
                                          "or scene{...}, not ") +
                              shownType(L, index));
}

}  // namespace

Scene sceneFromValue(lua_State* L, int index) {
  Scene scene = sceneOfValue(L, index);
  scene.resolveModifiers();
  if (scene.objects.empty() && scene.surfaces.empty() && scene.ghosts.empty())
    throw std::invalid_argument("nothing is left to show: every solid is disabled");
  return scene;
}

}  // namespace csgray::detail
