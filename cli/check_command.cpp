#include <CLI/CLI.hpp>
#include <memory>
#include <optional>

#include "cli/commands.h"
#include "cli/mesh_tools.h"
#include "cli/number_checks.h"
#include "cli/watchdog.h"

namespace csgray::detail {

Command checkCommand(CLI::App& app, ScriptArguments& script) {
  auto arguments = std::make_shared<CheckCommandOptions>();
  CheckOptions& check = arguments->check;
  CLI::App* checker = addScriptCommand(
      app, "check",
      "Hold a part's exported mesh against its exact model, and report on its booleans", script);
  checker
      ->add_option("--samples", check.samples,
                   "Random points classified by both the exact model and the mesh")
      ->check(decimal)
      ->check(CLI::Range(std::size_t(0), CheckOptions::kMaxSamples))
      ->capture_default_str();
  checker->add_option("--tolerance", check.tolerance, "Tolerance of the export, in model units")
      ->check(toleranceRange)
      ->capture_default_str();
  checker
      ->add_option("--min-wall", check.minWall,
                   "Warn of solid walls thinner than this (model units)")
      ->check(lengthRange)
      ->capture_default_str();
  checker
      ->add_option("--min-gap", check.minGap, "Warn of empty gaps narrower than this (model units)")
      ->check(lengthRange)
      ->capture_default_str();
  checker
      ->add_option("--grid", check.grid,
                   "Rays per side of each of the three ray grids along x, y and z")
      ->check(decimal)
      ->check(CLI::Range(2, CheckOptions::kMaxGrid))
      ->capture_default_str();
  checker->add_option("--seed", check.seed, "Seed of the random points and rays")
      ->check(decimal)
      ->capture_default_str();
  checker->add_flag("--strict", check.strict, "Fail on warnings too");
  checker->add_flag("--json", arguments->json, "Print the report as JSON");
  addScriptOptions(*checker, script);
  return {checker, [arguments](const PartScript& part) {
            CheckCommandOptions options = *arguments;
            options.script = part.path();
            Scene scene = part.run();
            // As for export: the process ends at the limit, before the
            // report is printed (CheckCommandOptions::checked).
            std::optional<Watchdog> limit(std::in_place, part.timeLeft(), part.timedOut());
            options.checked = [&limit] { limit.reset(); };
            return meshTools().checkScene(scene, options);
          }};
}

}  // namespace csgray::detail
