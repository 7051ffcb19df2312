// OpenSCAD's .csg files in csgray: import_csg{file=} in a script, and a
// .csg file opened as the part itself (runScriptFile). The format and its
// nodes are openscad/; this gives them the script's rules for files.
#include <filesystem>
#include <stdexcept>

#include "engine/boolean.h"
#include "openscad/csg_import.h"
#include "scene/region_surface.h"
#include "script/api.h"
#include "script/lua_args.h"
#include "script/lua_values.h"
#include "script/script_path.h"

namespace csgray::detail {

namespace {

// The import's options for the .csg file at path: files it names are
// relative to its folder and must be ones the script may read.
CsgImportOptions csgOptions(const std::string& path, const ScriptOptions& options) {
  CsgImportOptions csg;
  csg.facets = options.openscadFacets ? CsgFacets::OpenScad : CsgFacets::Exact;
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  const std::string folder = parent.empty() ? std::string(".") : parent.string();
  csg.resolveFile = [folder, &options](const std::string& name) {
    return allowedFile("import", name, folder, options);
  };
  if (options.loadMesh)
    csg.loadMesh = [&options](const std::string& file) {
      std::string report;
      return options.loadMesh(file, false, report);
    };
  csg.loadImage = options.loadImage;
  csg.project = options.projectSolid;
  csg.warn = options.warn;
  return csg;
}

// import_csg{file="part.csg"}: the file's solids as one solid, or its 2D
// shapes as one region.
int importCsgFn(lua_State* L) {
  checkArgumentCount(L, "import_csg", 1);
  LuaArgs args(L, 1, "import_csg");
  std::optional<std::string> file = args.string("file");
  args.finish();
  if (!file) throw std::invalid_argument("import_csg: needs file=\"part.csg\"");
  const ScriptOptions& options = scriptOptionsOf(L);
  const std::string path = scriptFile(L, "import_csg", *file);
  CsgModel model;
  try {
    model = importCsgFile(path, csgOptions(path, options));
  } catch (const CsgError& e) {
    // The file's own name as the script gave it, with the line in it.
    std::string message = e.what();
    if (message.starts_with(path)) message = *file + message.substr(path.size());
    throw std::invalid_argument("import_csg: " + message);
  }
  if (!model.solids.empty() && !model.regions.empty())
    throw std::invalid_argument("import_csg: " + *file +
                                " holds both 2D and 3D shapes; a script takes one kind");
  if (!model.solids.empty()) {
    pushSolid(L, model.solids.size() == 1 ? model.solids.front() : unionOf(model.solids));
    return 1;
  }
  if (model.regions.empty()) throw std::invalid_argument("import_csg: " + *file + " makes nothing");
  pushRegion(L, model.regions.size() == 1 ? model.regions.front()
                                          : Region::boolean(Region::Op::Union, model.regions));
  return 1;
}

}  // namespace

void registerCsgApi(lua_State* L) { lua_register(L, "import_csg", guarded<importCsgFn>); }

Scene csgFileScene(const std::string& path, const ScriptOptions& options) {
  CsgModel model;
  try {
    model = importCsgFile(path, csgOptions(path, options));
  } catch (const CsgError& e) {
    throw ScriptError(e.what());
  }
  Scene scene;
  scene.cadLook = true;
  scene.objects = model.solids;
  for (const RegionPtr& region : model.regions)
    scene.surfaces.push_back(regionSurface(region, "region"));
  scene.resolveModifiers();
  if (scene.objects.empty() && scene.surfaces.empty() && scene.ghosts.empty())
    throw ScriptError(path + ": the file makes nothing to show");
  return scene;
}

}  // namespace csgray::detail
