#include "cli/view_tools.h"

#include "io/plugin_module.h"

namespace csgray::detail {

const ViewTools& viewTools() {
  return pluginOf<ViewTools>("libcsgray_view_server.so", CSGRAY_VIEW_MODULE, "csgray_view_tools",
                             "the view's web server");
}

}  // namespace csgray::detail
