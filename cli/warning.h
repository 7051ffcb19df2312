// Warnings and errors as the terminal shows them: what the user should
// know of a run, as one line on stderr, whether the script, the executable
// or the mesh tools module says it.
#pragma once

#include <string>
#include <string_view>

namespace csgray::detail {

// The text as one line the terminal shows as it is: line breaks become
// spaces, and every other control byte '?', so that a message quoting a
// script's error() or a file's bytes cannot move the cursor, clear the
// screen or end the line early.
std::string terminalLine(std::string_view text);

// Writes "csgray: warning: <message>" on stderr, as terminalLine.
void printWarning(const std::string& message);

}  // namespace csgray::detail
