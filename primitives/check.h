// Parameter checks shared by the primitives' constructors: a degenerate or
// non-finite parameter is refused with a message that names it.
#pragma once

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace csgray::detail {

inline void requirePositive(const char* shape, const char* name, double value) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    std::ostringstream msg;
    msg << shape << ": " << name << " must be a positive finite number (got " << value << ")";
    throw std::invalid_argument(msg.str());
  }
}

inline void requireFinite(const char* shape, const char* name, double value) {
  if (!std::isfinite(value)) {
    std::ostringstream msg;
    msg << shape << ": " << name << " must be finite (got " << value << ")";
    throw std::invalid_argument(msg.str());
  }
}

}  // namespace csgray::detail
