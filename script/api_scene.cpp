// The script API for what a scene shows beyond its solids: materials and
// textures, lights, open surfaces, the camera, and the scene itself.
// Reference: docs/script.md.
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/boolean.h"
#include "engine/primitive.h"
#include "script/api.h"
#include "script/lua_args.h"
#include "script/lua_values.h"

namespace csgray::detail {

namespace {

// ---- Checks -----------------------------------------------------------------

double unitArg(LuaArgs& args, const char* key, double fallback) {
  double v = args.number(key).value_or(fallback);
  if (v < 0.0 || v > 1.0)
    throw std::invalid_argument(args.function() + ": " + key + " must be in [0, 1]");
  return v;
}

double positiveArg(LuaArgs& args, const char* key, double fallback) {
  double v = args.number(key).value_or(fallback);
  if (!(v > 0.0)) throw std::invalid_argument(args.function() + ": " + key + " must be > 0");
  return v;
}

dvec3 colorArg(LuaArgs& args, const char* key, const dvec3& fallback) {
  dvec3 c = args.vec3(key).value_or(fallback);
  if (c.x < 0.0 || c.y < 0.0 || c.z < 0.0)
    throw std::invalid_argument(args.function() + ": " + key + " components must be >= 0");
  return c;
}

dvec3 nonZeroVector(LuaArgs& args, const char* key, const dvec3& fallback) {
  dvec3 v = args.vec3(key).value_or(fallback);
  if (!(glm::length(v) > 0.0))
    throw std::invalid_argument(args.function() + ": " + key + " must not be the zero vector");
  return v;
}

// ---- Textures ---------------------------------------------------------------

// The two colours of a pattern: colors={{r, g, b}, {r, g, b}}.
std::pair<dvec3, dvec3> colorPair(lua_State* L, LuaArgs& args, const dvec3& a, const dvec3& b) {
  if (!args.push("colors")) return {a, b};
  std::string what = args.function() + ": colors";
  if (lua_type(L, -1) != LUA_TTABLE || lua_rawlen(L, -1) != 2)
    throw std::invalid_argument(what + " must be a list of two colours {{r, g, b}, {r, g, b}}");
  dvec3 c[2];
  for (int i = 0; i < 2; ++i) {
    lua_rawgeti(L, -1, i + 1);
    c[i] = toVec3(L, -1, what + "[" + std::to_string(i + 1) + "]");
    lua_pop(L, 1);
    if (c[i].x < 0.0 || c[i].y < 0.0 || c[i].z < 0.0)
      throw std::invalid_argument(what + " components must be >= 0");
  }
  lua_pop(L, 1);
  return {c[0], c[1]};
}

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// Every texture takes scale=, rotate= and translate=, applied to the
// pattern in that order.
void pushTexture(lua_State* L, LuaArgs& args, std::shared_ptr<Texture> texture) {
  Affine placement;
  try {
    if (std::optional<dvec3> s = args.vec3("scale")) placement = Affine::scaling(*s);
    if (std::optional<dvec3> r = args.vec3("rotate"))
      placement = placement.then(Affine::rotation(radians(r->x), {1, 0, 0}))
                      .then(Affine::rotation(radians(r->y), {0, 1, 0}))
                      .then(Affine::rotation(radians(r->z), {0, 0, 1}));
    if (std::optional<dvec3> t = args.vec3("translate"))
      placement = placement.then(Affine::translation(*t));
  } catch (const std::invalid_argument& e) {  // a zero scale: name the texture
    std::string what = e.what();
    if (what.starts_with(args.function())) throw;
    throw std::invalid_argument(args.function() + ": " + what);
  }
  args.finish();
  texture->setPlacement(placement);
  pushValue<TexturePtr>(L, std::move(texture));
}

// A texture the factory has just made, not yet shared with anything, so its
// placement may still be set.
std::shared_ptr<Texture> mutableCopy(const TexturePtr& t) {
  return std::const_pointer_cast<Texture>(t);
}

int checker(lua_State* L) {
  LuaArgs args(L, 1, "checker");
  auto [a, b] = colorPair(L, args, dvec3(1.0), dvec3(0.1));
  double size = positiveArg(args, "size", 1.0);
  pushTexture(L, args, mutableCopy(checkerTexture(a, b, size)));
  return 1;
}

// A file named by the script: relative to the script's folder, and not
// outside it (scripts are untrusted: they may not read /etc/passwd as a
// texture).
}  // namespace

// Declared in api_mesh.cpp too, which reads mesh files.
std::string scriptFile(lua_State* L, const std::string& function, const std::string& name) {
  namespace fs = std::filesystem;
  const ScriptOptions& options = scriptOptionsOf(L);
  if (name.empty()) throw std::invalid_argument(function + ": file is empty");
  // The file system would stop at a NUL byte: "a.png\0/../../x" would open
  // a.png, and messages would be cut short there.
  if (name.find('\0') != std::string::npos)
    throw std::invalid_argument(function + ": file name contains a NUL byte");
  fs::path folder = fs::weakly_canonical(fs::absolute(options.folder));
  fs::path file = fs::weakly_canonical(folder / fs::path(name));
  auto inside = [&file](const fs::path& dir) {
    auto [end, _] = std::mismatch(dir.begin(), dir.end(), file.begin(), file.end());
    return end == dir.end();
  };
  // Symbolic links are followed before the check (weakly_canonical), so a
  // link cannot lead out either.
  if (!fs::path(name).is_absolute() && inside(folder)) return file.string();
  for (const std::string& allowed : options.allowedFolders)
    if (inside(fs::weakly_canonical(fs::absolute(allowed)))) return file.string();
  throw std::invalid_argument(function + ": file " + name +
                              " is outside the script's folder; give a path relative to it" +
                              (options.allowedFolders.empty()
                                   ? std::string(", or allow its folder with --allow-path")
                                   : std::string(" or inside a folder given with --allow-path")));
}

namespace {

int imageTextureFn(lua_State* L) {
  LuaArgs args(L, 1, "image_texture");
  std::optional<std::string> file = args.string("file");
  std::string mappingName = args.string("mapping").value_or("planar");
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
        mappingName + "\"");
  const ScriptOptions& options = scriptOptionsOf(L);
  if (!options.loadImage)
    throw std::invalid_argument("image_texture: this program cannot read images");
  std::string path = scriptFile(L, "image_texture", *file);
  auto image = std::make_shared<TextureImage>(options.loadImage(path));
  Sandbox::of(L).charge(L, image->rgb.size() * sizeof(float));
  pushTexture(L, args, mutableCopy(imageTexture(std::move(image), mapping)));
  return 1;
}

template <NoiseKind kind>
int noise(lua_State* L) {
  const char* name = kind == NoiseKind::Perlin       ? "perlin"
                     : kind == NoiseKind::Turbulence ? "turbulence"
                     : kind == NoiseKind::Marble     ? "marble"
                                                     : "wood";
  LuaArgs args(L, 1, name);
  dvec3 a = kind == NoiseKind::Wood ? dvec3(0.55, 0.33, 0.16) : dvec3(0.9, 0.9, 0.88);
  dvec3 b = kind == NoiseKind::Wood ? dvec3(0.3, 0.16, 0.07) : dvec3(0.2, 0.2, 0.25);
  auto [colorA, colorB] = colorPair(L, args, a, b);
  // Plain Perlin noise is one octave; the others sum octaves.
  double octaves = kind == NoiseKind::Perlin ? 1.0 : args.number("octaves").value_or(6.0);
  if (octaves != std::floor(octaves) || octaves < 1 || octaves > 16)
    throw std::invalid_argument(std::string(name) +
                                ": octaves must be a whole number from 1 to 16");
  double strength = args.number("strength").value_or(4.0);
  if (!(strength >= 0.0))
    throw std::invalid_argument(std::string(name) + ": strength must be >= 0");
  pushTexture(L, args, mutableCopy(noiseTexture(kind, colorA, colorB, int(octaves), strength)));
  return 1;
}

// ---- Materials --------------------------------------------------------------

// material{...}: every key is optional; see docs/script.md.
MaterialPtr materialArgs(lua_State* L, int index) {
  LuaArgs args(L, index, "material");
  auto m = std::make_shared<Material>();
  if (args.push("color")) {
    if (TexturePtr* texture = toValue<TexturePtr>(L, -1)) {
      m->texture = *texture;
      lua_pop(L, 1);
    } else {
      lua_pop(L, 1);
      m->color = colorArg(args, "color", m->color);
    }
  }
  m->ambient = unitArg(args, "ambient", m->ambient);
  m->diffuse = unitArg(args, "diffuse", m->diffuse);
  m->specular = unitArg(args, "specular", m->specular);
  m->shininess = positiveArg(args, "shininess", m->shininess);
  m->reflection = unitArg(args, "reflection", m->reflection);
  m->transparency = unitArg(args, "transparency", m->transparency);
  m->filter = colorArg(args, "filter", m->filter);
  if (m->filter.x > 1.0 || m->filter.y > 1.0 || m->filter.z > 1.0)
    throw std::invalid_argument("material: filter components must be in [0, 1]");
  m->ior = args.number("ior").value_or(m->ior);
  if (!(m->ior >= 1.0 && m->ior <= 10.0))
    throw std::invalid_argument("material: ior must be from 1 to 10");
  m->fresnel = args.boolean("fresnel").value_or(false);
  args.finish();
  return m;
}

int surfaceMaterial(lua_State* L) {
  const SurfacePtr& surface = checkValue<SurfacePtr>(L, 1, "method receiver (use ':')");
  MaterialPtr m = materialArgs(L, 2);
  pushValue<SurfacePtr>(L, surface->withMaterial(m));
  return 1;
}

// ---- Open surfaces ----------------------------------------------------------

// A surface constructor: validates with the message of its kind.
void pushSurface(lua_State* L, SurfacePtr surface) { pushValue<SurfacePtr>(L, std::move(surface)); }

int plane(lua_State* L) {
  LuaArgs args(L, 1, "plane");
  dvec3 normal = nonZeroVector(args, "normal", dvec3(0, 0, 1));
  double offset = args.number("offset").value_or(0.0);
  args.finish();
  dvec3 unit = glm::normalize(normal);
  pushSurface(L, Surface::plane(offset / glm::length(normal) * unit, unit));
  return 1;
}

int disc(lua_State* L) {
  LuaArgs args(L, 1, "disc");
  std::optional<double> r = args.number("r"), d = args.number("d");
  if (r && d) throw std::invalid_argument("disc: give r or d, not both");
  double radius = r ? *r : d ? *d / 2.0 : -1.0;
  if (!r && !d) throw std::invalid_argument("disc: needs r (radius) or d (diameter)");
  if (!(radius > 0.0)) throw std::invalid_argument("disc: the radius must be > 0");
  dvec3 center = args.vec3("center").value_or(dvec3(0.0));
  dvec3 normal = nonZeroVector(args, "normal", dvec3(0, 0, 1));
  args.finish();
  pushSurface(L, Surface::disc(center, normal, radius));
  return 1;
}

int triangle(lua_State* L) {
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
  LuaArgs args(L, 1, "parallelogram");
  dvec3 origin = args.vec3("origin").value_or(dvec3(0.0));
  std::optional<dvec3> u = args.vec3("u"), v = args.vec3("v");
  args.finish();
  if (!u || !v) throw std::invalid_argument("parallelogram: needs the edges u={...} and v={...}");
  pushSurface(L, Surface::parallelogram(origin, *u, *v));
  return 1;
}

// rectangle{size={w, h}} and square{size=s}: in the xy plane from the
// origin (centred with center=true), facing +z, like OpenSCAD's square.
template <bool isSquare>
int rectangle(lua_State* L) {
  const char* name = isSquare ? "square" : "rectangle";
  LuaArgs args(L, 1, name);
  double w, h;
  if (isSquare) {
    w = h = args.number("size").value_or(-1.0);
  } else {
    if (!args.push("size")) throw std::invalid_argument("rectangle: needs size={w, h}");
    if (lua_type(L, -1) != LUA_TTABLE || lua_rawlen(L, -1) != 2)
      throw std::invalid_argument("rectangle: size must be {w, h}");
    lua_rawgeti(L, -1, 1);
    lua_rawgeti(L, -2, 2);
    w = toNumber(L, -2, "rectangle: size[1]");
    h = toNumber(L, -1, "rectangle: size[2]");
    lua_pop(L, 3);
  }
  bool center = args.boolean("center").value_or(false);
  args.finish();
  if (!(w > 0.0) || !(h > 0.0))
    throw std::invalid_argument(std::string(name) + ": size must be > 0");
  dvec3 origin = center ? dvec3(-w / 2, -h / 2, 0) : dvec3(0.0);
  pushSurface(L, Surface::parallelogram(origin, dvec3(w, 0, 0), dvec3(0, h, 0), name));
  return 1;
}

int surfaceBooleanError(lua_State* L) {
  SurfacePtr* s = toValue<SurfacePtr>(L, 1);
  if (!s) s = toValue<SurfacePtr>(L, 2);
  std::string kind = s ? (*s)->kind() : "surface";
  throw std::invalid_argument("a " + kind +
                              " is a surface, not a solid: it encloses no volume, so it cannot "
                              "take part in a boolean (put it in scene{objects=...} instead)");
}

// ---- Lights -----------------------------------------------------------------

// What every light takes: color, intensity, falloff.
void lightCommon(LuaArgs& args, Light& light) {
  light.color = colorArg(args, "color", light.color);
  light.intensity = args.number("intensity").value_or(light.intensity);
  if (!(light.intensity >= 0.0))
    throw std::invalid_argument(args.function() + ": intensity must be >= 0");
  light.inverseSquare = args.boolean("falloff").value_or(false);
}

dvec3 requiredPoint(LuaArgs& args, const char* key) {
  std::optional<dvec3> p = args.vec3(key);
  if (!p) throw std::invalid_argument(args.function() + ": needs " + key + "={x, y, z}");
  return *p;
}

int pointLight(lua_State* L) {
  LuaArgs args(L, 1, "point_light");
  Light light;
  light.position = requiredPoint(args, "pos");
  lightCommon(args, light);
  args.finish();
  pushValue(L, light);
  return 1;
}

int spotLight(lua_State* L) {
  LuaArgs args(L, 1, "spot_light");
  Light light;
  light.kind = Light::Kind::Spot;
  light.position = requiredPoint(args, "pos");
  std::optional<dvec3> lookAt = args.vec3("look_at");
  std::optional<dvec3> direction = args.vec3("direction");
  if (lookAt && direction)
    throw std::invalid_argument("spot_light: give look_at or direction, not both");
  light.direction = direction ? *direction : lookAt ? *lookAt - light.position : dvec3(0, 0, -1);
  if (!(glm::length(light.direction) > 0.0))
    throw std::invalid_argument("spot_light: the direction is the zero vector (look_at = pos?)");
  light.coneDegrees = args.number("angle").value_or(light.coneDegrees);
  if (!(light.coneDegrees > 0.0 && light.coneDegrees < 90.0))
    throw std::invalid_argument("spot_light: angle must be between 0 and 90 degrees");
  light.exponent = args.number("exponent").value_or(light.exponent);
  if (!(light.exponent >= 0.0)) throw std::invalid_argument("spot_light: exponent must be >= 0");
  lightCommon(args, light);
  args.finish();
  pushValue(L, light);
  return 1;
}

int samplesArg(LuaArgs& args) {
  double n = args.number("samples").value_or(16.0);
  if (n != std::floor(n) || n < 1 || n > 1024)
    throw std::invalid_argument(args.function() +
                                ": samples must be a whole number from 1 to 1024");
  return int(n);
}

int areaLight(lua_State* L) {
  LuaArgs args(L, 1, "area_light");
  Light light;
  light.kind = Light::Kind::Rectangle;
  light.position = requiredPoint(args, "pos");
  light.edgeU = nonZeroVector(args, "u", light.edgeU);
  light.edgeV = nonZeroVector(args, "v", light.edgeV);
  // Parallel edges span no rectangle: its samples would all lie on a line.
  // (Relative to the edges' lengths, so that a scale of the scene keeps it.)
  if (!(glm::length(glm::cross(light.edgeU, light.edgeV)) >
        1e-9 * glm::length(light.edgeU) * glm::length(light.edgeV)))
    throw std::invalid_argument(
        "area_light: u and v must not be parallel (they are the rectangle's edges)");
  light.samples = samplesArg(args);
  lightCommon(args, light);
  args.finish();
  pushValue(L, light);
  return 1;
}

int sphereLight(lua_State* L) {
  LuaArgs args(L, 1, "sphere_light");
  Light light;
  light.kind = Light::Kind::Sphere;
  light.position = requiredPoint(args, "pos");
  light.radius = positiveArg(args, "r", light.radius);
  light.samples = samplesArg(args);
  lightCommon(args, light);
  args.finish();
  pushValue(L, light);
  return 1;
}

// ---- Camera and scene -------------------------------------------------------

int camera(lua_State* L) {
  LuaArgs args(L, 1, "camera");
  CameraSpec c;
  c.eye = args.vec3("eye").value_or(c.eye);
  c.lookAt = args.vec3("look_at").value_or(c.lookAt);
  c.up = args.vec3("up").value_or(c.up);
  c.fovDegrees = args.number("fov").value_or(c.fovDegrees);
  std::string projection = args.string("projection").value_or("perspective");
  std::optional<double> width = args.number("width");
  args.finish();
  if (projection != "perspective" && projection != "orthographic")
    throw std::invalid_argument("camera: projection must be \"perspective\" or \"orthographic\"");
  c.orthographic = projection == "orthographic";
  if (width && !c.orthographic)
    throw std::invalid_argument("camera: width is for projection=\"orthographic\"; use fov");
  if (width && !(*width > 0.0)) throw std::invalid_argument("camera: width must be > 0");
  c.orthoWidth = width.value_or(0.0);  // 0: fit the scene
  if (!(c.fovDegrees > 0.0 && c.fovDegrees < 180.0))
    throw std::invalid_argument("camera: fov must be between 0 and 180 degrees");
  dvec3 view = c.lookAt - c.eye;
  if (glm::length(view) == 0.0)
    throw std::invalid_argument("camera: eye and look_at are the same point");
  if (glm::length(glm::cross(view, c.up)) <= 1e-12 * glm::length(view) * glm::length(c.up))
    throw std::invalid_argument("camera: up must not be parallel to the view direction");
  pushValue(L, c);
  return 1;
}

// Calls f for a single value under key or for each value of a list.
template <class F>
void forEachListed(lua_State* L, LuaArgs& args, const char* key, F f) {
  if (!args.push(key)) return;
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
}

// Memory a call charges while it builds a value, given back when the call
// ends (the value is then charged as a whole by pushValue), also when it
// fails.
class PendingCharge {
 public:
  explicit PendingCharge(lua_State* L) : L_(L) {}
  ~PendingCharge() { Sandbox::of(L_).release(bytes_); }
  PendingCharge(const PendingCharge&) = delete;
  PendingCharge& operator=(const PendingCharge&) = delete;
  void add(std::size_t bytes) {
    bytes_ += bytes;
    Sandbox::of(L_).charge(L_, bytes);
  }
  // Gives the charge back and returns it, for pushValue to charge again.
  std::size_t settle() {
    std::size_t b = bytes_;
    Sandbox::of(L_).release(b);
    bytes_ = 0;
    return b;
  }

