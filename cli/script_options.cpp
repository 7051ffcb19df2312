#include "cli/script_options.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "cli/mesh_tools.h"
#include "cli/number_checks.h"
#include "cli/warning.h"
#include "cli/watchdog.h"
#include "io/image_file.h"

namespace csgray::detail {

namespace {

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

std::string seconds(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

}  // namespace

CLI::App* addScriptCommand(CLI::App& app, const std::string& name, const std::string& description,
                           ScriptArguments& arguments) {
  CLI::App* command = app.add_subcommand(name, description);
  command->add_option("script", arguments.script, "Lua part script, or an OpenSCAD .csg file")
      ->required();
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
  command
      .add_option("--facets", arguments.facets,
                  "An OpenSCAD .csg file's circles, spheres, cylinders and letters: exact, or "
                  "the polygons OpenSCAD makes from $fn, $fa, $fs (openscad)")
      ->check(CLI::IsMember({"exact", "openscad"}))
      ->capture_default_str();
  command
      .add_option("--timeout", arguments.runTimeout,
                  "Seconds the whole command may run, script included (0: no limit)")
      ->check(timeoutRange)
      ->capture_default_str();
}

PartScript::PartScript(const ScriptArguments& arguments, std::string command)
    : path_(arguments.script),
      command_(std::move(command)),
      timeout_(arguments.timeout),
      runTimeout_(arguments.runTimeout),
      start_(std::chrono::steady_clock::now()) {
  options_.defines = parseDefines(arguments.defines);
  options_.loadImage = readTextureImage;
  options_.loadMesh = [](const std::string& path, bool repair, std::string& report) {
    return meshTools().importMesh(path, repair, report);
  };
  options_.checkSolid = [](const Solid& solid, const CheckOptions& options) {
    return meshTools().checkPart(solid, options);
  };
  options_.projectSolid = [](const SolidPtr& solid, bool cut) {
    return meshTools().solidProjection(solid, cut);
  };
  options_.allowedFolders = arguments.allowedFolders;
  options_.openscadFacets = arguments.facets == "openscad";
  options_.warn = printWarning;
}

Scene PartScript::run() const {
  // One timer for both limits (one watchdog at a time): the script's own,
  // or what is left of the whole run's when that ends first.
  const double left = timeLeft();
  const bool whole = left > 0.0 && !(timeout_ > 0.0 && timeout_ < left);
  const Watchdog watchdog(whole ? left : timeout_,
                          whole ? timedOut()
                                : path_ + ": the script did not finish within " +
                                      seconds(timeout_) + " s (--script-timeout)");
  return runScriptFile(path_, options_);
}

Scene PartScript::runWithin(const ScriptOptions& options) const {
  const Watchdog watchdog(timeout_, path_ + ": the script did not finish within " +
                                        seconds(timeout_) +
                                        " s (--script-timeout); csgray view ends here");
  return runScriptFile(path_, options);
}

double PartScript::timeLeft() const {
  if (!(runTimeout_ > 0.0)) return 0.0;
  const std::chrono::duration<double> spent = std::chrono::steady_clock::now() - start_;
  return std::max(runTimeout_ - spent.count(), 1e-6);
}

std::string PartScript::timedOut() const {
  // "the render", "the export", "the check"; info is not a noun.
  const std::string run = command_ == "info" ? "the info command" : "the " + command_;
  return path_ + ": " + run + " took longer than --timeout " + seconds(runTimeout_) + " s";
}

}  // namespace csgray::detail
