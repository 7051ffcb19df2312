// The web server of `csgray view` (cpp-httplib): the page, and the
// requests it passes to a ViewService. It answers only requests whose Host
// is its own address (and whose Origin, when a browser sends one, is its
// own page), so that another web site open in the same browser cannot
// read it or set values (DNS rebinding, cross-site POSTs).
//
//   GET  /, /view.js, /view.css   the page (view/page/)
//   GET  /scene                   the state as JSON (view_state_json.h)
//   GET  /wait?version=N          the same, once the version is not N (or
//                                 after 20 s): the page's long poll
//   GET  /frame?...               a PNG (view_frame.h); 409 if a newer
//                                 frame superseded it
//   GET  /pick?...&x=X&y=Y        what is under pixel (X, Y), as JSON
//   POST /define?name=N&value=V   a customizer value (without value: the
//                                 script's default); 400 with the reason
//                                 when the annotation refuses it
//   POST /reload                  runs the script again
//   POST /export?format=stl|3mf   starts an export, POST /check a check
//                                 (view_jobs.h); 202, or 409 while one runs
//   GET  /job                     the job's stage, error, file or report
//   GET  /job/file?id=N           the exported file, as a download
#pragma once

#include <memory>
#include <string>

#include "view/view_service.h"

namespace csgray::detail {

// Binds to address and port (0: a free one). Throws std::runtime_error
// when it cannot.
std::unique_ptr<HttpServer> makeViewServer(ViewService& service, const std::string& address,
                                           int port);

}  // namespace csgray::detail
