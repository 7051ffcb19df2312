#include "script/api.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <new>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/boolean.h"
#include "primitives/box.h"
#include "primitives/cylinder.h"
#include "primitives/half_space.h"
#include "primitives/quadric.h"
#include "primitives/sphere.h"
#include "primitives/torus.h"
#include "script/lua_args.h"
#include "script/lua_values.h"
#include "script/sandbox.h"

namespace csgray::detail {

namespace {

// ---- Argument shapes ------------------------------------------------------

// A vector given as f(x, y, z), f{x, y, z} or f(s) for {s, s, s}.
dvec3 vectorArgs(lua_State* L, int first, const std::string& what) {
  int n = lua_gettop(L) - first + 1;
  if (n == 3) {
    return {toNumber(L, first, what + " x"), toNumber(L, first + 1, what + " y"),
            toNumber(L, first + 2, what + " z")};
  }
  if (n == 1) return toVec3(L, first, what);
  throw std::invalid_argument(what + ": expected x, y, z or {x, y, z}");
}

// A shape constructor: a table of named parameters, or a bare main value
// (sphere(5), box{10, 20, 30}) that stands for the named one.
LuaArgs shapeArgs(lua_State* L, const char* function, const char* mainKey) {
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

// center=true moves a shape whose object frame starts at the origin so that
// its box is centred there.
SolidPtr centred(const SolidPtr& solid, LuaArgs& args, const dvec3& offset) {
  if (!args.boolean("center").value_or(false)) return solid;
  return solid->transformed(Affine::translation(offset));
}

// ---- Primitives -------------------------------------------------------------

// A radius from r= or d= (diameter), as in OpenSCAD.
// Checked here, so that the message names the parameter the script used.
std::optional<double> radiusArg(LuaArgs& args, const char* r, const char* d, bool zeroAllowed) {
  std::optional<double> radius = args.number(r);
  std::optional<double> diameter = args.number(d);
  if (radius && diameter)
    throw std::invalid_argument(args.function() + ": give " + r + " or " + d + ", not both");
  const char* given = diameter ? d : r;
  std::optional<double> value = diameter ? diameter : radius;
  if (value && (*value < 0.0 || (*value == 0.0 && !zeroAllowed))) {
    std::ostringstream msg;
    msg << args.function() << ": " << given << " must be " << (zeroAllowed ? ">= 0" : "> 0")
        << " (got " << *value << ")";
    throw std::invalid_argument(msg.str());
  }
  if (diameter) return *diameter / 2.0;
  return radius;
}

int sphere(lua_State* L) {
  LuaArgs args = shapeArgs(L, "sphere", "r");
  std::optional<double> r = radiusArg(args, "r", "d", false);
  args.finish();
  if (!r) throw std::invalid_argument("sphere: needs r (radius) or d (diameter)");
  pushSolid(L, Primitive::create<Sphere>(*r));
  return 1;
}

int ellipsoid(lua_State* L) {
  LuaArgs args = shapeArgs(L, "ellipsoid", "radii");
  std::optional<dvec3> radii = args.vec3("radii");
  args.finish();
  if (!radii) throw std::invalid_argument("ellipsoid: needs radii={a, b, c}");
  for (int i = 0; i < 3; ++i)
    if (!((*radii)[i] > 0.0)) throw std::invalid_argument("ellipsoid: radii must be positive");
  // A unit sphere under a non-uniform scale: exact, normals by inverse transpose.
  pushSolid(L, Primitive::create<Sphere>(1.0)->transformed(Affine::scaling(*radii)));
  return 1;
}

int box(lua_State* L) {
  LuaArgs args = shapeArgs(L, "box", "size");
  std::optional<dvec3> size = args.vec3("size");
  if (!size) throw std::invalid_argument("box: needs size={x, y, z} (or a number for a cube)");
  SolidPtr solid = centred(Primitive::create<Box>(*size), args, -0.5 * *size);
  args.finish();
  pushSolid(L, solid);
  return 1;
}

SolidPtr cylinderFrom(LuaArgs& args, bool defaultR2IsR1) {
  std::optional<double> h = args.number("h");
  std::optional<double> r = radiusArg(args, "r", "d", false);
  std::optional<double> r1 = radiusArg(args, "r1", "d1", true);
  std::optional<double> r2 = radiusArg(args, "r2", "d2", true);
  if (!h) throw std::invalid_argument(args.function() + ": needs h (height)");
  if (r && (r1 || r2))
    throw std::invalid_argument(args.function() + ": give r, or r1 and r2, not both");
  double bottom = r ? *r : r1.value_or(-1.0);
  if (bottom < 0.0 && !r1) throw std::invalid_argument(args.function() + ": needs r or r1");
  double top = r ? (defaultR2IsR1 ? *r : 0.0) : r2.value_or(defaultR2IsR1 ? bottom : 0.0);
  SolidPtr solid = Primitive::create<Cylinder>(bottom, top, *h);
  return centred(solid, args, dvec3(0.0, 0.0, -0.5 * *h));
}

int cylinder(lua_State* L) {
  LuaArgs args(L, 1, "cylinder");
  SolidPtr solid = cylinderFrom(args, true);
  args.finish();
  pushSolid(L, solid);
  return 1;
}

int cone(lua_State* L) {
  LuaArgs args(L, 1, "cone");
  SolidPtr solid = cylinderFrom(args, false);
  args.finish();
  pushSolid(L, solid);
  return 1;
}

int halfSpace(lua_State* L) {
  LuaArgs args(L, 1, "half_space");
  std::optional<dvec3> normal = args.vec3("normal");
  double offset = args.number("offset").value_or(0.0);
  args.finish();
  if (!normal) throw std::invalid_argument("half_space: needs normal={x, y, z}");
  pushSolid(L, Primitive::create<HalfSpace>(*normal, offset));
  return 1;
}

// torus{R=, r=}: about the z axis in the xy plane; R from the axis to the
// centre of the tube, r the tube's radius. Any R >= 0 is a solid.
int torus(lua_State* L) {
  LuaArgs args(L, 1, "torus");
  std::optional<double> major = args.number("R");
  std::optional<double> minor = args.number("r");
  args.finish();
  if (!major || !minor)
    throw std::invalid_argument("torus: needs R (major radius) and r (tube radius)");
  auto check = [](const char* name, double value, bool zeroAllowed) {
    if (value > 0.0 || (zeroAllowed && value == 0.0)) return;
    std::ostringstream msg;
    msg << "torus: " << name << " must be " << (zeroAllowed ? ">= 0" : "> 0") << " (got " << value
        << ")";
    throw std::invalid_argument(msg.str());
  };
  check("R", *major, true);
  check("r", *minor, false);
  pushSolid(L, Primitive::create<Torus>(*major, *minor));
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
  LuaArgs args(L, 1, "quadric");
  if (!args.push("matrix")) throw std::invalid_argument("quadric: needs matrix={{...}, ...} (4×4)");
  glm::dmat4 m = matrixArg(L, -1, "quadric: matrix", false);
  lua_pop(L, 1);
  args.finish();
  pushSolid(L, Primitive::create<Quadric>(m));
  return 1;
}

// ---- Booleans ---------------------------------------------------------------

// Operands as f(a, b, c) or f{a, b, c}; an operand may also be a list of
// solids, as in difference(a, holes) (the form that boolean.cpp's message
// about deep trees recommends).
std::vector<SolidPtr> operandArgs(lua_State* L, const std::string& function) {
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
  if (operands.empty()) throw std::invalid_argument(function + ": needs at least one solid");
  return operands;
}

template <Boolean::Op op>
int booleanOf(lua_State* L) {
  const char* name = op == Boolean::Op::Union          ? "union"
                     : op == Boolean::Op::Intersection ? "intersection"
                                                       : "difference";
  std::vector<SolidPtr> operands = operandArgs(L, name);
  SolidPtr result =
      operands.size() == 1 ? operands[0] : std::make_shared<Boolean>(op, std::move(operands));
  pushSolid(L, result);
  return 1;
}

// ---- Solid methods ------------------------------------------------------------

const SolidPtr& self(lua_State* L) {
  return checkValue<SolidPtr>(L, 1, "method receiver (use ':')");
}

// The receiver moved: a solid or an open surface.
void pushTransformed(lua_State* L, const Affine& worldFromObject) {
  if (SurfacePtr* surface = toValue<SurfacePtr>(L, 1)) {
    pushValue<SurfacePtr>(L, (*surface)->transformed(worldFromObject));
    return;
  }
  pushSolid(L, self(L)->transformed(worldFromObject));
}

int translate(lua_State* L) {
  dvec3 offset = vectorArgs(L, 2, "translate");
  pushTransformed(L, Affine::translation(offset));
  return 1;
}

int scale(lua_State* L) {
  dvec3 factors = vectorArgs(L, 2, "scale");
  pushTransformed(L, Affine::scaling(factors));
  return 1;
}

int mirror(lua_State* L) {
  dvec3 normal = vectorArgs(L, 2, "mirror");
  pushTransformed(L, Affine::mirror(normal));
  return 1;
}

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// rotate(x, y, z) or rotate{x, y, z}: degrees about x, then y, then z
// (OpenSCAD's rotate([x, y, z])); rotate{angle=a, axis={...}}: a degrees
// about the axis.
int rotate(lua_State* L) {
  if (lua_gettop(L) == 2 && lua_type(L, 2) == LUA_TTABLE && lua_rawlen(L, 2) == 0) {
    LuaArgs args(L, 2, "rotate");
    std::optional<double> angle = args.number("angle");
    std::optional<dvec3> axis = args.vec3("axis");
    args.finish();
    if (!angle || !axis) throw std::invalid_argument("rotate: needs angle= and axis=, or x, y, z");
    pushTransformed(L, Affine::rotation(radians(*angle), *axis));
    return 1;
  }
  dvec3 angles = vectorArgs(L, 2, "rotate");
  Affine r = Affine::rotation(radians(angles.x), {1, 0, 0})
                 .then(Affine::rotation(radians(angles.y), {0, 1, 0}))
                 .then(Affine::rotation(radians(angles.z), {0, 0, 1}));
  pushTransformed(L, r);
  return 1;
}

int transform(lua_State* L) {
  glm::dmat4 m = matrixArg(L, 2, "transform", true);
  pushTransformed(L, Affine::fromMatrix(m));
  return 1;
}

// bounds() returns two points, the low and the high corner.
int bounds(lua_State* L) {
  const Bounds& b = self(L)->bounds();
  pushVec3(L, b.lo);
  pushVec3(L, b.hi);
  return 2;
}

int contains(lua_State* L) {
  const SolidPtr& solid = self(L);
  lua_pushboolean(L, solid->contains(vectorArgs(L, 2, "contains")));
  return 1;
}

int solidToString(lua_State* L) {
  const SolidPtr& solid = self(L);
  TreeStats stats = treeStats(*solid);
  std::ostringstream s;
  s << "solid(" << solid->kind() << ", " << stats.primitives << " primitives)";
  lua_pushstring(L, s.str().c_str());
  return 1;
}

template <Boolean::Op op>
int booleanOperator(lua_State* L) {
  const char* symbol = op == Boolean::Op::Union ? "+" : op == Boolean::Op::Intersection ? "*" : "-";
  std::string what = std::string("operand of '") + symbol + "'";
  const SolidPtr& a = checkValue<SolidPtr>(L, 1, what);
  const SolidPtr& b = checkValue<SolidPtr>(L, 2, what);
  pushBoolean(L, std::make_shared<Boolean>(op, std::vector<SolidPtr>{a, b}));
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
      {"union", guarded<booleanOf<Boolean::Op::Union>>},
      {"intersection", guarded<booleanOf<Boolean::Op::Intersection>>},
      {"difference", guarded<booleanOf<Boolean::Op::Difference>>},
  };
  for (const luaL_Reg& g : globals) lua_register(L, g.name, g.func);
  registerSceneApi(L, transforms);
  registerQuadricApi(L);
  registerConvexApi(L);
  registerMeshApi(L);
  registerCheckApi(L);
}

}  // namespace csgray::detail
