// The script API: primitives, booleans, transforms, materials and scene
// description as Lua functions and methods. Reference: docs/script.md.
// The checks of what a script gives are those of scene/ (shapes.h,
// material.h, ...), which the library's API makes too; the functions here
// read Lua values into them.
#pragma once

#include <lua.hpp>

#include "profile/region.h"
#include "scene/scene.h"
#include "script/script.h"

namespace csgray::detail {

// Registers the API's globals and metatables in a sandboxed state. The
// options must outlive the script's run.
void registerScriptApi(lua_State* L, const ScriptOptions& options);
// The options registerScriptApi was given.
const ScriptOptions& scriptOptionsOf(lua_State* L);

// The parts of the API, each in its own file, each registering its
// globals and metatables: textures (api_texture.cpp), open surfaces, which
// take the given transform methods (api_surface.cpp), lights
// (api_light.cpp), the camera and the scene (api_scene.cpp); the named
// quadrics of the classic table (docs/theory.md) and clip (api_quadrics.cpp), convex
// polyhedra and the Platonic solids (api_convex.cpp), polyhedra from points
// and faces and mesh files (api_mesh.cpp), and check(solid, options)
// (api_check.cpp): ScriptOptions::checkSolid's report as a table.
void registerTextureApi(lua_State* L);
void registerSurfaceApi(lua_State* L, const luaL_Reg* transformMethods);
void registerLightApi(lua_State* L);
void registerSceneApi(lua_State* L);
void registerQuadricApi(lua_State* L);
void registerConvexApi(lua_State* L);
void registerMeshApi(lua_State* L);
void registerCheckApi(lua_State* L);

// 2D regions (api_region.cpp): the shapes of the plane, their booleans,
// transforms, offsets and hulls, as values of the metatable
// "csgray.region"; and the sweeps that turn a region into a solid
// (api_sweep.cpp): linear_extrude and rotate_extrude.
void registerRegionApi(lua_State* L);
// OpenSCAD's .csg files (api_csg.cpp): import_csg{file=} in a script, and
// the scene of a .csg file opened as the part (runScriptFile). Throws
// ScriptError "file:line: what".
void registerCsgApi(lua_State* L);
Scene csgFileScene(const std::string& path, const ScriptOptions& options);
void registerSweepApi(lua_State* L);
// import_dxf{file=}, import_svg{file=} and height_map{file=}
// (api_import.cpp): a DXF or SVG drawing as a region, OpenSCAD's surface()
// as a solid.
void registerImportApi(lua_State* L);
// projection(solid, {cut=}) (api_projection.cpp): a solid's section by
// z = 0 or its shadow on it, as a region (ScriptOptions::projectSolid).
void registerProjectionApi(lua_State* L);
// text{...} (api_text.cpp): a string's outlines as a region.
void registerTextApi(lua_State* L);
// kind: what the region was made as, for messages ("region", "text").
void pushRegion(lua_State* L, RegionPtr region, const std::string& kind = "region");
// The region at index, or a Lua error that names the place it was given
// (`what`: "linear_extrude: argument 1").
RegionPtr regionArg(lua_State* L, int index, const std::string& what);

// The solids a boolean-like function is given: f(a, b, c) or f{a, b, c},
// an operand also a list of solids, as in difference(a, holes) (the form
// that boolean.cpp's message about deep trees recommends). Lua errors name
// the function and the operand.
std::vector<SolidPtr> solidOperands(lua_State* L, const std::string& function);

// Hulls and Minkowski sums of solids, rounded boxes and cylinders
// (api_hull.cpp). Before registerRegionApi, whose hull() hands solids to
// this one.
void registerHullApi(lua_State* L);

// The material{...} table at index (api_material.cpp), checked.
MaterialPtr materialArg(lua_State* L, int index);
// s:material{...} on a solid.
int solidMaterial(lua_State* L);

// Turns the script's return value at index into a scene. Throws
// std::invalid_argument if it is not a solid, a surface or a scene.
Scene sceneFromValue(lua_State* L, int index);

}  // namespace csgray::detail
