#include "cli/number_checks.h"

#include <charconv>
#include <cstdint>
#include <cstdlib>

namespace csgray::detail {

namespace {

// A number from lo to hi; NaN and words are refused (CLI::Range lets NaN
// by). range is how the message writes lo and hi, unit what they count.
CLI::Validator numberRange(double lo, double hi, const std::string& range, const std::string& unit,
                           const std::string& name) {
  return CLI::Validator(
      [=](const std::string& text) -> std::string {
        char* end = nullptr;
        double v = std::strtod(text.c_str(), &end);
        return end != text.c_str() && *end == '\0' && v >= lo && v <= hi
                   ? ""
                   : "must be a number from " + range + " (" + unit + ")";
      },
      name);
}

}  // namespace

const CLI::Validator decimal(
    [](const std::string& text) -> std::string {
      bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
      // Past 64 bits CLI11 would keep the largest value or wrap around.
      std::uint64_t value = 0;
      bool fits = std::from_chars(text.data(), text.data() + text.size(), value).ec == std::errc();
      if (!digits || (text.size() > 1 && text[0] == '0'))
        return "must be a whole number (decimal digits)";
      return fits ? "" : "must be a whole number below 2^64 (18446744073709551616)";
    },
    "N");

const CLI::Validator toleranceRange =
    numberRange(1e-6, 1e3, "1e-6 to 1000", "model units", "TOLERANCE");

const CLI::Validator lengthRange = numberRange(0.0, 1e6, "0 to 1e6", "model units", "LENGTH");

const CLI::Validator timeoutRange =
    numberRange(0.0, 1e6, "0 to 1e6", "seconds; 0: no limit", "SECONDS");

const CLI::Validator rayCountRange =
    numberRange(0.0, 1e18, "0 to 1e18", "rays; 0: no limit", "RAYS");

}  // namespace csgray::detail
