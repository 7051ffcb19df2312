// Part scripts: sandboxed Lua 5.4 that returns a solid or a scene
// (docs/script.md), run as the csgray command runs them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "csgray/scene.h"

namespace csgray {

struct ScriptOptions {
  // Globals set before the script runs, as -D name=value: numbers,
  // true/false, or strings (quotes optional).
  std::vector<std::pair<std::string, std::string>> defines;
  // Folders outside the script's that its files (meshes, images) may come
  // from, as --allow-path.
  std::vector<std::string> allowedFolders;
  std::size_t memoryBytes = std::size_t{1} << 30;  // Lua heap plus solids built
  std::uint64_t instructions = 1'000'000'000;      // Lua VM instructions
  // Receives what the script should be told without stopping it (what
  // mesh{repair=true} repaired); none: dropped.
  std::function<void(const std::string& message)> onWarning;
  // Receives each line the script's print() writes (its values joined by
  // tabs, without the newline); none: they go to standard error, as the
  // command's do.
  std::function<void(const std::string& line)> onPrint;
};

// Runs the script file; error ScriptError with the message naming its file
// and line.
CSGRAY_API Scene runScript(const std::string& path, const ScriptOptions& options = {});
// Runs script text; chunkName stands for the file name in messages, and
// files it names are relative to the current folder.
CSGRAY_API Scene runScriptText(const std::string& source, const std::string& chunkName,
                               const ScriptOptions& options = {});

}  // namespace csgray
