#include "cli/script_options.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>

#include "cli/mesh_tools.h"
#include "cli/warning.h"
#include "cli/watchdog.h"
#include "io/image_file.h"

namespace csgray::detail {

namespace {

// 0 (no limit) up to about eleven days; NaN is refused.
const CLI::Validator timeoutRange(
    [](const std::string& text) -> std::string {
      double v = std::strtod(text.c_str(), nullptr);
      return v >= 0.0 && v <= 1e6 ? "" : "must be a number of seconds from 0 to 1e6";
    },
    "SECONDS");

// -D name=value pairs.
std::vector<std::pair<std::string, std::string>> parseDefines(
    const std::vector<std::string>& items) {
  std::vector<std::pair<std::string, std::string>> defines;
  for (const std::string& item : items) {
    size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw CLI::ValidationError("-D", "expected name=value, got '" + item + "'");
    defines.emplace_back(item.substr(0, eq), item.substr(eq + 1));
  }
  return defines;
}

}  // namespace

CLI::App* addScriptCommand(CLI::App& app, const std::string& name, const std::string& description,
                           ScriptArguments& arguments) {
  CLI::App* command = app.add_subcommand(name, description);
  command->add_option("script", arguments.script, "Lua part script")->required();
  return command;
}

void addScriptOptions(CLI::App& command, ScriptArguments& arguments) {
  command.add_option("-D", arguments.defines, "Set a script global before it runs: name=value");
  command
      .add_option("--script-timeout", arguments.timeout, "Seconds the script may run (0: no limit)")
      ->check(timeoutRange)
      ->capture_default_str();
  command
      .add_option("--allow-path", arguments.allowedFolders,
                  "A folder outside the script's that its files (meshes, images) may come from")
      ->check(CLI::ExistingDirectory);
}

PartScript::PartScript(const ScriptArguments& arguments)
    : path_(arguments.script), timeout_(arguments.timeout) {
  options_.defines = parseDefines(arguments.defines);
  options_.loadImage = readTextureImage;
  options_.loadMesh = [](const std::string& path, bool repair, std::string& report) {
    return meshTools().importMesh(path, repair, report);
  };
  options_.checkSolid = [](const Solid& solid, const CheckOptions& options) {
    return meshTools().checkPart(solid, options);
  };
  options_.allowedFolders = arguments.allowedFolders;
  options_.warn = printWarning;
}

Scene PartScript::run() const {
  char limit[32];
  std::snprintf(limit, sizeof limit, "%g", timeout_);
  Watchdog watchdog(
      timeout_, path_ + ": the script did not finish within " + limit + " s (--script-timeout)");
  return runScriptFile(path_, options_);
}

}  // namespace csgray::detail
