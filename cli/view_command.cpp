#include <CLI/CLI.hpp>
#include <memory>
#include <string>

#include "cli/commands.h"
#include "cli/mesh_tools.h"
#include "cli/number_checks.h"
#include "cli/view_tools.h"
#include "cli/warning.h"
#include "view/view_app.h"

namespace csgray::detail {

namespace {

struct ViewArguments {
  int port = 0;
  std::string address = "127.0.0.1";
  bool open = false;
  int threads = 0;
};

int view(const ViewArguments& arguments, const PartScript& script) {
  if (script.runTimeout() > 0.0)
    throw CLI::ValidationError("--timeout", "is for commands that end; view runs until Ctrl-C");
  ViewOptions options;
  options.script = script.path();
  options.scriptOptions = script.options();
  options.address = arguments.address;
  options.port = arguments.port;
  options.open = arguments.open;
  options.threads = arguments.threads;
  options.makeServer = viewTools().makeViewServer;
  options.runScript = [&script](const std::string&, const ScriptOptions& scriptOptions) {
    return script.runWithin(scriptOptions);
  };
  // The page's buttons; the mesh tools' module is loaded on the first press.
  options.tools.meshFile = [](const Scene& scene, const std::string& script,
                              const std::string& format,
                              const std::function<void(const std::string&)>& stage) {
    return meshTools().partFileBytes(scene, script, format, ExportOptions{}.tolerance, stage,
                                     printWarning);
  };
  options.tools.check = [](const Scene& scene, const std::string& script) {
    return meshTools().checkPrintedPart(scene, script, CheckOptions{}, printWarning);
  };
  return serveView(options);
}

}  // namespace

Command viewCommand(CLI::App& app, ScriptArguments& script) {
  auto arguments = std::make_shared<ViewArguments>();
  CLI::App* command = addScriptCommand(
      app, "view", "Show a part script in the browser, live: orbit, reload on save, customizer",
      script);
  command->add_option("--port", arguments->port, "Port to serve the page on (0: a free one)")
      ->check(decimal)
      ->check(CLI::Range(0, 65535))
      ->capture_default_str();
  command
      ->add_option("--address", arguments->address,
                   "Address to listen on; other than 127.0.0.1 lets other machines see the part")
      ->capture_default_str();
  command->add_flag("--open", arguments->open, "Open the page in the browser (xdg-open)");
  command->add_option("--threads", arguments->threads, "Threads to render on (0: one per core)")
      ->check(decimal)
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
  addScriptOptions(*command, script);
  // Taken only to be refused with a reason (view), so not in the help.
  command->get_option("--timeout")->group("");
  return {command, [arguments](const PartScript& part) { return view(*arguments, part); }};
}

}  // namespace csgray::detail
