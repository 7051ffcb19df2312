#include "cli/mesh_plugin.h"

#include "io/plugin_module.h"

namespace csgray::detail {

const MeshPlugin& meshPlugin() {
  return pluginOf<MeshPlugin>("libcsgray_meshes.so", CSGRAY_MESH_PLUGIN, "csgray_mesh_plugin",
                              "meshes");
}

}  // namespace csgray::detail
