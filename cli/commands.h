// The commands of csgray. Each is declared with its options and run in a
// file of its own (cli/<name>_command.cpp); main.cpp puts them together
// and runs the one chosen.
#pragma once

#include <functional>

#include "cli/script_options.h"

namespace csgray::detail {

struct Command {
  CLI::App* app;  // true once parsed when this command was chosen
  // Returns the exit status. Throws std::exception with a one-line message
  // when the command fails: CLI::ValidationError (exit status 2) for a
  // command line that is wrong in a way CLI11 cannot see.
  std::function<int(const PartScript& script)> run;
};

// Each declares its command on app; `script` receives the options all
// commands share (only one command is chosen).

// csgray render: a part script ray traced to an image, and optionally its
// depth and normal images.
Command renderCommand(CLI::App& app, ScriptArguments& script);

// csgray export: a part script's solids as a closed, printable mesh file,
// made in the mesh tools module (cli/export_scene.h).
Command exportCommand(CLI::App& app, ScriptArguments& script);

// csgray check: a part script's export held against its exact model, in
// the mesh tools module (cli/check_scene.h).
Command checkCommand(CLI::App& app, ScriptArguments& script);

// csgray info: the bounds and tree size of a part script.
Command infoCommand(CLI::App& app, ScriptArguments& script);

// csgray view: a web page that shows the part, renders it again as the
// camera moves and reloads it when its files change (view/view_app.h).
Command viewCommand(CLI::App& app, ScriptArguments& script);

}  // namespace csgray::detail
