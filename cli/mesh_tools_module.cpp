// The entry of the mesh tools module (cli/mesh_tools.h): the export and
// check commands' work, mesh import and the check.
#include "check/part_check.h"
#include "cli/check_scene.h"
#include "cli/export_scene.h"
#include "cli/mesh_tools.h"
#include "export/solid_projection.h"
#include "meshio/mesh_import.h"
#include "meshio/part_file_bytes.h"

extern "C" __attribute__((visibility("default"))) const csgray::detail::MeshTools*
csgray_mesh_tools() {
  using namespace csgray::detail;
  static const MeshTools tools{checkExportOutput, exportScene,     checkScene,    importMesh,
                               checkPart,         solidProjection, partFileBytes, checkPrintedPart};
  return &tools;
}
