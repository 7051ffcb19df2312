// The module of cli/mesh_plugin.h: the export and check commands, mesh
// import and the check.
#include "cli/check_command.h"
#include "cli/export_command.h"
#include "cli/mesh_plugin.h"
#include "meshfile/mesh_import.h"
#include "check/part_check.h"

extern "C" __attribute__((visibility("default"))) const csgray::MeshPlugin* csgray_mesh_plugin() {
  static const csgray::MeshPlugin plugin{csgray::checkExportOutput, csgray::exportScene,
                                         csgray::checkScene, csgray::importMesh, csgray::checkPart};
  return &plugin;
}
