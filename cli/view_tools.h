// The server of `csgray view` (view/view_app.h), in a module loaded when
// that command runs: cpp-httplib and the OpenSSL, zlib and Brotli it is
// linked with would cost every other run of csgray their loading.
#pragma once

#include <memory>
#include <string>

#include "view/view_service.h"

namespace csgray::detail {

struct ViewTools {
  // As declared in view/view_server.h.
  std::unique_ptr<HttpServer> (*makeViewServer)(ViewService& service, const std::string& address,
                                                int port);
};

// The module's table, loaded on the first call. Throws std::runtime_error
// if it cannot be loaded.
const ViewTools& viewTools();

}  // namespace csgray::detail

extern "C" const csgray::detail::ViewTools* csgray_view_tools();
