// The entry of the view's module (cli/view_tools.h).
#include "cli/view_tools.h"
#include "view/view_server.h"

extern "C" __attribute__((visibility("default"))) const csgray::detail::ViewTools*
csgray_view_tools() {
  using namespace csgray::detail;
  static const ViewTools tools{makeViewServer};
  return &tools;
}
