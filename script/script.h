// Runs a part script: sandboxed Lua 5.4 that returns a solid or a scene.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "check/check_report.h"
#include "profile/profile.h"
#include "scene/scene.h"
#include "script/parameters.h"
#include "tessellation/triangle_mesh.h"

namespace csgray::detail {

// Resource caps that end a runaway script with a clear error.
struct ScriptLimits {
  std::size_t memoryBytes = std::size_t{1} << 30;  // Lua heap plus solids built
  std::uint64_t instructions = 1'000'000'000;      // Lua VM instructions, a few seconds
};

struct ScriptOptions {
  // Globals set before the script runs (-D name=value): numbers, true/false,
  // or strings (quotes optional).
  std::vector<std::pair<std::string, std::string>> defines;
  ScriptLimits limits;
  // The folder that file names in the script (image textures, meshes) are
  // relative to, and may not leave; runScriptFile sets it to the script's
  // folder.
  std::string folder = ".";
  // Further folders (--allow-path) that file names may lead into, by a
  // relative path from `folder` or an absolute one.
  std::vector<std::string> allowedFolders;
  // Reads an image file for image_texture{}; without it, image textures
  // are an error. (The modeler does not read images itself: io/ does.)
  std::function<TextureImage(const std::string& path)> loadImage;
  // Reads a mesh file for mesh{}, repairing it when asked and saying what
  // it did in repairReport; throws std::invalid_argument for a bad file or
  // a mesh that is not a solid. Without it, mesh{} is an error. (importMesh
  // of meshio/mesh_import.h fits.)
  std::function<TriangleMesh(const std::string& path, bool repair, std::string& repairReport)>
      loadMesh;
  // Checks a solid's export against it for check(solid, options)
  // (checkPart of check/part_check.h fits); without it, check() is an error.
  std::function<CheckReport(const Solid& solid, const CheckOptions& options)> checkSolid;
  // The section by z = 0 (cut) or the shadow on it of a solid, for
  // projection() in scripts and in .csg files (solidProjection of
  // export/solid_projection.h fits); without it, projection() is an error.
  std::function<Profile(const SolidPtr& solid, bool cut)> projectSolid;
  // OpenSCAD's .csg files (a path ending in .csg, import_csg{}): make
  // circles, spheres and cylinders the polygons OpenSCAD makes from $fn,
  // $fa and $fs (--facets openscad) rather than exact.
  bool openscadFacets = false;
  // Told the path of each file the script names to read (meshes, images,
  // drawings, height maps, .csg files and the files they name), once its
  // name is allowed: what a watcher watches with the script.
  std::function<void(const std::string& path)> fileRead;
  // Receives what the script should be told but does not stop it, such as
  // what mesh{repair=true} repaired; without it these are dropped.
  std::function<void(const std::string& message)> warn;
  // Receives each line the script prints; without it they go to standard
  // error.
  std::function<void(const std::string& line)> print;
};

// A script that failed: the message names the file and line where known.
class ScriptError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A global set before the script (ScriptOptions::defines) that is refused:
// the fault of the command line (-D), not of the script.
class DefineError : public ScriptError {
 public:
  using ScriptError::ScriptError;
};

// Runs the script file at path; a path ending in .csg (any case) is an
// OpenSCAD .csg file, imported (openscad/csg_import.h). Throws ScriptError.
Scene runScriptFile(const std::string& path, const ScriptOptions& options = {});
// Runs source text; chunkName is used in messages in place of a file name.
Scene runScript(const std::string& source, const std::string& chunkName,
                const ScriptOptions& options = {});
// The annotated parameters of the script file at path (script/parameters.h),
// for a customizer. Throws ScriptError.
std::vector<Parameter> scriptFileParameters(const std::string& path);

}  // namespace csgray::detail
