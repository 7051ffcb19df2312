// polyhedron{points=..., faces=...}: OpenSCAD's polyhedron, a closed
// triangle mesh from points and faces (docs/script.md, Polyhedron),
// mesh{file=...}: the same solid from a mesh file, and
// mesh_surface{points=..., faces=...}: an open mesh as a surface.
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "primitives/mesh_solid.h"
#include "scene/shapes.h"
#include "scene/surface_mesh.h"
#include "script/api.h"
#include "script/lua_args.h"
#include "script/lua_values.h"
#include "script/sandbox.h"
#include "script/script_path.h"

namespace csgray::detail {

namespace {

[[noreturn]] void refuse(const char* function, const std::string& message) {
  throw std::invalid_argument(std::string(function) + ": " + message);
}

// The length of a list, or an error naming what it should have been.
lua_Unsigned listLength(lua_State* L, int index, const char* function, const std::string& what,
                        const std::string& expected) {
  if (lua_type(L, index) != LUA_TTABLE)
    refuse(function, what + " must be " + expected + ", got " + shownType(L, index));
  return lua_rawlen(L, index);
}

// points={{x, y, z}, ...}; point i of the script's list is point i − 1 of
// the faces, as in OpenSCAD. The lists are read as they come, and charged
// as they grow: a list's length may be far from what it holds (#t of a
// table with keys 1, 2, 4, 8, ... 2^40 is 2^40), and a list may name one
// point or face many times.
// (`what` names them in messages: "point", or "normal" for a list of
// normals.)
std::vector<dvec3> readPoints(lua_State* L, int index, PendingCharge& pending, const char* function,
                              const std::string& what = "point") {
  index = lua_absindex(L, index);
  lua_Unsigned n =
      listLength(L, index, function, what + "s", "a list of " + what + "s {{x, y, z}, ...}");
  std::vector<dvec3> points;
  for (lua_Unsigned i = 0; i < n; ++i) {
    std::string item = what + " " + std::to_string(i);
    lua_rawgeti(L, index, lua_Integer(i + 1));
    if (listLength(L, -1, function, item, "a list of three numbers {x, y, z}") != 3)
      refuse(function, item + " must be a list of three numbers {x, y, z}");
    dvec3 p;
    for (int k = 0; k < 3; ++k) {
      lua_rawgeti(L, -1, k + 1);
      // toNumber refuses NaN and infinities, naming the coordinate.
      p[k] = toNumber(L, -1, std::string(function) + ": " + item + ": " + "xyz"[k]);
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
    pending.add(sizeof(dvec3));
    points.push_back(p);
  }
  return points;
}

// faces={{i, j, k, ...}, ...} of point indices from 0.
std::vector<std::vector<std::int64_t>> readFaces(lua_State* L, int index, PendingCharge& pending,
                                                 const char* function) {
  index = lua_absindex(L, index);
  lua_Unsigned n = listLength(L, index, function, "faces",
                              "a list of faces {{i, j, k}, ...} (point indices from 0)");
  std::vector<std::vector<std::int64_t>> faces;
  for (lua_Unsigned f = 0; f < n; ++f) {
    std::string what = "face " + std::to_string(f);
    lua_rawgeti(L, index, lua_Integer(f + 1));
    lua_Unsigned count =
        listLength(L, -1, function, what, "a list of point indices {i, j, k, ...}");
    faces.emplace_back();
    for (lua_Unsigned k = 0; k < count; ++k) {
      lua_rawgeti(L, -1, lua_Integer(k + 1));
      int isInteger = 0;
      lua_Integer v = lua_tointegerx(L, -1, &isInteger);
      if (lua_type(L, -1) != LUA_TNUMBER || !isInteger) {
        std::string value = lua_type(L, -1) == LUA_TNUMBER     ? std::string(lua_tostring(L, -1))
                            : lua_type(L, -1) == LUA_TUSERDATA ? shownType(L, -1)
                                                               : "a " + shownType(L, -1);
        refuse(function, what + ": " + value + " is not a point index (an integer from 0)");
      }
      lua_pop(L, 1);
      faces[f].push_back(std::int64_t(v));
    }
    lua_pop(L, 1);
    pending.add(sizeof(faces[f]) + faces[f].size() * sizeof(std::int64_t));
  }
  return faces;
}

// The points={...} and faces={...} of polyhedron{} and mesh_surface{};
// facesHow tells, when faces are missing, how they are listed.
struct PointsAndFaces {
  std::vector<dvec3> points;
  std::vector<std::vector<std::int64_t>> faces;
};
PointsAndFaces readPointsAndFaces(lua_State* L, LuaArgs& args, PendingCharge& pending,
                                  const char* function, const std::string& facesHow) {
  PointsAndFaces mesh;
  if (!args.push("points")) refuse(function, "needs points={{x, y, z}, ...}");
  mesh.points = readPoints(L, -1, pending, function);
  lua_pop(L, 1);
  if (!args.push("faces")) refuse(function, "needs faces={{i, j, k}, ...} (" + facesHow + ")");
  mesh.faces = readFaces(L, -1, pending, function);
  lua_pop(L, 1);
  return mesh;
}

int polyhedron(lua_State* L) {
  const char* name = "polyhedron";
  checkArgumentCount(L, name, 1);
  LuaArgs args(L, 1, name);
  PendingCharge pending(L);
  const auto [points, faces] = readPointsAndFaces(
      L, args, pending, name, "point indices from 0, clockwise seen from outside");
  // OpenSCAD's hint for its preview renderer; rays need none.
  args.number("convexity");
  args.finish();
  auto mesh = Primitive::create<MeshSolid>(points, faces);
  // The mesh is charged once for the rest of the run, not with the value
  // returned here: transformed copies share it and may outlive that value,
  // so refunding it when the value is collected would let a loop keep many
  // meshes uncharged.
  Sandbox::of(L).charge(L, mesh->memoryBytes());
  pushSolid(L, mesh);
  return 1;
}

// mesh{file="part.stl", repair=false}: the file is read by the program
// (ScriptOptions::loadMesh), which refuses a mesh that is not a solid.
int meshFn(lua_State* L) {
  checkArgumentCount(L, "mesh", 1);
  LuaArgs args(L, 1, "mesh");
  std::optional<std::string> file = args.string("file");
  const bool repair = args.boolean("repair").value_or(false);
  args.finish();
  if (!file) throw std::invalid_argument("mesh: needs file=\"part.stl\" (STL, OBJ, OFF or PLY)");
  const ScriptOptions& options = scriptOptionsOf(L);
  if (!options.loadMesh) throw std::invalid_argument("mesh: this program cannot read mesh files");
  const std::string path = scriptFile(L, "mesh", *file);
  std::string report;
  std::shared_ptr<MeshSolid> mesh;
  try {
    // The loader's messages begin with the file's name, and so do
    // meshShape's.
    mesh = meshShape(options.loadMesh(path, repair, report), *file);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("mesh: " + std::string(e.what()));
  }
  if (!report.empty() && options.warn) {
    // "part.lua:3: ", as an error would begin.
    luaL_where(L, 1);
    std::string where = lua_tostring(L, -1);
    lua_pop(L, 1);
    options.warn(where + "mesh: " + *file + ": " + report);
  }
  Sandbox::of(L).charge(L, mesh->memoryBytes());
  pushSolid(L, mesh);
  return 1;
}

// mesh_surface{points=..., faces=..., normals=..., smooth=true}: an open
// surface of triangles (scene/surface_mesh.h).
int meshSurface(lua_State* L) {
  const char* name = "mesh_surface";
  checkArgumentCount(L, name, 1);
  LuaArgs args(L, 1, name);
  PendingCharge pending(L);
  auto [points, faces] = readPointsAndFaces(L, args, pending, name, "point indices from 0");
  std::vector<dvec3> normals;
  if (args.push("normals")) {
    normals = readPoints(L, -1, pending, name, "normal");
    lua_pop(L, 1);
  }
  const bool smooth = args.boolean("smooth").value_or(true);
  args.finish();
  SurfacePtr surface = meshSurfaceOf(std::move(points), faces, std::move(normals), smooth);
  // Charged for the rest of the run, as polyhedron's mesh is.
  Sandbox::of(L).charge(L, surface->mesh()->memoryBytes());
  pushShared<SurfacePtr>(L, std::move(surface));
  return 1;
}

}  // namespace

void registerMeshApi(lua_State* L) {
  lua_register(L, "mesh_surface", guarded<meshSurface>);
  lua_register(L, "polyhedron", guarded<polyhedron>);
  lua_register(L, "mesh", guarded<meshFn>);
}

}  // namespace csgray::detail
