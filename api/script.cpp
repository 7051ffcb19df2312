// runScript(): part scripts run as the csgray command runs them
// (script/script.h), with images, mesh files and check() at hand.
#include "csgray/script.h"

#include "api/access.h"
#include "api/errors.h"
#include "check/part_check.h"
#include "export/solid_projection.h"
#include "io/image_file.h"
#include "meshio/mesh_import.h"
#include "script/script.h"

namespace csgray {

namespace {

detail::ScriptOptions optionsOf(const ScriptOptions& o) {
  detail::ScriptOptions made;
  made.defines = o.defines;
  made.allowedFolders = o.allowedFolders;
  made.limits.memoryBytes = o.memoryBytes;
  made.limits.instructions = o.instructions;
  made.loadImage = detail::readTextureImage;
  made.loadMesh = detail::importMesh;
  made.checkSolid = detail::checkPart;
  made.projectSolid = detail::solidProjection;
  made.warn = o.onWarning;
  made.print = o.onPrint;
  return made;
}

}  // namespace

Scene runScript(const std::string& path, const ScriptOptions& options) {
  return detail::guarded(ErrorCode::ScriptError, [&] {
    return detail::Access::scene(detail::runScriptFile(path, optionsOf(options)));
  });
}

Scene runScriptText(const std::string& source, const std::string& chunkName,
                    const ScriptOptions& options) {
  return detail::guarded(ErrorCode::ScriptError, [&] {
    return detail::Access::scene(detail::runScript(source, chunkName, optionsOf(options)));
  });
}

}  // namespace csgray