 private:
  lua_State* L_;
  std::size_t bytes_ = 0;
};

int scene(lua_State* L) {
  LuaArgs args(L, 1, "scene");
  Scene s;
  // The lists are copied into the scene: charged as they grow, so that a
  // list of millions of references to one light or part stops at the
  // memory limit instead of exhausting the machine. The objects are drawn
  // together, so they share the limit on primitives of a part.
  PendingCharge pending(L);
  std::size_t primitives = 0;
  auto count = [&](std::size_t n, const std::string& what) {
    primitives += n;
    if (primitives > Boolean::kMaxPrimitives)
      throw std::invalid_argument(what + ": the scene would have more than " +
                                  std::to_string(Boolean::kMaxPrimitives) +
                                  " primitives and surfaces (counting each use of a shared part)");
  };
  // Objects: solids and open surfaces, alone or in a list.
  forEachListed(L, args, "objects", [&](const std::string& what) {
    if (SurfacePtr* surface = toValue<SurfacePtr>(L, -1)) {
      count(1, what);
      pending.add(sizeof(SurfacePtr));
      s.surfaces.push_back(*surface);
    } else {
      const SolidPtr& solid = checkValue<SolidPtr>(L, -1, what + " (a solid or surface)");
      count(solid->primitiveCount(), what);
      pending.add(sizeof(SolidPtr));
      s.objects.push_back(solid);
    }
  });
  forEachListed(L, args, "lights", [&](const std::string& what) {
    pending.add(sizeof(Light));
    s.lights.push_back(checkValue<Light>(L, -1, what));
  });
  if (args.push("camera")) {
    s.camera = checkValue<CameraSpec>(L, -1, "scene: camera");
    lua_pop(L, 1);
  }
  s.background = colorArg(args, "background", s.background);
  double depth = args.number("max_depth").value_or(s.limits.maxDepth);
  if (depth != std::floor(depth) || depth < 0 || depth > 64)
    throw std::invalid_argument("scene: max_depth must be a whole number from 0 to 64");
  s.limits.maxDepth = int(depth);
  s.limits.minWeight = unitArg(args, "min_weight", s.limits.minWeight);
  args.finish();
  if (s.objects.empty() && s.surfaces.empty())
    throw std::invalid_argument("scene: objects is empty");
  pushValue(L, std::move(s), kBytesPerNode + pending.settle());
  return 1;
}

}  // namespace

