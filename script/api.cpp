#include "script/api.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <new>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/boolean.h"
#include "engine/tight_bounds.h"
#include "primitives/blob.h"
#include "primitives/quadric.h"
#include "scene/modifiers.h"
#include "scene/resize.h"
#include "scene/rotation.h"
#include "scene/shapes.h"
#include "script/lua_args.h"
#include "script/lua_values.h"
#include "script/sandbox.h"

namespace csgray::detail {

namespace {

// ---- Argument shapes ------------------------------------------------------

// A vector given as f(x, y, z), f{x, y, z} or f(s) for {s, s, s}; noun
// names it in messages ("contains: point[1] must be finite").
dvec3 vectorArgs(lua_State* L, int first, const std::string& function, const char* noun) {
  int n = lua_gettop(L) - first + 1;
  if (n == 3) {
    return {toNumber(L, first, function + ": x"), toNumber(L, first + 1, function + ": y"),
            toNumber(L, first + 2, function + ": z")};
  }
  if (n == 1) return toVec3(L, first, function + ": " + noun);
  throw std::invalid_argument(function + ": takes x, y, z or {x, y, z} (got " + std::to_string(n) +
                              (n == 1 ? " argument)" : " arguments)"));
}

// A shape constructor: a table of named parameters, or a bare main value
// (sphere(5), box{10, 20, 30}) that stands for the named one.
LuaArgs shapeArgs(lua_State* L, const char* function, const char* mainKey) {
  checkArgumentCount(L, function, 1);
  // sphere(radius) with radius never set: say so, not "needs r".
  if (lua_gettop(L) == 1 && lua_isnil(L, 1))
    throw std::invalid_argument(std::string(function) + ": got nil (a variable without a value?) " +
                                "where " + mainKey + " or a table of parameters goes");
  bool bare = lua_type(L, 1) == LUA_TNUMBER ||
              (lua_type(L, 1) == LUA_TTABLE && lua_rawlen(L, 1) > 0 && !hasStringKey(L, 1));
  if (bare) {
    lua_createtable(L, 0, 1);
    lua_pushvalue(L, 1);
    lua_setfield(L, -2, mainKey);
    lua_replace(L, 1);
  }
  return LuaArgs(L, 1, function);
}

// ---- Primitives ---------------------------------------------------------------
// The shapes and their checks are in scene/shapes.h; these read them.

int sphere(lua_State* L) {
  LuaArgs args = shapeArgs(L, "sphere", "r");
  std::optional<double> r = args.number("r"), d = args.number("d");
  args.finish();
  pushSolid(L, sphereShape(r, d));
  return 1;
}

int ellipsoid(lua_State* L) {
  LuaArgs args = shapeArgs(L, "ellipsoid", "radii");
  std::optional<dvec3> radii = args.vec3("radii");
  args.finish();
  pushSolid(L, ellipsoidShape(radii));
  return 1;
}

int box(lua_State* L) {
  LuaArgs args = shapeArgs(L, "box", "size");
  std::optional<dvec3> size = args.vec3("size");
  bool center = args.boolean("center").value_or(false);
  args.finish();  // an unknown name (corner1=) before "needs size"
  pushSolid(L, boxShape(size, center));
  return 1;
}

// cylinder{} and cone{}: function names which.
int cylinderOrCone(lua_State* L, const char* function) {
  checkArgumentCount(L, function, 1);
  LuaArgs args(L, 1, function);
  CylinderParams p;
  p.h = args.number("h");
  p.r = args.number("r");
  p.d = args.number("d");
  p.r1 = args.number("r1");
  p.d1 = args.number("d1");
  p.r2 = args.number("r2");
  p.d2 = args.number("d2");
  p.center = args.boolean("center").value_or(false);
  args.finish();  // an unknown name (base=) before "needs h"
  pushSolid(L, cylinderShape(function, p));
  return 1;
}

int cylinder(lua_State* L) { return cylinderOrCone(L, "cylinder"); }
int cone(lua_State* L) { return cylinderOrCone(L, "cone"); }

int halfSpace(lua_State* L) {
  checkArgumentCount(L, "half_space", 1);
  LuaArgs args(L, 1, "half_space");
  std::optional<dvec3> normal = args.vec3("normal");
  double offset = args.number("offset").value_or(0.0);
  args.finish();
  pushSolid(L, halfSpaceShape(normal, offset));
  return 1;
}

int torus(lua_State* L) {
  checkArgumentCount(L, "torus", 1);
  LuaArgs args(L, 1, "torus");
  std::optional<double> major = args.number("R");
  std::optional<double> minor = args.number("r");
  args.finish();
  pushSolid(L, torusShape(major, minor));
  return 1;
}

int superellipsoid(lua_State* L) {
  // POV-Ray's superellipsoid { <e, n> }, written as superellipsoid{e, n}.
  if (lua_type(L, 1) == LUA_TTABLE && lua_rawlen(L, 1) == 2 && !hasStringKey(L, 1))
    throw std::invalid_argument(
        "superellipsoid: the exponents are named here, and the size too: "
        "superellipsoid{radii=1, e=..., n=...} for POV-Ray's superellipsoid { <e, n> }");
  LuaArgs args = shapeArgs(L, "superellipsoid", "radii");
  std::optional<dvec3> radii = args.vec3("radii");
  std::optional<double> e = args.number("e"), n = args.number("n");
  args.finish();
  pushSolid(L, superellipsoidShape(radii, e, n));
  return 1;
}

// blob{balls={{center={x, y, z}, r=, strength=1}, ...}, threshold=0.5}.
int blob(lua_State* L) {
  checkArgumentCount(L, "blob", 1);
  LuaArgs args(L, 1, "blob");
  const std::optional<double> threshold = args.number("threshold");
  if (!args.push("balls"))
    throw std::invalid_argument("blob: needs balls={{center={x, y, z}, r=, strength=}, ...}");
  const int list = lua_gettop(L);
  if (lua_type(L, list) != LUA_TTABLE || lua_rawlen(L, list) == 0)
    throw std::invalid_argument(
        "blob: balls must be a list of balls {center={x, y, z}, r=, strength=}");
  const lua_Unsigned count = lua_rawlen(L, list);
  if (count > Blob::kMaxBalls)
    throw std::invalid_argument("blob: at most " + std::to_string(Blob::kMaxBalls) +
                                " balls (got " + std::to_string(count) + ")");
  std::vector<BlobBall> balls;
  balls.reserve(count);
  for (lua_Unsigned i = 1; i <= count; ++i) {
    lua_rawgeti(L, list, static_cast<lua_Integer>(i));
    const std::string what = "blob: ball " + std::to_string(i);
    if (lua_type(L, -1) != LUA_TTABLE)
      throw std::invalid_argument(
          what + " must be a table {center={x, y, z}, r=, strength=}, got " + shownType(L, -1));
    LuaArgs ball(L, -1, what);
    const std::optional<dvec3> center = ball.vec3("center");
    const std::optional<double> r = ball.number("r");
    const double strength = ball.number("strength").value_or(1.0);
    ball.finish();
    if (!r) throw std::invalid_argument(what + ": needs r (its radius of influence)");
    balls.push_back({center.value_or(dvec3(0.0)), *r, strength});
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  args.finish();
  SolidPtr solid = blobShape(std::move(balls), threshold);
  Sandbox::of(L).charge(L, count * sizeof(BlobBall));
  pushSolid(L, solid);
  return 1;
}

// A 4×4 matrix given as four rows of four numbers; with allowThreeRows the
// last row may be left out (it is 0 0 0 1).
glm::dmat4 matrixArg(lua_State* L, int index, const std::string& what, bool allowThreeRows) {
  index = lua_absindex(L, index);
  lua_Unsigned rows = lua_type(L, index) == LUA_TTABLE ? lua_rawlen(L, index) : 0;
  if (rows != 4 && !(allowThreeRows && rows == 3))
    throw std::invalid_argument(what + " must be a table of " +
                                (allowThreeRows ? "3 or 4" : std::string("4")) +
                                " rows of 4 numbers");
  glm::dmat4 m(1.0);
  for (lua_Unsigned r = 0; r < rows; ++r) {
    lua_rawgeti(L, index, static_cast<lua_Integer>(r + 1));
    if (lua_type(L, -1) != LUA_TTABLE || lua_rawlen(L, -1) != 4)
      throw std::invalid_argument(what + ": row " + std::to_string(r + 1) + " must have 4 numbers");
    for (int c = 0; c < 4; ++c) {
      lua_rawgeti(L, -1, c + 1);
      m[c][r] =
          toNumber(L, -1, what + "[" + std::to_string(r + 1) + "][" + std::to_string(c + 1) + "]");
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
  }
  return m;
}

int quadric(lua_State* L) {
  checkArgumentCount(L, "quadric", 1);
  LuaArgs args(L, 1, "quadric");
  if (!args.push("matrix")) throw std::invalid_argument("quadric: needs matrix={{...}, ...} (4×4)");
  glm::dmat4 m = matrixArg(L, -1, "quadric: matrix", false);
  lua_pop(L, 1);
  args.finish();
  pushSolid(L, Primitive::create<Quadric>(m));
  return 1;
}

// ---- Booleans ---------------------------------------------------------------

}  // namespace

std::vector<SolidPtr> solidOperands(lua_State* L, const std::string& function) {
  std::vector<SolidPtr> operands;
  // The value at index: a solid, or a list of solids (one level).
  auto take = [&](int index, const std::string& what) {
    if (lua_type(L, index) != LUA_TTABLE) {
      operands.push_back(checkValue<SolidPtr>(L, index, what));
      return;
    }
    index = lua_absindex(L, index);
    lua_Unsigned count = lua_rawlen(L, index);
    for (lua_Unsigned i = 1; i <= count; ++i) {
      lua_rawgeti(L, index, static_cast<lua_Integer>(i));
      operands.push_back(checkValue<SolidPtr>(L, -1, what + "[" + std::to_string(i) + "]"));
      lua_pop(L, 1);
    }
  };
  int n = lua_gettop(L);
  if (n == 1 && lua_type(L, 1) == LUA_TTABLE) {
    lua_Unsigned count = lua_rawlen(L, 1);
    for (lua_Unsigned i = 1; i <= count; ++i) {
      lua_rawgeti(L, 1, static_cast<lua_Integer>(i));
      std::string what = function + ": operand " + std::to_string(i);
      if (lua_type(L, -1) == LUA_TTABLE)  // f{a, {b, c}}: no deeper
        operands.push_back(checkValue<SolidPtr>(L, -1, what));
      else
        take(-1, what);
      lua_pop(L, 1);
    }
  } else {
    for (int i = 1; i <= n; ++i) take(i, function + ": operand " + std::to_string(i));
  }
  // A list given, and left empty (a loop that added nothing, a count of 0
  // from -D): there is no empty solid to stand for it.
  if (operands.empty() && n >= 1 && lua_type(L, 1) == LUA_TTABLE)
    throw std::invalid_argument(function +
                                ": the list is empty; there is no empty solid, so leave the " +
                                function + " out when the list is (if #list > 0 then ... end)");
  return operands;  // booleanShape refuses no operands
}

namespace {

template <Boolean::Op op>
int booleanOf(lua_State* L) {
  pushSolid(L, booleanShape(op, solidOperands(L, booleanName(op))));
  return 1;
}

// ---- Solid methods ------------------------------------------------------------

// The receiver moved: a solid or an open surface.
void pushTransformed(lua_State* L, const char* method, const Affine& worldFromObject) {
  if (SurfacePtr* surface = toValue<SurfacePtr>(L, 1)) {
    pushShared<SurfacePtr>(L, (*surface)->transformed(worldFromObject));
    return;
  }
  pushSolid(L, methodReceiver(L, method)->transformed(worldFromObject));
}

int translate(lua_State* L) {
  // OpenSCAD's translate([x, y]) of a solid: z is 0. (Two numbers, or a
  // list of two, can mean nothing else.)
  const int n = lua_gettop(L) - 1;
  if (n == 2 || (n == 1 && lua_type(L, 2) == LUA_TTABLE && lua_rawlen(L, 2) == 2)) {
    const dvec2 xy = n == 2 ? dvec2(toNumber(L, 2, "translate: x"), toNumber(L, 3, "translate: y"))
                            : toVec2(L, 2, "translate: offset");
    pushTransformed(L, "translate", Affine::translation(dvec3(xy, 0.0)));
    return 1;
  }
  dvec3 offset = vectorArgs(L, 2, "translate", "offset");
  pushTransformed(L, "translate", Affine::translation(offset));
  return 1;
}

int scale(lua_State* L) {
  dvec3 factors = vectorArgs(L, 2, "scale", "factors");
  pushTransformed(L, "scale", Affine::scaling(factors));
  return 1;
}

int mirror(lua_State* L) {
  dvec3 normal = vectorArgs(L, 2, "mirror", "normal");
  pushTransformed(L, "mirror", Affine::mirror(normal));
  return 1;
}

// resize(x, y, z) or resize{x, y, z, auto=}: OpenSCAD's resize, scaled
// about the origin so that the solid's bounds() get these sizes.
int resize(lua_State* L) {
  const SolidPtr& solid = methodReceiver(L, "resize");
  const ResizeArgs args = resizeArgs(L, 3);
  pushSolid(L, solid->transformed(
                   Affine::scaling(resizeFactors(tightBounds(*solid), args.size, args.autoAxes))));
  return 1;
}

// rotate(x, y, z) or rotate{x, y, z}: degrees about x, then y, then z
// (OpenSCAD's rotate([x, y, z])); rotate{angle=a, axis={...}}: a degrees
// about the axis, by default z. rotate(a), one number, turns about z, as
// OpenSCAD's rotate(a) does and as a region's rotate(a) does here: not a
// degrees about each axis in turn, as a vector's one number would say.
int rotate(lua_State* L) {
  constexpr dvec3 kZ(0.0, 0.0, 1.0);
  if (lua_gettop(L) == 2 && lua_type(L, 2) == LUA_TNUMBER) {
    pushTransformed(L, "rotate", rotationDegrees(dvec3(0.0, 0.0, toNumber(L, 2, "rotate: angle"))));
    return 1;
  }
  if (lua_gettop(L) == 2 && lua_type(L, 2) == LUA_TTABLE && lua_rawlen(L, 2) == 0) {
    LuaArgs args(L, 2, "rotate");
    std::optional<double> angle = args.number("angle");
    std::optional<dvec3> axis = args.vec3("axis");
    args.finish();
    if (!angle) throw std::invalid_argument("rotate: needs angle= (and axis=), or x, y, z");
    pushTransformed(L, "rotate", rotationDegrees(*angle, axis.value_or(kZ)));
    return 1;
  }
  pushTransformed(L, "rotate", rotationDegrees(vectorArgs(L, 2, "rotate", "angles")));
  return 1;
}

int transform(lua_State* L) {
  checkArgumentCount(L, "transform", 1, 2);
  glm::dmat4 m = matrixArg(L, 2, "transform", true);
  pushTransformed(L, "transform", Affine::fromMatrix(m));
  return 1;
}

// bounds() returns two points, the low and the high corner.
int bounds(lua_State* L) {
  const SolidPtr& solid = methodReceiver(L, "bounds");
  checkArgumentCount(L, "bounds", 0, 2);
  const Bounds& b = solid->bounds();
  pushVec3(L, b.lo);
  pushVec3(L, b.hi);
  return 2;
}

int contains(lua_State* L) {
  const SolidPtr& solid = methodReceiver(L, "contains");
  lua_pushboolean(L, solid->contains(vectorArgs(L, 2, "contains", "point")));
  return 1;
}

int solidToString(lua_State* L) {
  const SolidPtr& solid = checkValue<SolidPtr>(L, 1, "tostring");
  TreeStats stats = treeStats(*solid);
  std::ostringstream s;
  s << "solid(" << solid->kind() << ", " << stats.primitives << " primitives)";
  lua_pushstring(L, s.str().c_str());
  return 1;
}

// s:highlight(), s:ghost(), s:disable() and only(s): OpenSCAD's `#`, `%`,
// `*` and `!` (scene/modifiers.h).
template <Modifier modifier>
int markSolid(lua_State* L) {
  const std::string name = modifierName(modifier);
  const SolidPtr& solid = modifier == Modifier::Only
                              ? checkValue<SolidPtr>(L, 1, name + ": argument")
                              : methodReceiver(L, name);
  if (modifier == Modifier::Only)
    checkArgumentCount(L, name, 1);
  else
    checkArgumentCount(L, name, 0, 2);
  pushSolid(L, std::make_shared<MarkedSolid>(modifier, solid));
  return 1;
}

template <Boolean::Op op>
int booleanOperator(lua_State* L) {
  const char* symbol = op == Boolean::Op::Union ? "+" : op == Boolean::Op::Intersection ? "*" : "-";
  std::string what = std::string("operand of '") + symbol + "'";
  const SolidPtr& a = checkValue<SolidPtr>(L, 1, what);
  const SolidPtr& b = checkValue<SolidPtr>(L, 2, what);
  pushSolid(L, std::make_shared<Boolean>(op, std::vector<SolidPtr>{a, b}));
  return 1;
}

// ---- Registration -----------------------------------------------------------

}  // namespace

namespace {
const char* const kOptionsKey = "csgray.options";
}

const ScriptOptions& scriptOptionsOf(lua_State* L) {
  lua_getfield(L, LUA_REGISTRYINDEX, kOptionsKey);
  const auto* options = static_cast<const ScriptOptions*>(lua_touserdata(L, -1));
  lua_pop(L, 1);
  return *options;
}

void registerScriptApi(lua_State* L, const ScriptOptions& options) {
  lua_pushlightuserdata(L, const_cast<ScriptOptions*>(&options));
  lua_setfield(L, LUA_REGISTRYINDEX, kOptionsKey);
  // Transforms apply to solids and open surfaces alike.
  static const luaL_Reg transforms[] = {
      {"translate", guarded<translate>}, {"rotate", guarded<rotate>},
      {"scale", guarded<scale>},         {"mirror", guarded<mirror>},
      {"transform", guarded<transform>}, {nullptr, nullptr}};
  newMetatable<SolidPtr>(L);
  static const luaL_Reg methods[] = {{"material", guarded<solidMaterial>},
                                     {"bounds", guarded<bounds>},
                                     {"contains", guarded<contains>},
                                     {"resize", guarded<resize>},
                                     {"highlight", guarded<markSolid<Modifier::Highlight>>},
                                     {"ghost", guarded<markSolid<Modifier::Ghost>>},
                                     {"disable", guarded<markSolid<Modifier::Disable>>},
                                     {nullptr, nullptr}};
  luaL_newlib(L, methods);
  luaL_setfuncs(L, transforms, 0);
  lua_setfield(L, -2, "__index");
  static const luaL_Reg operators[] = {
      {"__add", guarded<booleanOperator<Boolean::Op::Union>>},
      {"__sub", guarded<booleanOperator<Boolean::Op::Difference>>},
      {"__mul", guarded<booleanOperator<Boolean::Op::Intersection>>},
      {"__tostring", guarded<solidToString>},
      {nullptr, nullptr}};
  luaL_setfuncs(L, operators, 0);
  lua_pop(L, 1);

  static const luaL_Reg globals[] = {
      {"sphere", guarded<sphere>},
      {"ellipsoid", guarded<ellipsoid>},
      {"box", guarded<box>},
      {"cylinder", guarded<cylinder>},
      {"cone", guarded<cone>},
      {"half_space", guarded<halfSpace>},
      {"quadric", guarded<quadric>},
      {"torus", guarded<torus>},
      {"superellipsoid", guarded<superellipsoid>},
      {"blob", guarded<blob>},
      {"union", guarded<booleanOf<Boolean::Op::Union>>},
      {"intersection", guarded<booleanOf<Boolean::Op::Intersection>>},
      {"difference", guarded<booleanOf<Boolean::Op::Difference>>},
      {"only", guarded<markSolid<Modifier::Only>>},
  };
  for (const luaL_Reg& g : globals) lua_register(L, g.name, g.func);
  registerTextureApi(L);
  registerSurfaceApi(L, transforms);
  registerLightApi(L);
  registerSceneApi(L);
  registerQuadricApi(L);
  registerConvexApi(L);
  registerMeshApi(L);
  registerCheckApi(L);
  registerProjectionApi(L);
  registerHullApi(L);
  // After the solids' booleans, which union() and its kin call for solids,
  // and after the surfaces: square and rectangle are regions.
  registerRegionApi(L);
  registerSweepApi(L);
  registerCsgApi(L);
  registerImportApi(L);
  registerTextApi(L);
}

}  // namespace csgray::detail
