// `csgray view` as a whole: the session, the file watcher that reloads it,
// and the server, until the process is ended (Ctrl-C).
#pragma once

#include <functional>
#include <string>

#include "script/script.h"
#include "view/view_jobs.h"
#include "view/view_service.h"
#include "view/view_session.h"

namespace csgray::detail {

struct ViewOptions {
  std::string script;
  ScriptOptions scriptOptions;  // its -D are the customizer's first values
  std::string address = "127.0.0.1";
  int port = 0;       // 0: a free one
  bool open = false;  // open the page in the browser (xdg-open)
  int threads = 0;    // 0: one per core
  // A first run of the script longer than this says so on standard error
  // before the page is served (with 0, every first run says so).
  double slowRunSeconds = 1.0;
  // Makes the web server (makeViewServer of view_server.h, which the
  // command line loads from a module).
  std::function<std::unique_ptr<HttpServer>(ViewService&, const std::string& address, int port)>
      makeServer;
  // Runs the script each time (the command line's: under --script-timeout,
  // which ends the process); runScriptFile where empty.
  ViewSession::ScriptRunner runScript;
  // The work of the page's export and check buttons (from the mesh tools).
  PartTools tools;
};

// Serves the view; returns only when it cannot start (a port in use: throws
// std::runtime_error; a -D the script refuses: DefineError). Prints the
// page's address, and a warning when it is reachable from other machines.
int serveView(const ViewOptions& options);

}  // namespace csgray::detail
