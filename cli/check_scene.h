// The work of csgray check, in the mesh tools module (cli/mesh_tools.h): a
// scene's export held against its exact model (check/part_check.h),
// printed as text or JSON.
#pragma once

#include <functional>
#include <string>

#include "check/check_report.h"
#include "scene/scene.h"

namespace csgray::detail {

struct CheckCommandOptions {
  std::string script;  // for messages
  CheckOptions check;
  bool json = false;  // print JSON instead of text
  // Called when the check is done, before the report is printed: the
  // command's time limit ends there, so that no half report is printed.
  std::function<void()> checked;
};

// Checks the scene's solids (their union, when there are several) and
// prints the report on stdout. Returns the exit status: 0 when the check
// holds, 1 when it does not. Throws std::runtime_error when there is no
// solid to check.
int checkScene(const Scene& scene, const CheckCommandOptions& options);

}  // namespace csgray::detail
