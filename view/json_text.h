// The pieces of the JSON (RFC 8259) that the view's server sends.
#pragma once

#include <string>
#include <string_view>

#include "engine/ray.h"

namespace csgray::detail {

// A string in quotes, with quotes, backslashes and control characters
// escaped.
std::string jsonString(std::string_view text);
// A number as few digits as read back the same; null if not finite (JSON
// has no infinities).
std::string jsonNumber(double value);
// [x, y, z].
std::string jsonVector(const dvec3& v);

}  // namespace csgray::detail
