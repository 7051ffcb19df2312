// What every command takes about its part script, declared once for all of
// them: the script, the globals set before it runs (-D), its time limit
// (--script-timeout), the folders its files may come from (--allow-path)
// and the time limit of the whole run (--timeout).
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "script/script.h"

namespace CLI {
class App;
}

namespace csgray::detail {

struct ScriptArguments {
  std::string script;
  std::vector<std::string> defines;  // name=value
  double timeout = 60.0;             // seconds; 0: no limit
  std::vector<std::string> allowedFolders;
  double runTimeout = 0.0;       // --timeout: seconds for the whole command; 0: no limit
  std::string facets = "exact";  // --facets: a .csg file's curves, exact or OpenSCAD's polygons
};

// Declares a command of app that runs a part script, with the script as
// its first argument (CLI11 names the first required one missing).
CLI::App* addScriptCommand(CLI::App& app, const std::string& name, const std::string& description,
                           ScriptArguments& arguments);

// Declares -D, --script-timeout, --allow-path and --timeout on a command;
// called after its own options, which its help lists first.
void addScriptOptions(CLI::App& command, ScriptArguments& arguments);

// The script of a parsed command line, ready to run; the clock of
// --timeout starts when it is made.
class PartScript {
 public:
  // command: the command's name, for messages ("render"). Throws
  // CLI::ValidationError for a -D that is not name=value.
  PartScript(const ScriptArguments& arguments, std::string command);

  const std::string& path() const { return path_; }
  // What the script runs with: its -D, the loaders of meshes and images,
  // the folders it may read (csgray view and render --watch run it
  // themselves, again and again).
  const ScriptOptions& options() const { return options_; }
  ScriptOptions& options() { return options_; }
  double runTimeout() const { return runTimeout_; }
  // Runs the script under the watchdog (cli/watchdog.h), so nothing may be
  // written meanwhile; it ends the process at --script-timeout or at the
  // end of --timeout, whichever comes first. Throws std::exception with a
  // one-line message.
  Scene run() const;
  // Runs the script with `options` (its own, as csgray view changes them
  // for the customizer) under --script-timeout's watchdog alone, which
  // ends the process: a string pattern that backtracks for hours would
  // otherwise hold the view's script thread, and every reload after it.
  Scene runWithin(const ScriptOptions& options) const;

  // The seconds left of --timeout: 0 when there is no limit, and a
  // microsecond when it has run out (a watchdog given it fires at once).
  double timeLeft() const;
  // "<script>: the render took longer than --timeout 5 s".
  std::string timedOut() const;

 private:
  std::string path_;
  std::string command_;
  double timeout_;
  double runTimeout_;
  std::chrono::steady_clock::time_point start_;
  ScriptOptions options_;
};

}  // namespace csgray::detail