int solidMaterial(lua_State* L) {
  const SolidPtr& solid = checkValue<SolidPtr>(L, 1, "method receiver (use ':')");
  MaterialPtr m = materialArgs(L, 2);
  // On a primitive it replaces the material; on a boolean it goes to every
  // primitive below that has none of its own.
  if (auto* p = dynamic_cast<const Primitive*>(solid.get())) {
    pushSolid(L, p->withMaterial(m));
  } else {
    pushSolid(L, solid->withDefaultMaterial(m));
  }
  return 1;
}

void registerSceneApi(lua_State* L, const luaL_Reg* transformMethods) {
  newMetatable<SurfacePtr>(L);
  static const luaL_Reg surfaceMethods[] = {{"material", guarded<surfaceMaterial>},
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
  newMetatable<TexturePtr>(L);
  lua_pop(L, 1);
  newMetatable<CameraSpec>(L);
  lua_pop(L, 1);
  newMetatable<Light>(L);
  lua_pop(L, 1);
  newMetatable<Scene>(L);
  lua_pop(L, 1);

  static const luaL_Reg globals[] = {
      {"checker", guarded<checker>},
      {"image_texture", guarded<imageTextureFn>},
      {"perlin", guarded<noise<NoiseKind::Perlin>>},
      {"turbulence", guarded<noise<NoiseKind::Turbulence>>},
      {"marble", guarded<noise<NoiseKind::Marble>>},
      {"wood", guarded<noise<NoiseKind::Wood>>},
      {"plane", guarded<plane>},
      {"disc", guarded<disc>},
      {"triangle", guarded<triangle>},
      {"parallelogram", guarded<parallelogram>},
      {"rectangle", guarded<rectangle<false>>},
      {"square", guarded<rectangle<true>>},
      {"point_light", guarded<pointLight>},
      {"spot_light", guarded<spotLight>},
      {"area_light", guarded<areaLight>},
      {"sphere_light", guarded<sphereLight>},
      {"camera", guarded<camera>},
      {"scene", guarded<scene>},
  };
  for (const luaL_Reg& g : globals) lua_register(L, g.name, g.func);
}

Scene sceneFromValue(lua_State* L, int index) {
  if (SolidPtr* solid = toValue<SolidPtr>(L, index)) {
    Scene s;
    s.objects.push_back(*solid);
    return s;
  }
  if (SurfacePtr* surface = toValue<SurfacePtr>(L, index)) {
    Scene s;
    s.surfaces.push_back(*surface);
    return s;
  }
  if (Scene* s = toValue<Scene>(L, index)) return *s;
  throw std::invalid_argument(std::string("the script must return a solid, a surface or "
                                          "scene{...}, not ") +
                              luaL_typename(L, index));
}

}  // namespace csgray::detail
