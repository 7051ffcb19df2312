// The module of cli/mesh_plugin.h: the export and check commands, mesh
// import and the check.
#include "cli/check_command.h"
#include "cli/export_command.h"
#include "cli/mesh_plugin.h"
#include "meshfile/mesh_import.h"
#include "check/part_check.h"

extern "C" __attribute__((visibility("default"))) const csgray::detail::MeshPlugin* csgray_mesh_plugin() {
  static const csgray::detail::MeshPlugin plugin{csgray::detail::checkExportOutput, csgray::detail::exportScene,
                                         csgray::detail::checkScene, csgray::detail::importMesh, csgray::detail::checkPart};
  return &plugin;
}
