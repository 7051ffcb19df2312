// Textures in the script (docs/script.md, Textures): checker{}, gradient{}, the noises
// perlin{}, turbulence{}, marble{} and wood{}, the fractals mandelbrot{} and
// julia{}, and image_texture{}.
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "script/api.h"
#include "script/lua_args.h"
#include "script/lua_values.h"
#include "script/script_path.h"

namespace csgray::detail {

namespace {

// The two colours of a pattern: colors={{r, g, b}, {r, g, b}}.
std::optional<ColorPair> colorsArg(lua_State* L, LuaArgs& args) {
  if (!args.push("colors")) return std::nullopt;
  std::string what = args.function() + ": colors";
  if (lua_type(L, -1) != LUA_TTABLE || lua_rawlen(L, -1) != 2)
    throw std::invalid_argument(what + " must be a list of two colours {{r, g, b}, {r, g, b}}");
  dvec3 c[2];
  for (int i = 0; i < 2; ++i) {
    lua_rawgeti(L, -1, i + 1);
    c[i] = toColor(L, -1, what + "[" + std::to_string(i + 1) + "]");
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  return ColorPair(c[0], c[1]);
}

// The colours a blending pattern takes: colors={a, b, ...} spaced evenly
// from 0 to 1, or colors={{t, a}, {u, b}, ...} at stops (POV-Ray's
// color_map): an entry of two values whose first is a number is a stop (a
// colour has three, or is a name).
std::optional<ColorMap> colorMapArg(lua_State* L, LuaArgs& args) {
  if (!args.push("colors")) return std::nullopt;
  const std::string what = args.function() + ": colors";
  if (lua_type(L, -1) != LUA_TTABLE || lua_rawlen(L, -1) < 2)
    throw std::invalid_argument(what +
                                " must be a list of two or more colours, or of {place, colour} "
                                "stops such as {{0, \"white\"}, {0.7, \"steelblue\"}, {1, "
                                "\"navy\"}}");
  const lua_Unsigned n = lua_rawlen(L, -1);
  if (n > ColorMap::kMaxStops)
    throw std::invalid_argument(what + " must be at most " + std::to_string(ColorMap::kMaxStops) +
                                " colours, not " + std::to_string(n));
  std::vector<ColorStop> stops;
  std::vector<dvec3> plain;
  for (lua_Unsigned i = 1; i <= n; ++i) {
    const std::string entry = what + "[" + std::to_string(i) + "]";
    lua_rawgeti(L, -1, static_cast<lua_Integer>(i));
    bool stop = false;
    if (lua_type(L, -1) == LUA_TTABLE && lua_rawlen(L, -1) == 2) {
      lua_rawgeti(L, -1, 1);
      stop = lua_type(L, -1) == LUA_TNUMBER;
      lua_pop(L, 1);
    }
    if (stop) {
      lua_rawgeti(L, -1, 1);
      const double at = toNumber(L, -1, entry + "'s place");
      lua_pop(L, 1);
      lua_rawgeti(L, -1, 2);
      stops.push_back({at, toColor(L, -1, entry + "'s colour")});
      lua_pop(L, 1);
    } else {
      plain.push_back(toColor(L, -1, entry));
    }
    lua_pop(L, 1);
    if (!stops.empty() && !plain.empty())
      throw std::invalid_argument(what +
                                  ": give every entry as a colour, or every one as a {place, "
                                  "colour} stop");
  }
  lua_pop(L, 1);
  return plain.empty() ? ColorMap(std::move(stops), args.function())
                       : ColorMap::evenly(plain, args.function());
}

// scale=, rotate= and translate=, which every texture takes.
TexturePlacement placementArgs(LuaArgs& args) {
  TexturePlacement placement;
  placement.scale = args.vec3("scale");
  placement.rotate = args.vec3("rotate");
  placement.translate = args.vec3("translate");
  return placement;
}

int checker(lua_State* L) {
  checkArgumentCount(L, "checker", 1);
  LuaArgs args(L, 1, "checker");
  std::optional<ColorPair> colors = colorsArg(L, args);
  double size = args.number("size").value_or(1.0);
  TexturePtr texture = placedChecker(colors, size, placementArgs(args));
  args.finish();
  pushShared<TexturePtr>(L, std::move(texture));
  return 1;
}

int gradient(lua_State* L) {
  checkArgumentCount(L, "gradient", 1);
  LuaArgs args(L, 1, "gradient");
  std::optional<ColorMap> colors = colorMapArg(L, args);
  const dvec3 from = args.vec3("from").value_or(dvec3(0.0));
  const dvec3 to = args.vec3("to").value_or(dvec3(0.0, 0.0, 1.0));
  TexturePtr texture = placedGradient(colors, from, to, placementArgs(args));
  args.finish();
  pushShared<TexturePtr>(L, std::move(texture));
  return 1;
}

template <NoiseKind kind>
int noise(lua_State* L) {
  checkArgumentCount(L, noiseName(kind), 1);
  LuaArgs args(L, 1, noiseName(kind));
  std::optional<ColorMap> colors = colorMapArg(L, args);
  // Plain Perlin noise is one octave; the others sum octaves.
  double octaves = kind == NoiseKind::Perlin ? 1.0 : args.number("octaves").value_or(6.0);
  double strength = args.number("strength").value_or(4.0);
  TexturePtr texture = placedNoise(kind, colors, octaves, strength, placementArgs(args));
  args.finish();
  pushShared<TexturePtr>(L, std::move(texture));
  return 1;
}

// mandelbrot{colors=, inside=, iterations=} and julia{c={x, y}, ...}.
template <FractalKind kind>
int fractal(lua_State* L) {
  const char* name = kind == FractalKind::Mandelbrot ? "mandelbrot" : "julia";
  checkArgumentCount(L, name, 1);
  LuaArgs args(L, 1, name);
  std::optional<ColorMap> colors = colorMapArg(L, args);
  std::optional<dvec3> inside = args.color("inside");
  double iterations = args.number("iterations").value_or(100.0);
  dvec2 c(0.0);
  if (kind == FractalKind::Julia) {
    // The default: Douady's rabbit, a Julia set of three-lobed islands.
    c = dvec2(-0.123, 0.745);
    if (args.push("c")) {
      c = toVec2(L, -1, "julia: c");
      lua_pop(L, 1);
    }
  }
  TexturePtr texture =
      placedFractal(kind, colors, inside, iterations, c.x, c.y, placementArgs(args));
  args.finish();
  pushShared<TexturePtr>(L, std::move(texture));
  return 1;
}

int imageTexture(lua_State* L) {
  checkArgumentCount(L, "image_texture", 1);
  LuaArgs args(L, 1, "image_texture");
  std::optional<std::string> file = args.string("file");
  std::string mappingName = args.string("mapping").value_or("planar");
  TexturePlacement placement = placementArgs(args);
  if (!file) throw std::invalid_argument("image_texture: needs file=\"name.png\"");
  ImageMapping mapping;
  if (mappingName == "planar")
    mapping = ImageMapping::Planar;
  else if (mappingName == "spherical")
    mapping = ImageMapping::Spherical;
  else if (mappingName == "cylindrical")
    mapping = ImageMapping::Cylindrical;
  else if (mappingName == "box")
    mapping = ImageMapping::Box;
  else
    throw std::invalid_argument(
        "image_texture: mapping must be \"planar\", \"spherical\", "
        "\"cylindrical\" or \"box\", got \"" +
        shortened(mappingName) + "\"");
  const auto load = scriptImageLoader(L, *file);
  if (!load) throw std::invalid_argument("image_texture: this program cannot read images");
  const std::string path = scriptFile(L, "image_texture", *file);
  TextureImage loaded;
  try {
    loaded = load(path);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("image_texture: " + std::string(e.what()));
  }
  auto image = std::make_shared<TextureImage>(std::move(loaded));
  Sandbox::of(L).charge(L, image->rgb.size() * sizeof(float));
  TexturePtr texture = placedImage(std::move(image), mapping, placement);
  args.finish();
  pushShared<TexturePtr>(L, std::move(texture));
  return 1;
}

}  // namespace

void registerTextureApi(lua_State* L) {
  newMetatable<TexturePtr>(L);
  lua_pop(L, 1);
  static const luaL_Reg globals[] = {
      {"checker", guarded<checker>},
      {"gradient", guarded<gradient>},
      {"image_texture", guarded<imageTexture>},
      {"perlin", guarded<noise<NoiseKind::Perlin>>},
      {"turbulence", guarded<noise<NoiseKind::Turbulence>>},
      {"marble", guarded<noise<NoiseKind::Marble>>},
      {"wood", guarded<noise<NoiseKind::Wood>>},
      {"mandelbrot", guarded<fractal<FractalKind::Mandelbrot>>},
      {"julia", guarded<fractal<FractalKind::Julia>>},
  };
  for (const luaL_Reg& g : globals) lua_register(L, g.name, g.func);
}

}  // namespace csgray::detail
