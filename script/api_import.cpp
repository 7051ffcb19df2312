// Shapes read from files other than meshes: import_dxf{file=} and
// import_svg{file=} (a DXF or SVG drawing as a region, OpenSCAD's import()
// of a .dxf or .svg) and
// height_map{file=} (OpenSCAD's surface(): a text file of heights or a PNG
// image as a solid). Files follow the script's rule (script_path.h).
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

#include "io/height_map_file.h"
#include "io/input_file.h"
#include "profile/dxf_reader.h"
#include "profile/svg_reader.h"
#include "script/api.h"
#include "script/lua_args.h"
#include "script/lua_values.h"
#include "script/sandbox.h"
#include "script/script_path.h"

namespace csgray::detail {

namespace {

constexpr std::size_t kMaxDrawingBytes = std::size_t{64} << 20;

// The drawing file= names, read by `read` (from its text and its name), its
// errors prefixed with the function's name, pushed as a region whose edges
// are charged to the script's memory.
int pushDrawing(lua_State* L, const std::string& function, const std::optional<std::string>& file,
                const std::function<RegionPtr(const std::string&, const std::string&)>& read) {
  const std::string extension = function.substr(function.size() - 3);
  if (!file) throw std::invalid_argument(function + ": needs file=\"part." + extension + "\"");
  const std::string path = scriptFile(L, function, *file);
  RegionPtr region;
  try {
    region = read(readInputFile(path, *file, kMaxDrawingBytes), *file);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(function + ": " + e.what());
  }
  region->forEachLeaf([&](const Profile& p) {
    Sandbox::of(L).charge(L, p.loops.size() * sizeof(ProfileLoop));
    for (const ProfileLoop& loop : p.loops)
      Sandbox::of(L).charge(L, loop.edges.size() * sizeof(ProfileEdge));
  });
  pushRegion(L, region);
  return 1;
}

// import_dxf{file="plate.dxf", layer="", origin={0, 0}, scale=1}.
int importDxf(lua_State* L) {
  checkArgumentCount(L, "import_dxf", 1);
  LuaArgs args(L, 1, "import_dxf");
  std::optional<std::string> file = args.string("file");
  DxfOptions dxf;
  dxf.layer = args.string("layer").value_or("");
  if (args.push("origin")) {
    dxf.origin = toVec2(L, -1, "import_dxf: origin");
    lua_pop(L, 1);
  }
  dxf.scale = args.number("scale").value_or(1.0);
  args.finish();
  return pushDrawing(L, "import_dxf", file, [&](const std::string& text, const std::string& name) {
    return readDxf(text, name, dxf);
  });
}

// import_svg{file="badge.svg", id="", dpi=72, center=false}.
int importSvg(lua_State* L) {
  checkArgumentCount(L, "import_svg", 1);
  LuaArgs args(L, 1, "import_svg");
  std::optional<std::string> file = args.string("file");
  SvgOptions svg;
  svg.id = args.string("id").value_or("");
  svg.dpi = args.number("dpi").value_or(72.0);
  svg.center = args.boolean("center").value_or(false);
  args.finish();
  return pushDrawing(L, "import_svg", file, [&](const std::string& text, const std::string& name) {
    return readSvg(text, name, svg);
  });
}

// height_map{file="terrain.dat" or "terrain.png", center=false, invert=false}.
constexpr std::size_t kBuildBytesPerTriangle = 800;

int heightMap(lua_State* L) {
  checkArgumentCount(L, "height_map", 1);
  LuaArgs args(L, 1, "height_map");
  std::optional<std::string> file = args.string("file");
  const bool center = args.boolean("center").value_or(false);
  const bool invert = args.boolean("invert").value_or(false);
  args.finish();
  if (!file)
    throw std::invalid_argument("height_map: needs file=\"terrain.dat\" (numbers) or a PNG image");
  const std::string path = scriptFile(L, "height_map", *file);
  std::shared_ptr<MeshSolid> solid;
  try {
    const HeightMap map = readHeightMap(path, *file, invert, scriptImageLoader(L, *file));
    // Charged at what building the mesh takes before it is built (about
    // 800 bytes a triangle at the peak, measured on maps of 256 and 512
    // squared), so that a map past the memory limit stops at once rather
    // than after taking the memory; the solid's own size is charged below.
    if (map.rows >= 2 && map.columns >= 2) {
      const std::size_t triangles =
          4 * (map.rows - 1) * (map.columns - 1) + 4 * (map.rows + map.columns);
      // A map that could not be built even alone says so, with its file.
      const std::size_t limit = Sandbox::of(L).memoryLimit();
      if (triangles > limit / kBuildBytesPerTriangle)
        throw std::invalid_argument(*file + ": a map of " + std::to_string(map.columns) + " x " +
                                    std::to_string(map.rows) + " heights takes about " +
                                    std::to_string(triangles * kBuildBytesPerTriangle >> 20) +
                                    " MiB to build, more than the script's memory limit of " +
                                    std::to_string(limit >> 20) + " MiB");
      Sandbox::of(L).charge(L, triangles * kBuildBytesPerTriangle);
      Sandbox::of(L).release(triangles * kBuildBytesPerTriangle);
    }
    try {
      solid = heightMapSolid(map, center);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(*file + ": " + e.what());
    }
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("height_map: " + std::string(e.what()));
  }
  Sandbox::of(L).charge(L, solid->memoryBytes());
  pushSolid(L, solid);
  return 1;
}

}  // namespace

void registerImportApi(lua_State* L) {
  lua_register(L, "import_dxf", guarded<importDxf>);
  lua_register(L, "import_svg", guarded<importSvg>);
  lua_register(L, "height_map", guarded<heightMap>);
}

}  // namespace csgray::detail
