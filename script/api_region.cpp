// 2D regions in the script (docs/script.md, "2D regions"): the shapes of
// the plane, their booleans, transforms, offsets and hulls. A region is a
// Lua userdata of metatable "csgray.region" holding a RegionPtr; its user
// value names what it was made as ("square", "circle", "region"), for
// messages and for the surface it becomes in a scene.
//
// A region is not a solid. Placed in a scene it is a flat surface in the
// plane z = 0 (scene/region_surface.h). A 3D transform that keeps that
// plane where it is (translate(x, y, 0), rotate(0, 0, a), ...) leaves a
// region; one that moves or tilts the plane, or a material, places it in
// space as that flat surface, which no sweep takes any more.
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "profile/region_evaluation.h"
#include "profile/region_operations.h"
#include "profile/shapes.h"
#include "scene/region_surface.h"
#include "scene/resize.h"
#include "script/api.h"
#include "script/lua_args.h"
#include "script/lua_values.h"

namespace csgray::detail {

namespace {

// ---- Region values ------------------------------------------------------------

// What a region's nodes cost: a leaf its edges besides the node, a boolean
// its operand list (as held_objects.h counts the nodes of solids).
std::size_t nodeBytes(const Region& node) {
  if (node.op() != Region::Op::Leaf)
    return kBytesPerBoolean + node.operands().size() * sizeof(RegionPtr);
  std::size_t edges = 0;
  for (const ProfileLoop& loop : node.profile().loops)
    edges += loop.edges.size() * sizeof(ProfileEdge) + sizeof(ProfileLoop);
  return kBytesPerShape + edges;
}

void pushRegionAs(lua_State* L, RegionPtr region, const std::string& kind) {
  Sandbox& sandbox = Sandbox::of(L);
  std::vector<Sandbox::HeldObject> fresh;
  auto collect = [&](auto& self, const RegionPtr& node) -> void {
    if (sandbox.holds(node)) return;
    fresh.push_back({node, nodeBytes(*node)});
    for (const RegionPtr& operand : node->operands()) self(self, operand);
  };
  collect(collect, region);
  sandbox.hold(L, fresh);
  void* memory = lua_newuserdatauv(L, sizeof(Held<RegionPtr>), 1);
  new (memory) Held<RegionPtr>{std::move(region), 0};
  luaL_setmetatable(L, TypeName<RegionPtr>::value);
  lua_pushstring(L, kind.c_str());
  lua_setiuservalue(L, -2, 1);
}

// The region a method was called on.
// The error for a value where a region was wanted, `what` naming the place
// ("union: operand 2").
[[noreturn]] void notARegion(lua_State* L, int index, const std::string& what) {
  if (SurfacePtr* s = toValue<SurfacePtr>(L, index)) {
    if ((*s)->shape() == Surface::Shape::Region)
      throw std::invalid_argument(what + " must be a region, but this " + (*s)->kind() +
                                  " was placed in space (by a 3D transform or a material), so "
                                  "it is a flat surface now");
    throw std::invalid_argument(what + " must be a region, but a " + (*s)->kind() +
                                " is a surface");
  }
  if (toValue<SolidPtr>(L, index))
    throw std::invalid_argument(what +
                                " must be a region, not a solid: 2D regions and solids do not "
                                "mix (extrude the region first)");
  throw std::invalid_argument(what + " must be a region, got " + shownType(L, index));
}

const RegionPtr& regionAt(lua_State* L, int index, const std::string& what) {
  if (RegionPtr* r = toValue<RegionPtr>(L, index)) return *r;
  notARegion(L, index, what);
}

// The region a method was called on.
const RegionPtr& receiver(lua_State* L, const char* method) {
  return regionAt(L, 1, std::string(method) + ": the receiver (call it as r:" + method + "(...))");
}

// ---- Shapes -------------------------------------------------------------------

// A shape's table of named parameters, or a bare main value (circle(5),
// polygon{{0, 0}, {1, 0}, {0, 1}}) that stands for the named one.
LuaArgs shapeArgs(lua_State* L, const char* function, const char* mainKey) {
  checkArgumentCount(L, function, 1);
  const bool bare = lua_type(L, 1) == LUA_TNUMBER ||
                    (lua_type(L, 1) == LUA_TTABLE && lua_rawlen(L, 1) > 0 && !hasStringKey(L, 1));
  if (bare) {
    lua_createtable(L, 0, 1);
    lua_pushvalue(L, 1);
    lua_setfield(L, -2, mainKey);
    lua_replace(L, 1);
  }
  return LuaArgs(L, 1, function);
}

// square{size=s or {w, h}, center=} and rectangle{size={w, h}, center=}.
template <bool isSquare>
int rectangle(lua_State* L) {
  const char* name = isSquare ? "square" : "rectangle";
  LuaArgs args = shapeArgs(L, name, "size");
  if (!args.push("size"))
    throw std::invalid_argument(std::string(name) + ": needs size=" + (isSquare ? "s" : "{w, h}"));
  dvec2 size;
  if (lua_type(L, -1) == LUA_TNUMBER) {
    if (!isSquare) throw std::invalid_argument("rectangle: size must be {w, h}");
    size = dvec2(toNumber(L, -1, "square: size"));
  } else {
    size = toVec2(L, -1, std::string(name) + ": size");
  }
  lua_pop(L, 1);
  const bool center = args.boolean("center").value_or(false);
  args.finish();
  pushRegionAs(L, rectangleRegion(name, size.x, size.y, center), name);
  return 1;
}

int circle(lua_State* L) {
  LuaArgs args = shapeArgs(L, "circle", "r");
  std::optional<double> r = args.number("r"), d = args.number("d");
  args.finish();
  pushRegionAs(L, circleRegion(r, d), "circle");
  return 1;
}

int ellipse(lua_State* L) {
  checkArgumentCount(L, "ellipse", 1);
  LuaArgs args(L, 1, "ellipse");
  std::optional<double> rx = args.number("rx"), ry = args.number("ry");
  args.finish();
  if (!rx || !ry) throw std::invalid_argument("ellipse: needs rx and ry (the half-axes)");
  pushRegionAs(L, ellipseRegion(*rx, *ry), "ellipse");
  return 1;
}

// The length of the list at index, or an error naming what it should be.
lua_Unsigned listLength(lua_State* L, int index, const std::string& what, const char* expected) {
  if (lua_type(L, index) != LUA_TTABLE)
    throw std::invalid_argument(what + " must be " + expected + ", got " + shownType(L, index));
  return lua_rawlen(L, index);
}

// polygon{points={{x, y}, ...}, paths={{i, j, k, ...}, ...}}: indices from
// 0, as polyhedron's faces and OpenSCAD's paths. The lists are charged as
// they are read (a list's length may be far from what it holds).
int polygon(lua_State* L) {
  LuaArgs args = shapeArgs(L, "polygon", "points");
  PendingCharge pending(L);
  if (!args.push("points")) throw std::invalid_argument("polygon: needs points={{x, y}, ...}");
  std::vector<dvec2> points;
  const lua_Unsigned n = listLength(L, -1, "polygon: points", "a list of points {{x, y}, ...}");
  for (lua_Unsigned i = 1; i <= n; ++i) {
    lua_rawgeti(L, -1, static_cast<lua_Integer>(i));
    pending.add(sizeof(dvec2));
    points.push_back(toVec2(L, -1, "polygon: points[" + std::to_string(i) + "]"));
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  std::vector<std::vector<std::size_t>> paths;
  if (args.push("paths")) {
    const lua_Unsigned count =
        listLength(L, -1, "polygon: paths", "a list of paths {{i, j, k, ...}, ...}");
    for (lua_Unsigned p = 1; p <= count; ++p) {
      const std::string what = "polygon: paths[" + std::to_string(p) + "]";
      lua_rawgeti(L, -1, static_cast<lua_Integer>(p));
      const lua_Unsigned length =
          listLength(L, -1, what, "a list of point indices {i, j, k, ...} (from 0)");
      std::vector<std::size_t>& path = paths.emplace_back();
      for (lua_Unsigned k = 1; k <= length; ++k) {
        lua_rawgeti(L, -1, static_cast<lua_Integer>(k));
        int isInteger = 0;
        const lua_Integer v = lua_tointegerx(L, -1, &isInteger);
        if (lua_type(L, -1) != LUA_TNUMBER || !isInteger || v < 0)
          throw std::invalid_argument(what + "[" + std::to_string(k) +
                                      "] must be a point index (an integer from 0)");
        lua_pop(L, 1);
        pending.add(sizeof(std::size_t));
        path.push_back(static_cast<std::size_t>(v));
      }
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
    if (paths.empty()) throw std::invalid_argument("polygon: paths must not be empty");
  }
  args.number("convexity");  // OpenSCAD's hint for its preview; rays need none
  args.finish();
  pushRegionAs(L, polygonRegion(points, paths), "polygon");
  return 1;
}

int regularPolygon(lua_State* L) {
  checkArgumentCount(L, "regular_polygon", 1);
  LuaArgs args(L, 1, "regular_polygon");
  std::optional<double> n = args.number("n");
  std::optional<double> r = args.number("r"), flats = args.number("flats");
  args.finish();
  if (!n) throw std::invalid_argument("regular_polygon: needs n (the number of corners)");
  pushRegionAs(L, regularPolygonRegion(*n, r, flats), "regular_polygon");
  return 1;
}

// ---- Booleans -------------------------------------------------------------------

// The operands of union(a, b, c), union{a, b, c} or difference(a, {b, c}),
// as for solids (script/api.cpp).
std::vector<RegionPtr> regionOperands(lua_State* L, const std::string& function) {
  std::vector<RegionPtr> operands;
  auto take = [&](int index, const std::string& what) {
    if (lua_type(L, index) != LUA_TTABLE) {
      operands.push_back(regionAt(L, index, what));
      return;
    }
    index = lua_absindex(L, index);
    const lua_Unsigned count = lua_rawlen(L, index);
    for (lua_Unsigned i = 1; i <= count; ++i) {
      lua_rawgeti(L, index, static_cast<lua_Integer>(i));
      operands.push_back(regionAt(L, -1, what + "[" + std::to_string(i) + "]"));
      lua_pop(L, 1);
    }
  };
  const int n = lua_gettop(L);
  if (n == 1 && lua_type(L, 1) == LUA_TTABLE) {
    const lua_Unsigned count = lua_rawlen(L, 1);
    for (lua_Unsigned i = 1; i <= count; ++i) {
      lua_rawgeti(L, 1, static_cast<lua_Integer>(i));
      const std::string what = function + ": operand " + std::to_string(i);
      if (lua_type(L, -1) == LUA_TTABLE)
        operands.push_back(regionAt(L, -1, what));
      else
        take(-1, what);
      lua_pop(L, 1);
    }
  } else {
    for (int i = 1; i <= n; ++i) take(i, function + ": operand " + std::to_string(i));
  }
  if (operands.empty()) throw std::invalid_argument(function + ": needs at least one region");
  return operands;
}

// Is the first operand of union(...) and its kin a region? It decides
// whether the call is a boolean of regions or of solids.
bool firstOperandIsRegion(lua_State* L) {
  if (lua_gettop(L) < 1) return false;
  int depth = 0;
  lua_pushvalue(L, 1);
  // union{a, ...}, difference({a, b}), union{{a, b}}: at most two levels.
  while (lua_type(L, -1) == LUA_TTABLE && depth < 2) {
    lua_rawgeti(L, -1, 1);
    ++depth;
  }
  const bool region = toValue<RegionPtr>(L, -1) != nullptr;
  lua_pop(L, depth + 1);
  return region;
}

const char* opName(Region::Op op) {
  return op == Region::Op::Union          ? "union"
         : op == Region::Op::Intersection ? "intersection"
                                          : "difference";
}

// Calls the solids' function that a function of regions replaced (its
// closure's upvalue) with the same arguments.
int solidsFunction(lua_State* L) {
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  lua_call(L, lua_gettop(L) - 1, 1);
  return 1;
}

// union(...), difference(...), intersection(...): of regions when the
// first operand is one, else the solids' function.
template <Region::Op op>
int booleanOf(lua_State* L) {
  if (!firstOperandIsRegion(L)) return solidsFunction(L);
  pushRegionAs(L, Region::boolean(op, regionOperands(L, opName(op))), "region");
  return 1;
}

template <Region::Op op>
int booleanOperator(lua_State* L) {
  const char* symbol = op == Region::Op::Union ? "+" : op == Region::Op::Intersection ? "*" : "-";
  const std::string what = std::string("operand of '") + symbol + "'";
  const RegionPtr& a = regionAt(L, 1, what);
  const RegionPtr& b = regionAt(L, 2, what);
  pushRegionAs(L, Region::boolean(op, {a, b}), "region");
  return 1;
}

// ---- Transforms ---------------------------------------------------------------

// The region moved by a 2D map, keeping its kind (region_operations.h
// refuses a map that squashes the plane or overflows).
int pushMapped(lua_State* L, const char* method, const Affine2& map) {
  pushRegionAs(L, mappedRegion(*receiver(L, method), map, method), regionKind(L, 1));
  return 1;
}

// A 3D form of a transform: the region becomes its flat surface, which the
// surfaces' method of that name moves; when the result still lies in the
// plane z = 0 (translate(x, y, 0), rotate(0, 0, a), ...) it is a region
// again.
int placeInSpace(lua_State* L, const char* method) {
  const RegionPtr region = receiver(L, method);
  const std::string kind = regionKind(L, 1);
  pushShared<SurfacePtr>(L, regionSurface(region, kind));
  lua_replace(L, 1);
  luaL_getmetatable(L, TypeName<SurfacePtr>::value);
  lua_getfield(L, -1, "__index");
  lua_getfield(L, -1, method);
  lua_replace(L, -3);
  lua_pop(L, 1);
  lua_insert(L, 1);
  lua_call(L, lua_gettop(L) - 1, 1);
  const SurfacePtr placed = *toValue<SurfacePtr>(L, -1);
  if (std::optional<Affine2> map = planarMap(placed->frame()); map && !placed->material()) {
    lua_pop(L, 1);
    pushRegionAs(L, region->transformed(*map), kind);
  }
  return 1;
}

// How many numbers a transform was given: n arguments, or a list of n.
int givenCount(lua_State* L) {
  const int n = lua_gettop(L) - 1;
  if (n == 1 && lua_type(L, 2) == LUA_TTABLE && !hasStringKey(L, 2))
    return static_cast<int>(lua_rawlen(L, 2));
  return n;
}

// Two numbers as f(x, y) or f{x, y}.
dvec2 planeArgs(lua_State* L, const char* method, const char* noun) {
  if (lua_gettop(L) == 3)
    return {toNumber(L, 2, std::string(method) + ": x"),
            toNumber(L, 3, std::string(method) + ": y")};
  return toVec2(L, 2, std::string(method) + ": " + noun);
}

[[noreturn]] void badTransform(lua_State* L, const char* method, const char* forms) {
  const int n = lua_gettop(L) - 1;
  throw std::invalid_argument(std::string(method) + ": takes " + forms + " (got " +
                              std::to_string(n) + (n == 1 ? " argument)" : " arguments)"));
}

int translate(lua_State* L) {
  const int n = givenCount(L);
  if (n == 3) return placeInSpace(L, "translate");
  if (n != 2) badTransform(L, "translate", "x, y or {x, y} (or x, y, z to place it in space)");
  Affine2 map;
  map.offset = planeArgs(L, "translate", "offset");
  return pushMapped(L, "translate", map);
}

// rotate(a): a degrees counterclockwise about the origin; the 3D forms
// rotate(x, y, z) and rotate{angle=, axis=} place the region in space.
int rotate(lua_State* L) {
  const int n = lua_gettop(L) - 1;
  if (n == 1 && lua_type(L, 2) == LUA_TNUMBER) {
    return pushMapped(L, "rotate", turnMap(toNumber(L, 2, "rotate: angle")));
  }
  if (n == 3 || (n == 1 && lua_type(L, 2) == LUA_TTABLE)) return placeInSpace(L, "rotate");
  badTransform(L, "rotate", "an angle in degrees (or x, y, z to place it in space)");
}

int scale(lua_State* L) {
  const int n = givenCount(L);
  if (n == 3) return placeInSpace(L, "scale");
  dvec2 factors;
  if (lua_gettop(L) == 2 && lua_type(L, 2) == LUA_TNUMBER)
    factors = dvec2(toNumber(L, 2, "scale: factor"));
  else if (n == 2)
    factors = planeArgs(L, "scale", "factors");
  else
    badTransform(L, "scale", "s, sx, sy or {sx, sy} (or x, y, z to place it in space)");
  return pushMapped(L, "scale", scaleMap(factors, "scale"));
}

// resize(x, y) or resize{x, y, auto=}: OpenSCAD's resize, scaled about
// the origin so that the region's own box (tightBounds) gets these sizes.
int resize(lua_State* L) {
  const RegionPtr& region = receiver(L, "resize");
  const ResizeArgs args = resizeArgs(L, 2);
  return pushMapped(
      L, "resize",
      regionResizeMap(*region, dvec2(args.size), {args.autoAxes[0], args.autoAxes[1]}));
}

// mirror(x, y): the reflection in the line through the origin with that
// normal, as OpenSCAD's mirror([x, y]) of a 2D shape.
int mirror(lua_State* L) {
  const int n = givenCount(L);
  if (n == 3) return placeInSpace(L, "mirror");
  if (n != 2) badTransform(L, "mirror", "x, y or {x, y} (or x, y, z to place it in space)");
  return pushMapped(L, "mirror", mirrorMap(planeArgs(L, "mirror", "normal"), "mirror"));
}

// transform{{a, b, tx}, {c, d, ty}} (a third row {0, 0, 1} may follow): the
// 2D affine map (x, y) ↦ (a x + b y + tx, c x + d y + ty). Rows of four
// numbers are a 3D transform and place the region in space.
int transform(lua_State* L) {
  checkArgumentCount(L, "transform", 1, 2);
  const lua_Unsigned rows = lua_type(L, 2) == LUA_TTABLE ? lua_rawlen(L, 2) : 0;
  lua_Unsigned columns = 0;
  if (rows > 0) {
    lua_rawgeti(L, 2, 1);
    columns = lua_type(L, -1) == LUA_TTABLE ? lua_rawlen(L, -1) : 0;
    lua_pop(L, 1);
  }
  if (columns == 4) return placeInSpace(L, "transform");
  if (columns != 3 || (rows != 2 && rows != 3))
    throw std::invalid_argument(
        "transform: a region takes 2 or 3 rows of 3 numbers (or rows of 4 to place it in space)");
  double m[3][3];
  for (lua_Unsigned r = 0; r < rows; ++r) {
    lua_rawgeti(L, 2, static_cast<lua_Integer>(r + 1));
    if (lua_type(L, -1) != LUA_TTABLE || lua_rawlen(L, -1) != 3)
      throw std::invalid_argument("transform: row " + std::to_string(r + 1) +
                                  " must have 3 numbers");
    for (int c = 0; c < 3; ++c) {
      lua_rawgeti(L, -1, c + 1);
      m[r][c] = toNumber(L, -1,
                         "transform[" + std::to_string(r + 1) + "][" + std::to_string(c + 1) + "]");
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
  }
  if (rows == 3 && (m[2][0] != 0.0 || m[2][1] != 0.0 || m[2][2] != 1.0))
    throw std::invalid_argument("transform: the third row must be {0, 0, 1}");
  Affine2 map;
  map.linear = dmat2(m[0][0], m[1][0], m[0][1], m[1][1]);  // column by column
  map.offset = dvec2(m[0][2], m[1][2]);
  return pushMapped(L, "transform", map);
}

// r:material{...}: the region shown in the scene with that material, a
// flat surface from then on.
int material(lua_State* L) {
  const RegionPtr& region = receiver(L, "material");
  checkArgumentCount(L, "material", 1, 2);
  MaterialPtr m = materialArg(L, 2);
  pushShared<SurfacePtr>(L, regionSurface(region, regionKind(L, 1))->withMaterial(m));
  return 1;
}

// ---- Offsets, hulls, measures -------------------------------------------------

// r:offset{r=} (rounded) or r:offset{delta=, chamfer=}, as OpenSCAD's
// offset().
int offsetMethod(lua_State* L) {
  const RegionPtr& region = receiver(L, "offset");
  checkArgumentCount(L, "offset", 1, 2);
  LuaArgs args(L, 2, "offset");
  std::optional<double> r = args.number("r"), delta = args.number("delta");
  std::optional<bool> chamfer = args.boolean("chamfer");
  args.finish();
  pushRegionAs(L, offsetRegion(*region, r, delta, chamfer), "region");
  return 1;
}

// hull(a, b, ...) or hull{a, b, ...}: the convex hull of regions when the
// first operand is one, else the solids' hull (the closure's upvalue).
int hullOf(lua_State* L) {
  if (!firstOperandIsRegion(L)) return solidsFunction(L);
  pushRegionAs(L, hullOfRegions(regionOperands(L, "hull")), "region");
  return 1;
}

// minkowski(a, b, ...) of regions, when the first operand is one, else the
// solids' sum, pair by pair from the first (region_evaluation.h: a region
// plus a circle is its rounded offset, OpenSCAD's minkowski() {square();
// circle();}; two convex regions, one a polygon, the hull of copies).
int minkowskiOf(lua_State* L) {
  if (!firstOperandIsRegion(L)) return solidsFunction(L);
  pushRegionAs(L, minkowskiOfRegions(regionOperands(L, "minkowski")), "region");
  return 1;
}

int areaMethod(lua_State* L) {
  const RegionPtr& region = receiver(L, "area");
  checkArgumentCount(L, "area", 0, 2);
  lua_pushnumber(L, regionArea(*region));
  return 1;
}

void pushVec2(lua_State* L, const dvec2& v) {
  lua_createtable(L, 2, 0);
  lua_pushnumber(L, v.x);
  lua_rawseti(L, -2, 1);
  lua_pushnumber(L, v.y);
  lua_rawseti(L, -2, 2);
}

// r:bounds(): the low and the high corner {x, y} of a box about the
// region (for booleans, the box their operands' boxes give).
int bounds(lua_State* L) {
  const RegionPtr& region = receiver(L, "bounds");
  checkArgumentCount(L, "bounds", 0, 2);
  const ProfileBounds& b = region->bounds();
  if (b.empty()) throw std::invalid_argument("bounds: the region is empty");
  pushVec2(L, b.lo);
  pushVec2(L, b.hi);
  return 2;
}

// r:contains(x, y) or r:contains{x, y}; a point on the outline may go
// either way.
int contains(lua_State* L) {
  const RegionPtr& region = receiver(L, "contains");
  if (givenCount(L) != 2 || lua_gettop(L) > 3) badTransform(L, "contains", "x, y or {x, y}");
  lua_pushboolean(L, region->contains(planeArgs(L, "contains", "point")));
  return 1;
}

int regionToString(lua_State* L) {
  const RegionPtr& region = regionAt(L, 1, "tostring");
  std::size_t leaves = 0, edges = 0;
  region->forEachLeaf([&](const Profile& p) {
    ++leaves;
    for (const ProfileLoop& loop : p.loops) edges += loop.edges.size();
  });
  std::ostringstream s;
  s << "region(" << regionKind(L, 1) << ", " << leaves
    << (leaves == 1 ? " profile, " : " profiles, ") << edges << (edges == 1 ? " edge)" : " edges)");
  lua_pushstring(L, s.str().c_str());
  return 1;
}

// Registers f as the global name, with the global it replaces (the
// solids' function) as its upvalue.
void registerOverSolids(lua_State* L, const char* name, lua_CFunction f) {
  lua_getglobal(L, name);
  lua_pushcclosure(L, f, 1);
  lua_setglobal(L, name);
}

}  // namespace

void pushRegion(lua_State* L, RegionPtr region, const std::string& kind) {
  pushRegionAs(L, std::move(region), kind);
}

RegionPtr regionArg(lua_State* L, int index, const std::string& what) {
  return regionAt(L, index, what);
}

void registerRegionApi(lua_State* L) {
  newMetatable<RegionPtr>(L);
  static const luaL_Reg methods[] = {
      {"translate", guarded<translate>}, {"rotate", guarded<rotate>},
      {"scale", guarded<scale>},         {"resize", guarded<resize>},
      {"mirror", guarded<mirror>},       {"transform", guarded<transform>},
      {"material", guarded<material>},   {"offset", guarded<offsetMethod>},
      {"area", guarded<areaMethod>},     {"bounds", guarded<bounds>},
      {"contains", guarded<contains>},   {nullptr, nullptr}};
  luaL_newlib(L, methods);
  lua_setfield(L, -2, "__index");
  static const luaL_Reg operators[] = {
      {"__add", guarded<booleanOperator<Region::Op::Union>>},
      {"__sub", guarded<booleanOperator<Region::Op::Difference>>},
      {"__mul", guarded<booleanOperator<Region::Op::Intersection>>},
      {"__tostring", guarded<regionToString>},
      {nullptr, nullptr}};
  luaL_setfuncs(L, operators, 0);
  lua_pop(L, 1);

  static const luaL_Reg globals[] = {
      {"square", guarded<rectangle<true>>}, {"rectangle", guarded<rectangle<false>>},
      {"circle", guarded<circle>},          {"ellipse", guarded<ellipse>},
      {"polygon", guarded<polygon>},        {"regular_polygon", guarded<regularPolygon>},
  };
  for (const luaL_Reg& g : globals) lua_register(L, g.name, g.func);
  registerOverSolids(L, "union", guarded<booleanOf<Region::Op::Union>>);
  registerOverSolids(L, "difference", guarded<booleanOf<Region::Op::Difference>>);
  registerOverSolids(L, "intersection", guarded<booleanOf<Region::Op::Intersection>>);
  registerOverSolids(L, "hull", guarded<hullOf>);
  registerOverSolids(L, "minkowski", guarded<minkowskiOf>);
}

}  // namespace csgray::detail
