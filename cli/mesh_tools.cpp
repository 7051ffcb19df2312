#include "cli/mesh_tools.h"

#include "io/plugin_module.h"

namespace csgray::detail {

const MeshTools& meshTools() {
  return pluginOf<MeshTools>("libcsgray_mesh_tools.so", CSGRAY_MESH_TOOLS_MODULE,
                             "csgray_mesh_tools", "meshes");
}

}  // namespace csgray::detail
