// The named quadrics of seed 000's table 17.1 as script functions, and clip,
// which bounds an unbounded solid. Reference: docs/script.md, "Named
// quadrics".
#include <cmath>
#include <glm/mat4x4.hpp>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/boolean.h"
#include "primitives/box.h"
#include "primitives/quadric.h"
#include "script/api.h"
#include "script/lua_args.h"
#include "script/lua_values.h"

namespace csgray::detail {

namespace {

// ---- Named quadrics -----------------------------------------------------------

// 1/v² for a semi-axis v: a required positive finite number. Read with
// LuaArgs::number (which rejects NaN and ±inf), checked here after
// LuaArgs::finish, so that a misspelt name is reported as such rather than
// as a missing parameter.
double inverseSquareArg(const LuaArgs& args, const char* key, std::optional<double> v) {
  if (!v) throw std::invalid_argument(args.function() + ": needs " + key + " (> 0)");
  if (!(*v > 0.0)) {
    std::ostringstream msg;
    msg << args.function() << ": " << key << " must be > 0 (got " << *v << ")";
    throw std::invalid_argument(msg.str());
  }
  // 1/v² is the entry the semi-axis contributes to the matrix. For a tiny v
  // it overflows, and for a huge one it vanishes (which would silently turn
  // the quadric into a different one): both are errors.
  double s = 1.0 / (*v * *v);
  if (!std::isfinite(s) || s == 0.0) {
    std::ostringstream msg;
    msg << args.function() << ": " << key << " = " << *v << " is out of range (1/" << key
        << "² must be a finite non-zero double)";
    throw std::invalid_argument(msg.str());
  }
  return s;
}

glm::dmat4 diagonal(double x, double y, double z, double w) {
  glm::dmat4 m(0.0);
  m[0][0] = x;
  m[1][1] = y;
  m[2][2] = z;
  m[3][3] = w;
  return m;
}

// What the semi-axes a, b (and c) of a named quadric contribute.
struct Axes {
  double a2, b2, c2;  // 1/a², 1/b², 1/c²
};

Axes axesArgs(LuaArgs& args, bool withC) {
  std::optional<double> a = args.number("a");
  std::optional<double> b = args.number("b");
  std::optional<double> c = withC ? args.number("c") : std::nullopt;
  args.finish();
  return {inverseSquareArg(args, "a", a), inverseSquareArg(args, "b", b),
          withC ? inverseSquareArg(args, "c", c) : 1.0};
}

// The matrices are those of seed 000, table 17.1, divided by the positive
// factor a²b²c² (a²b² for the paraboloids and the elliptic and hyperbolic
// cylinders; the parabolic cylinder's is used as it is): the same quadric
// and the same solid pᵀMp <= 0, with entries 1/a² that do not overflow for
// semi-axes where a²b²c² would. The one exception is the hyperbolic
// cylinder, whose table matrix is negated (see below).

// x²/a² + y²/b² − z²/c² <= 1: inside the sheet, around the z axis.
glm::dmat4 hyperboloid1Matrix(LuaArgs& args) {
  Axes s = axesArgs(args, true);
  return diagonal(s.a2, s.b2, -s.c2, -1.0);
}

// x²/a² + y²/b² − z²/c² <= −1: inside both sheets, which hold the z axis
// for |z| >= c.
glm::dmat4 hyperboloid2Matrix(LuaArgs& args) {
  Axes s = axesArgs(args, true);
  return diagonal(s.a2, s.b2, -s.c2, 1.0);
}

// x²/a² + y²/b² <= z²/c²: both nappes, apex at the origin.
glm::dmat4 ellipticConeMatrix(LuaArgs& args) {
  Axes s = axesArgs(args, true);
  return diagonal(s.a2, s.b2, -s.c2, 0.0);
}

// x²/a² + y²/b² − z <= 0: vertex at the origin, opening up +z. The linear
// term −z is split over the two off-diagonal entries (z, w) and (w, z).
glm::dmat4 ellipticParaboloidMatrix(LuaArgs& args) {
  Axes s = axesArgs(args, false);
  glm::dmat4 m = diagonal(s.a2, s.b2, 0.0, 0.0);
  m[2][3] = m[3][2] = -0.5;
  return m;
}

// x²/a² − y²/b² − z <= 0: the side of the saddle above it (z >= x²/a² −
// y²/b²), which holds the +z axis.
glm::dmat4 hyperbolicParaboloidMatrix(LuaArgs& args) {
  Axes s = axesArgs(args, false);
  glm::dmat4 m = diagonal(s.a2, -s.b2, 0.0, 0.0);
  m[2][3] = m[3][2] = -0.5;
  return m;
}

// x²/a² + y²/b² <= 1, along z.
glm::dmat4 ellipticCylinderMatrix(LuaArgs& args) {
  Axes s = axesArgs(args, false);
  return diagonal(s.a2, s.b2, 0.0, -1.0);
}

// x²/a² − y²/b² >= 1, along z: the two regions inside the sheets, which
// hold the x axis for |x| >= a. The table's matrix, taken as it is, would
// give the region between the sheets (x²/a² − y²/b² <= 1); the inside of
// the sheets is chosen to match the other quadrics, whose solid is the
// side the surface curves around. Hence the factor −1/(a²b²).
glm::dmat4 hyperbolicCylinderMatrix(LuaArgs& args) {
  Axes s = axesArgs(args, false);
  return diagonal(-s.a2, s.b2, 0.0, 1.0);
}

// y² − 2px <= 0, along z: vertex line on the z axis, opening towards +x for
// p > 0 and towards −x for p < 0. The table's matrix as it is.
glm::dmat4 parabolicCylinderMatrix(LuaArgs& args) {
  std::optional<double> p = args.number("p");
  args.finish();
  if (!p) throw std::invalid_argument("parabolic_cylinder: needs p (not 0)");
  if (*p == 0.0) throw std::invalid_argument("parabolic_cylinder: p must not be 0");
  glm::dmat4 m(0.0);
  m[1][1] = 1.0;
  m[0][3] = m[3][0] = -*p;
  return m;
}

template <glm::dmat4 (*Matrix)(LuaArgs&)>
int namedQuadric(lua_State* L, const char* function) {
  LuaArgs args(L, 1, function);
  pushSolid(L, Primitive::create<Quadric>(Matrix(args)));
  return 1;
}

// One Lua function per quadric, so that each message names its function.
#define CSGRAY_NAMED_QUADRIC(name, matrix) \
  int name(lua_State* L) { return namedQuadric<matrix>(L, #name); }
CSGRAY_NAMED_QUADRIC(hyperboloid1, hyperboloid1Matrix)
CSGRAY_NAMED_QUADRIC(hyperboloid2, hyperboloid2Matrix)
CSGRAY_NAMED_QUADRIC(elliptic_cone, ellipticConeMatrix)
CSGRAY_NAMED_QUADRIC(elliptic_paraboloid, ellipticParaboloidMatrix)
CSGRAY_NAMED_QUADRIC(hyperbolic_paraboloid, hyperbolicParaboloidMatrix)
CSGRAY_NAMED_QUADRIC(elliptic_cylinder, ellipticCylinderMatrix)
CSGRAY_NAMED_QUADRIC(hyperbolic_cylinder, hyperbolicCylinderMatrix)
CSGRAY_NAMED_QUADRIC(parabolic_cylinder, parabolicCylinderMatrix)
#undef CSGRAY_NAMED_QUADRIC

// ---- clip -----------------------------------------------------------------------

// The box {lo=, hi=} at stack index 2.
SolidPtr clipBox(lua_State* L) {
  LuaArgs args(L, 2, "clip");
  std::optional<dvec3> lo = args.vec3("lo");
  std::optional<dvec3> hi = args.vec3("hi");
  args.finish();
  if (!lo || !hi) throw std::invalid_argument(std::string("clip: needs ") + (lo ? "hi" : "lo"));
  const char* axes = "xyz";
  for (int i = 0; i < 3; ++i) {
    if (!((*lo)[i] < (*hi)[i])) {
      std::ostringstream msg;
      msg << "clip: lo must be below hi on every axis (" << axes[i] << ": " << (*lo)[i]
          << " >= " << (*hi)[i] << ")";
      throw std::invalid_argument(msg.str());
    }
    if (!std::isfinite((*hi)[i] - (*lo)[i]))
      throw std::invalid_argument(std::string("clip: the box is too large along ") + axes[i]);
  }
  return Primitive::create<Box>(*hi - *lo)->transformed(Affine::translation(*lo));
}

// The one material of all the solid's primitives, or null if they have none
// or several.
MaterialPtr uniformMaterial(const Solid& solid) {
  MaterialPtr found;
  bool first = true;
  std::vector<const Solid*> pending{&solid};  // a walk without recursion: trees may be deep
  while (!pending.empty()) {
    const Solid* s = pending.back();
    pending.pop_back();
    if (const auto* p = dynamic_cast<const Primitive*>(s)) {
      if (!first && p->material() != found) return nullptr;
      found = p->material();
      first = false;
    }
    for (const SolidPtr& child : s->children()) pending.push_back(child.get());
  }
  return found;
}

// clip(solid, {lo=, hi=}), clip(solid, other) or clip(solid, {a, b, ...}):
// the solid intersected with the box, the other solid, or all of the list.
int clip(lua_State* L) {
  if (lua_gettop(L) > 2)
    throw std::invalid_argument("clip: takes two arguments, a solid and {lo=, hi=} or solids");
  if (lua_isnoneornil(L, 1)) throw std::invalid_argument("clip: needs a solid to clip");
  const SolidPtr& solid = checkValue<SolidPtr>(L, 1, "clip: the first argument");
  std::vector<SolidPtr> cutters;
  // Memory charged against the script's cap: the new intersection node with
  // its operand list, and any cutter built here.
  std::size_t charge = kBytesPerNode;
  if (lua_isnoneornil(L, 2)) {
    throw std::invalid_argument("clip: needs a box {lo=, hi=}, a solid or a list of solids");
  } else if (lua_type(L, 2) == LUA_TUSERDATA) {
    cutters.push_back(checkValue<SolidPtr>(L, 2, "clip: the second argument"));
  } else if (lua_type(L, 2) == LUA_TTABLE && hasStringKey(L, 2)) {
    cutters.push_back(clipBox(L));
    charge += kBytesPerNode;
  } else if (lua_type(L, 2) == LUA_TTABLE) {
    lua_Unsigned count = lua_rawlen(L, 2);
    if (count == 0)
      throw std::invalid_argument("clip: the second argument is empty; give {lo=, hi=} or solids");
    for (lua_Unsigned i = 1; i <= count; ++i) {
      lua_rawgeti(L, 2, static_cast<lua_Integer>(i));
      cutters.push_back(checkValue<SolidPtr>(L, -1, "clip: cutter " + std::to_string(i)));
      lua_pop(L, 1);
    }
  } else {
    throw std::invalid_argument(
        std::string("clip: the second argument must be {lo=, hi=}, a solid or a list of solids, "
                    "got ") +
        luaL_typename(L, 2));
  }
  // Clipping only bounds the solid: the faces the cutters add should look
  // like the rest of it. Cutters without a material of their own take the
  // solid's, when the whole solid has one (a copy of the cutter, charged).
  if (MaterialPtr material = uniformMaterial(*solid)) {
    for (SolidPtr& c : cutters) {
      c = c->withDefaultMaterial(material);
      charge += (c->primitiveCount() + c->booleanCount()) * kBytesPerNode;
    }
  }
  std::vector<SolidPtr> operands{solid};
  operands.insert(operands.end(), cutters.begin(), cutters.end());
  charge += operands.size() * sizeof(SolidPtr);
  auto result = std::make_shared<Boolean>(Boolean::Op::Intersection, std::move(operands));
  markOrigin(L, *result);
  pushValue<SolidPtr>(L, std::move(result), charge);
  return 1;
}

}  // namespace

void registerQuadricApi(lua_State* L) {
  static const luaL_Reg globals[] = {
      {"hyperboloid1", guarded<hyperboloid1>},
      {"hyperboloid2", guarded<hyperboloid2>},
      {"elliptic_cone", guarded<elliptic_cone>},
      {"elliptic_paraboloid", guarded<elliptic_paraboloid>},
      {"hyperbolic_paraboloid", guarded<hyperbolic_paraboloid>},
      {"elliptic_cylinder", guarded<elliptic_cylinder>},
      {"hyperbolic_cylinder", guarded<hyperbolic_cylinder>},
      {"parabolic_cylinder", guarded<parabolic_cylinder>},
      {"clip", guarded<clip>},
  };
  for (const luaL_Reg& g : globals) lua_register(L, g.name, g.func);
}

}  // namespace csgray::detail
