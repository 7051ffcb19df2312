#include <CLI/CLI.hpp>
#include <chrono>
#include <memory>
#include <optional>

#include "cli/commands.h"
#include "cli/mesh_tools.h"
#include "cli/number_checks.h"
#include "cli/watchdog.h"

namespace csgray::detail {

Command exportCommand(CLI::App& app, ScriptArguments& script) {
  auto arguments = std::make_shared<ExportOptions>();
  CLI::App* exporter = addScriptCommand(
      app, "export",
      "Write a part script's solids as a closed, printable mesh, or its 2D regions' outline",
      script);
  exporter
      ->add_option("-o,--output", arguments->output,
                   "Mesh file; its extension picks the format (.stl, .obj, .off, .ply, .3mf), "
                   "or .svg or .dxf for the outline of the 2D regions")
      ->required();
  exporter
      ->add_option("--tolerance", arguments->tolerance,
                   "Largest distance of the mesh from the exact surface, in model units")
      ->check(toleranceRange)
      ->capture_default_str();
  exporter->add_flag("--ascii", arguments->ascii, "Write STL and PLY as text");
  exporter->add_flag("--stats", arguments->stats,
                     "Print the time of each stage and the booleans done to stderr");
  addScriptOptions(*exporter, script);
  return {exporter, [arguments](const PartScript& part) {
            ExportOptions options = *arguments;
            options.script = part.path();
            meshTools().checkExportOutput(options);
            auto start = std::chrono::steady_clock::now();
            Scene scene = part.run();
            // The booleans cannot be stopped half way: the watchdog ends the
            // process, before the file is opened (ExportOptions::meshed).
            std::optional<Watchdog> limit(std::in_place, part.timeLeft(), part.timedOut());
            options.meshed = [&limit] { limit.reset(); };
            meshTools().exportScene(
                scene, options,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
            return 0;
          }};
}

}  // namespace csgray::detail
