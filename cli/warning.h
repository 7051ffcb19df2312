// Warnings: what the user should know of a run that still succeeds, as one
// line on stderr, whether the script, the executable or the mesh tools
// module says it.
#pragma once

#include <string>

namespace csgray::detail {

// Writes "csgray: warning: <message>" on stderr.
void printWarning(const std::string& message);

}  // namespace csgray::detail
