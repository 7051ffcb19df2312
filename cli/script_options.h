// What every command takes about its part script, declared once for all of
// them: the script, the globals set before it runs (-D), its time limit
// (--script-timeout) and the folders its files may come from (--allow-path).
#pragma once

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
};

// Declares a command of app that runs a part script, with the script as
// its first argument (CLI11 names the first required one missing).
CLI::App* addScriptCommand(CLI::App& app, const std::string& name, const std::string& description,
                           ScriptArguments& arguments);

// Declares -D, --script-timeout and --allow-path on a command; called after
// its own options, which its help lists first.
void addScriptOptions(CLI::App& command, ScriptArguments& arguments);

// The script of a parsed command line, ready to run.
class PartScript {
 public:
  // Throws CLI::ValidationError for a -D that is not name=value.
  explicit PartScript(const ScriptArguments& arguments);

  const std::string& path() const { return path_; }
  // Runs the script under the watchdog (cli/watchdog.h), so nothing may be
  // written meanwhile. Throws std::exception with a one-line message.
  Scene run() const;

 private:
  std::string path_;
  double timeout_;
  ScriptOptions options_;
};

}  // namespace csgray::detail
