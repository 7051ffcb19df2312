// Checks of the numbers that more than one option takes, so that a bad one
// is refused in the same words wherever it is given.
#pragma once

#include <CLI/CLI.hpp>

namespace csgray::detail {

// Digits only, at most 2⁶⁴ − 1: CLI11 would read 0x10 as sixteen and 010
// as eight, and keep the largest value for a larger one.
extern const CLI::Validator decimal;
// An export's tolerance: 1e-6 to 1000 model units.
extern const CLI::Validator toleranceRange;
// A wall or gap: 0 to 10⁶ model units.
extern const CLI::Validator lengthRange;
// A time limit: 0 (no limit) to 10⁶ seconds, about eleven days.
extern const CLI::Validator timeoutRange;
// A count of rays: 0 (no limit) to 10¹⁸.
extern const CLI::Validator rayCountRange;

}  // namespace csgray::detail
